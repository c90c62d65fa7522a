// A function of expressions applied to many, the work shared among this process and copies of it
// made by fork(2), one per further core.
//
// GiNaC is not thread-safe (reference counts and shared constants are updated without locks), so
// the cores are used by processes. Each copy takes the next expression from a common queue (a
// pipe of their numbers, the largest expressions first), keeps what it computes, and writes it
// back at the end (symbolic/expression_transport.hpp); the results are the function's own, the
// same whichever process computed them. What a copy could not compute or send (an exception, an
// expression that does not travel, a copy that died) is computed here afterwards, in order, so
// errors are raised as without the copies.
#pragma once

#include <cstddef>
#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// How many processes map_in_processes uses: the environment's UNIDYN_PROCESSES when set (a
// positive integer; anything else is refused with std::invalid_argument), else the cores this
// process may run on.
std::size_t worker_processes();

// f(e) for each e of `inputs`, in their order.
std::vector<Expr> map_in_processes(const std::vector<Expr>& inputs, Expr (*f)(const Expr&));

}  // namespace unidyn
