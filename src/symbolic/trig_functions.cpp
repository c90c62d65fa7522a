// sin x and cos x made once for each argument.
#include "unidyn/symbolic/trig_functions.hpp"

#include <unordered_map>

namespace unidyn {
namespace {

using Made = std::unordered_map<Expr, Expr, ExprHash, GiNaC::ex_is_equal>;

// f(x) from `made`, or made now and kept.
Expr made_once(Made& made, const Expr& x, Expr (*f)(const Expr&)) {
  constexpr std::size_t kKept = 100000;
  if (const auto found = made.find(x); found != made.end()) return found->second;
  if (made.size() >= kKept) made.clear();
  return made.emplace(x, f(x)).first->second;
}

Expr make_sine(const Expr& x) {
  return GiNaC::sin(x);
}
Expr make_cosine(const Expr& x) {
  return GiNaC::cos(x);
}

}  // namespace

Expr sine_of(const Expr& x) {
  thread_local Made made;
  return made_once(made, x, make_sine);
}

Expr cosine_of(const Expr& x) {
  thread_local Made made;
  return made_once(made, x, make_cosine);
}

}  // namespace unidyn
