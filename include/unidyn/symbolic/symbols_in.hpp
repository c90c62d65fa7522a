// The symbols expressions hold, found in one walk.
//
// GiNaC's has() makes each term of a sum and each factor of a product anew as it descends (op()),
// so asking it for each coordinate of a deep tree's frames takes seconds. This walk reads the
// pairs GiNaC keeps (expairs.hpp) and each shared node once; asking for a symbol is then a lookup.
#pragma once

#include <unordered_set>
#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

class SymbolsIn {
 public:
  SymbolsIn() = default;
  explicit SymbolsIn(const Expr& e) { add(e); }

  // Takes in the symbols of e.
  void add(const Expr& e) { walk(e); }
  void add(const VectorExpr& v) {
    for (int i = 0; i < 3; ++i) add(v[i]);
  }
  // Whether any expression taken in holds x (as e.has(x) for a symbol x).
  bool has(const GiNaC::symbol& x) const { return symbols_.count(x) != 0; }

 private:
  void walk(const Expr& e);

  std::vector<Expr> held_;  // every node seen, held: its address stays its own
  std::unordered_set<const GiNaC::basic*> seen_;
  std::unordered_set<Expr, ExprHash, GiNaC::ex_is_equal> symbols_;
};

}  // namespace unidyn
