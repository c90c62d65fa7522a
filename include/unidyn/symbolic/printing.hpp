// Readable equations: simplification for display, and text / LaTeX printing.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// The number of nodes of an expression tree, a product's sign (a factor ±1) not counted: the
// measure "simpler" means here, the same for −x and x and for either sign GiNaC gives a sum.
std::size_t expression_size(const Expr& e);

// Expanded, with sin²x + cos²x = 1 applied wherever it makes the expression smaller (each
// argument x tried both ways, sin² → 1 − cos² and cos² → 1 − sin²), rational functions normalised.
// Every choice (the order of the arguments, ties in size, the sign of a fraction) follows the
// canonical order, so the result is the same expression in every run.
Expr simplify(const Expr& e);
// simplify of each, the work shared among processes (symbolic/process_map.hpp), every result
// remembered for later calls.
std::vector<Expr> simplify_all(const std::vector<Expr>& es);

// f(e), computed once for equal expressions (in this thread; up to a bound of kept results): for
// the simplifications, which meet the same coefficient again and again.
Expr remembered(const Expr& e, Expr (*f)(const Expr&));
// f(e) as remembered, if it is; and `result` remembered as f(e) (computed elsewhere: in another
// process, symbolic/process_map.hpp).
std::optional<Expr> recalled(const Expr& e, Expr (*f)(const Expr&));
void remember(const Expr& e, Expr (*f)(const Expr&), const Expr& result);
// f of each of `es`: those not remembered computed at once by map_in_processes
// (symbolic/process_map.hpp), each once, then remembered.
std::vector<Expr> remembered_all(const std::vector<Expr>& es, Expr (*f)(const Expr&));

// Collects an expression in the given symbols (e.g. the accelerations) after simplifying.
Expr collect_in(const Expr& e, const std::vector<Expr>& symbols);

// Text and LaTeX in the canonical order (symbolic/canonical_text.hpp): the same in every run.
std::string to_text(const Expr& e);
std::string to_latex(const Expr& e);

}  // namespace unidyn
