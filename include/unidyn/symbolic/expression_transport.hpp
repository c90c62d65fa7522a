// Expressions written to bytes and read back in another process made by fork(2) from this one.
//
// A forked copy shares every object that existed when it was made, so a symbol travels as its
// place in a table of symbols both sides hold (`SymbolTable`), a function as GiNaC's serial of it
// (the same binary registers the same functions in the same order), a number as its exact text.
// The expression goes as its nodes in post-order, each shared node once, each node naming its
// children by their place in that order; the reader rebuilds it through GiNaC's constructors,
// which evaluate, as the writer's did. Sums, products, powers, functions, symbols of the table and
// rational numbers travel; anything else is refused (`Untransportable`), and the caller computes
// that expression itself.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// What cannot travel: a symbol outside the table, a floating-point or complex number, a class of
// expression other than those above; or bytes that are not a written expression.
struct Untransportable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The symbols of some expressions, each with its place in the order they were met.
class SymbolTable {
 public:
  // The symbols of `expressions`, in the order a walk through them meets them.
  explicit SymbolTable(const std::vector<Expr>& expressions);
  // The place of the symbol equal to `s` (a copy of a symbol is equal to it), or −1.
  std::int64_t place(const Expr& s) const;
  const Expr& symbol(std::size_t place) const { return symbols_.at(place); }
  std::size_t size() const { return symbols_.size(); }

 private:
  std::vector<Expr> symbols_;
  std::unordered_map<Expr, std::size_t, ExprHash, GiNaC::ex_is_equal> places_;
};

// `e` appended to `bytes`. Throws Untransportable (and appends nothing).
void write_expression(const Expr& e, const SymbolTable& symbols, std::string& bytes);

// The expression written at the front of `bytes`, which is advanced past it. Throws
// Untransportable when the bytes are not one.
Expr read_expression(std::string_view& bytes, const SymbolTable& symbols);

}  // namespace unidyn
