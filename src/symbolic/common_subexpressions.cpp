// Naming the subexpressions that occur more than once.
#include "unidyn/symbolic/common_subexpressions.hpp"

#include <algorithm>
#include <map>
#include <string>

#include "unidyn/symbolic/canonical_text.hpp"
#include "unidyn/symbolic/coordinates.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

// An expression and its negative are one subexpression (GiNaC writes a sum with either sign, by
// its own order of terms, which moves with the memory layout, and a product's sign follows its
// sums'): the one whose canonical text does not start with a minus, its text, and the sign taken
// out.
struct SignedText {
  Expr positive;
  std::string text;
  int sign = 1;
};
SignedText with_sign_out(const Expr& e) {
  std::string text = canonical_text(e);
  if (!text.starts_with("-")) return {e, std::move(text), 1};
  const Expr negated = -e;
  return {negated, canonical_text(negated), -1};
}

// How often each subexpression occurs, by canonical text, with one instance and its size.
struct Occurrence {
  Expr instance;
  std::size_t size = 0, count = 0;
};
void count(const Expr& e, std::size_t min_size, std::map<std::string, Occurrence>& found) {
  const std::size_t size = expression_size(e);
  if (size < min_size) return;
  const auto [x, text, sign] = with_sign_out(e);
  Occurrence& o = found[text];
  if (o.count++ == 0) {
    o.instance = x;
    o.size = size;
  }
  // the parts of an expression met again are counted with it, not again
  if (o.count > 1) return;
  for (std::size_t i = 0; i < x.nops(); ++i) count(x.op(i), min_size, found);
}

// Bottom up: each subexpression with a name replaced by it (± it, for a sum). The parts looked
// into are e's own, not those of −e: GiNaC may write −e with e inside it (a power of a sum with the
// sign taken out by its own order of terms), and that descent need not end.
struct Replace : GiNaC::map_function {
  const std::map<std::string, Expr>& named;
  explicit Replace(const std::map<std::string, Expr>& n) : named(n) {}
  Expr operator()(const Expr& e) override {
    const auto [x, text, sign] = with_sign_out(e);
    if (const auto found = named.find(text); found != named.end()) return sign * found->second;
    return e.map(*this);
  }
};

}  // namespace

Intermediates common_subexpressions(const std::vector<Expr>& expressions, std::size_t min_size) {
  std::map<std::string, Occurrence> found;
  for (const Expr& e : expressions) count(e, min_size, found);
  // the repeated ones, smaller first (their parts are named before them), then by text
  std::vector<std::pair<std::string, Occurrence>> repeated;
  for (const auto& [text, o] : found) {
    if (o.count >= 2) repeated.emplace_back(text, o);
  }
  std::stable_sort(repeated.begin(), repeated.end(),
                   [](const auto& a, const auto& b) { return a.second.size < b.second.size; });
  Intermediates result;
  std::map<std::string, Expr> named;
  for (const auto& [text, o] : repeated) {
    // its value in terms of the names before it
    Replace replace(named);
    Expr value = o.instance.map(replace);
    const std::string name = "z" + std::to_string(result.names.size() + 1);
    result.names.emplace_back(name, latex_name(name));
    result.values.push_back(value);
    named.emplace(text, result.names.back());
  }
  Replace replace(named);
  for (const Expr& e : expressions) result.expressions.push_back(replace(e));
  return result;
}

}  // namespace unidyn
