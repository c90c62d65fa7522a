// The symbols expressions hold (symbolic/symbols_in.hpp), against GiNaC's has() on the same
// expressions: inside sums, products, powers, functions and matrices, and shared nodes.
#include "unidyn/symbolic/symbols_in.hpp"

#include <gtest/gtest.h>

namespace unidyn {
namespace {

TEST(SymbolsIn, AsGiNaCsHasFindsThem) {
  const GiNaC::realsymbol x("x"), y("y"), z("z"), u("u"), v("v"), w("w");
  const Expr shared = GiNaC::sin(x + 2 * y);
  const Expr e = 3 * shared * shared.op(0) + GiNaC::pow(GiNaC::cos(z), 2) - 1;
  const Expr m = GiNaC::matrix{{u, 0}, {0, shared}};
  SymbolsIn symbols(e);
  symbols.add(m);
  for (const GiNaC::realsymbol& s : {x, y, z, u, v, w}) {
    EXPECT_EQ(symbols.has(s), e.has(s) || m.has(s)) << s;
  }
  EXPECT_TRUE(symbols.has(u));
  EXPECT_FALSE(symbols.has(v));
  EXPECT_FALSE(SymbolsIn(Expr(7)).has(x));
  EXPECT_TRUE(SymbolsIn(Expr(w)).has(w));
}

// Expressions taken in one after another, each a temporary: none is missed (a node's address is
// not reused while the walk remembers it).
TEST(SymbolsIn, TemporariesOneAfterAnother) {
  std::vector<GiNaC::realsymbol> q;
  for (int i = 0; i < 50; ++i) q.emplace_back("q" + std::to_string(i));
  SymbolsIn symbols;
  for (int i = 0; i < 50; ++i) symbols.add(GiNaC::cos(q[static_cast<std::size_t>(i)] + 1) * 2);
  for (const auto& s : q) EXPECT_TRUE(symbols.has(s)) << s;
}

}  // namespace
}  // namespace unidyn
