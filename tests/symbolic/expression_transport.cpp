// Expressions to bytes and back (symbolic/expression_transport.hpp): the same expression, node
// for node, for the book's kinds; what cannot travel is refused, never read wrong.
#include <gtest/gtest.h>

#include "support/random_expressions.hpp"
#include "unidyn/symbolic/expression_transport.hpp"

namespace unidyn {
namespace {

using test::m;
using test::q1;
using test::q2;
using test::random_expression;

Expr round_trip(const Expr& e, const SymbolTable& symbols) {
  std::string bytes;
  write_expression(e, symbols, bytes);
  std::string_view rest(bytes);
  const Expr back = read_expression(rest, symbols);
  EXPECT_TRUE(rest.empty());
  return back;
}

TEST(ExpressionTransport, RandomExpressionsComeBackNodeForNode) {
  std::mt19937 rng(20261127);
  const SymbolTable symbols({test::q1, test::q2, test::u, test::m, test::L});
  int travelled = 0;
  for (int k = 0; k < 400; ++k) {
    const Expr e = random_expression(rng, 4);
    try {
      const Expr back = round_trip(e, symbols);
      EXPECT_TRUE(back.is_equal(e)) << e << "\n  " << back;
      EXPECT_EQ(back.gethash(), e.gethash()) << e;
      ++travelled;
    } catch (const Untransportable&) {
      // only GiNaC's constants (atan2 of numbers gives π) stay behind
      EXPECT_TRUE(e.has(GiNaC::Pi)) << e;
    }
  }
  EXPECT_GE(travelled, 380);
}

TEST(ExpressionTransport, NumbersExactly) {
  const SymbolTable symbols({q1});
  const GiNaC::numeric big("-123456789012345678901234567890/7");
  for (const Expr& e : {Expr(big) * q1, Expr(GiNaC::numeric(-1, 3)), GiNaC::pow(q1, -3) / 2}) {
    EXPECT_TRUE(round_trip(e, symbols).is_equal(e)) << e;
  }
}

TEST(ExpressionTransport, SeveralInARowAndSharedParts) {
  const Expr shared = GiNaC::sin(q1 - q2) * m;
  const SymbolTable symbols({q1, q2, m});
  std::string bytes;
  write_expression(shared + GiNaC::pow(shared, 2), symbols, bytes);
  write_expression(q2, symbols, bytes);
  std::string_view rest(bytes);
  EXPECT_TRUE(read_expression(rest, symbols).is_equal(shared + GiNaC::pow(shared, 2)));
  EXPECT_TRUE(read_expression(rest, symbols).is_equal(q2));
  EXPECT_TRUE(rest.empty());
}

TEST(ExpressionTransport, RefusesWhatDoesNotTravel) {
  const SymbolTable symbols({q1});
  std::string bytes;
  // a symbol outside the table, a floating-point number, a constant: refused, nothing written
  for (const Expr& e : {q1 + q2, q1 * 0.5, q1 * GiNaC::Pi}) {
    EXPECT_THROW(write_expression(e, symbols, bytes), Untransportable) << e;
    EXPECT_TRUE(bytes.empty()) << e;
  }
  // bytes cut short or not an expression: refused on reading
  write_expression(GiNaC::cos(q1) * 3, symbols, bytes);
  for (std::size_t cut = 0; cut < bytes.size(); ++cut) {
    std::string_view rest(bytes.data(), cut);
    EXPECT_THROW(read_expression(rest, symbols), Untransportable) << cut;
  }
  std::string_view nonsense("not an expression at all");
  EXPECT_THROW(read_expression(nonsense, symbols), Untransportable);
}

}  // namespace
}  // namespace unidyn
