// The canonical printers: the same text whatever order GiNaC keeps terms and factors in. GiNaC
// orders them by hash values that follow each symbol's serial number, so symbols made in the
// opposite order (here: a, b and then b, a of the same names) give it another order, and another
// sign for a sum inside a product; the text must not change.
#include "unidyn/symbolic/canonical_text.hpp"

#include <gtest/gtest.h>

namespace unidyn {
namespace {

// Two sets of symbols with the same names, made in opposite orders.
struct Symbols {
  GiNaC::realsymbol a, b, c;
};
Symbols forward() {
  GiNaC::realsymbol a("a"), b("b"), c("c");
  return {a, b, c};
}
Symbols backward() {
  GiNaC::realsymbol c("c"), b("b"), a("a");
  return {a, b, c};
}

// The text of f built from each set of symbols: one text.
template <typename F>
std::string both(F f, std::string (*print)(const Expr&) = canonical_text) {
  const Symbols s1 = forward(), s2 = backward();
  const std::string t1 = print(f(s1)), t2 = print(f(s2));
  EXPECT_EQ(t1, t2);
  return t1;
}

TEST(CanonicalText, SumsAndProductsInOneOrder) {
  // terms by their text without the number, factors by their text, the constant first
  EXPECT_EQ(both([](const Symbols& s) { return s.a - s.b + 2 * s.b * s.a * GiNaC::sin(s.a) + 3; }),
            "3+a+2*a*b*sin(a)-b");
  EXPECT_EQ(both([](const Symbols& s) { return GiNaC::cos(s.b + s.a) * s.c * s.a; }),
            "a*c*cos(a+b)");
}

TEST(CanonicalText, ASumInAProductHasItsFirstTermPositive) {
  EXPECT_EQ(both([](const Symbols& s) { return (s.a - s.b) * s.c; }), "(a-b)*c");
  EXPECT_EQ(both([](const Symbols& s) { return (s.b - s.a) * s.c; }), "-(a-b)*c");
  EXPECT_EQ(both([](const Symbols& s) { return (s.b - s.a) * (s.c - s.a) * s.b; }),
            "(a-b)*(a-c)*b");
  EXPECT_EQ(both([](const Symbols& s) { return GiNaC::pow(s.b - s.a, 3); }), "-(a-b)^3");
  EXPECT_EQ(both([](const Symbols& s) { return GiNaC::pow(s.b - s.a, 2) * s.c; }), "(a-b)^2*c");
  EXPECT_EQ(both([](const Symbols& s) { return s.c / (s.b - s.a); }), "-(a-b)^(-1)*c");
}

// GiNaC's own notation for everything but the order.
TEST(CanonicalText, GiNaCsNotation) {
  EXPECT_EQ(both([](const Symbols& s) { return s.a / 2; }), "1/2*a");
  EXPECT_EQ(both([](const Symbols& s) { return -s.a / 2; }), "-1/2*a");
  EXPECT_EQ(both([](const Symbols& s) { return 1 / s.a; }), "a^(-1)");
  EXPECT_EQ(both([](const Symbols& s) { return GiNaC::sqrt(s.a); }), "sqrt(a)");
  EXPECT_EQ(both([](const Symbols& s) { return GiNaC::pow(s.a, GiNaC::numeric(3, 2)); }),
            "a^(3/2)");
  EXPECT_EQ(both([](const Symbols& s) { return -s.a; }), "-a");
  EXPECT_EQ(both([](const Symbols& s) { return GiNaC::atan2(s.b, s.a); }), "atan2(b,a)");
  EXPECT_EQ(both([](const Symbols& s) { return GiNaC::pow(s.a + s.b, 2); }), "(a+b)^2");
}

TEST(CanonicalText, Latex) {
  EXPECT_EQ(both([](const Symbols& s) { return s.a / 2; }, canonical_latex), "\\frac{1}{2} a");
  EXPECT_EQ(both([](const Symbols& s) { return s.a / s.b; }, canonical_latex), "\\frac{a}{b}");
  EXPECT_EQ(both([](const Symbols& s) { return s.c / (s.b - s.a); }, canonical_latex),
            "-\\frac{c}{\\left(a-b\\right)}");
  // a book's order: the root before the function, \sin a for a lone symbol, \sin^{2} a
  EXPECT_EQ(
      both([](const Symbols& s) { return GiNaC::sin(s.a) * GiNaC::sqrt(s.b); }, canonical_latex),
      "\\sqrt{b} \\sin a");
  EXPECT_EQ(
      both([](const Symbols& s) { return GiNaC::pow(GiNaC::cos(s.a + s.b), 2); }, canonical_latex),
      "\\cos^{2}\\left(a+b\\right)");
  EXPECT_EQ(both([](const Symbols& s) { return GiNaC::pow(s.a, 2); }, canonical_latex), "a^{2}");
}

// The normal form's sign: the denominator's first term positive, whatever GiNaC chose.
TEST(CanonicalText, NormalFormHasOneSign) {
  const std::string text =
      both([](const Symbols& s) { return canonical_normal(s.c / (s.b - s.a) + s.c); });
  EXPECT_EQ(text, "(a*c-b*c-c)*(a-b)^(-1)");
  for (const Symbols& s : {forward(), backward()}) {
    const Expr n = canonical_normal(s.c / (s.b - s.a) + s.c);
    EXPECT_TRUE(GiNaC::normal(n - (s.c / (s.b - s.a) + s.c)).is_zero());
  }
}

}  // namespace
}  // namespace unidyn
