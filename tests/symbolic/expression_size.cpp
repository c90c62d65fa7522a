// The size "simpler" means (symbolic/printing.hpp expression_size): the nodes of a tree, a
// product's sign not counted, so that the two signs GiNaC may give one sum inside a product (by
// its own order of terms, which moves with the memory layout) measure the same.
#include <gtest/gtest.h>

#include "support/random_expressions.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

TEST(ExpressionSize, CountsTheNodes) {
  const GiNaC::realsymbol a("a"), b("b"), c("c");
  EXPECT_EQ(expression_size(a), 1u);
  EXPECT_EQ(expression_size(a * b), 3u);          // the product and its two factors
  EXPECT_EQ(expression_size(a + b * c), 5u);      // the sum, a, the product, b, c
  EXPECT_EQ(expression_size(GiNaC::sin(a)), 2u);  // the function and its argument
  EXPECT_EQ(expression_size(2 * a * b), 4u);      // a number other than ±1 counts
  EXPECT_GT(expression_size(2 * a), expression_size(a));
}

TEST(ExpressionSize, ASignIsNotANode) {
  const GiNaC::realsymbol a("a"), b("b"), c("c");
  EXPECT_EQ(expression_size(-a), expression_size(a));
  EXPECT_EQ(expression_size(-a * b), expression_size(a * b));
  // −(a − b) c kept as a product with the number −1, and (b − a) c: one product
  const Expr negated = GiNaC::mul(GiNaC::exvector{a - b, c, Expr(-1)});
  const Expr turned = (b - a) * c;
  ASSERT_TRUE((negated - turned).expand().is_zero());
  EXPECT_EQ(expression_size(negated), expression_size(turned));
  EXPECT_EQ(expression_size(negated + a), expression_size(turned + a));
}

// The definition through GiNaC's op(), which makes each term and factor as an expression of its
// own: the oracle for the size read from GiNaC's pairs.
std::size_t size_by_op(const Expr& e) {
  if (GiNaC::is_exactly_a<GiNaC::mul>(e)) {
    std::size_t size = 1, factors = 0;
    bool unit = true;
    Expr only;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const Expr factor = e.op(i);
      if (GiNaC::is_exactly_a<GiNaC::numeric>(factor)) {
        unit = unit && GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(factor)).is_equal(1);
        if (!unit) ++size;
        continue;
      }
      ++factors;
      only = factor;
      size += size_by_op(factor);
    }
    return factors == 1 && unit ? size_by_op(only) : size;
  }
  std::size_t size = 1;
  for (std::size_t i = 0; i < e.nops(); ++i) size += size_by_op(e.op(i));
  return size;
}

TEST(ExpressionSize, TheSameAsByGiNaCsOperands) {
  std::mt19937 rng(20261129);
  for (int k = 0; k < 500; ++k) {
    const Expr e = test::random_expression(rng, 4);
    for (const Expr& x : {e, -3 * e, e.expand(), (2 * e - test::m).expand()}) {
      EXPECT_EQ(expression_size(x), size_by_op(x)) << x;
    }
  }
}

}  // namespace
}  // namespace unidyn
