// The size "simpler" means (symbolic/printing.hpp expression_size): the nodes of a tree, a
// product's sign not counted, so that the two signs GiNaC may give one sum inside a product (by
// its own order of terms, which moves with the memory layout) measure the same.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace unidyn
