// Numbered intermediate quantities (symbolic/common_subexpressions.hpp): the repeated
// subexpressions are named once, each in terms of the earlier names only, and substituting the
// names back gives the expressions again.
#include "unidyn/symbolic/common_subexpressions.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "unidyn/symbolic/canonical_text.hpp"

namespace unidyn {
namespace {

const GiNaC::realsymbol a("a"), b("b"), m("m"), l("l");

// The expressions with every z replaced by its value, the last one first.
std::vector<Expr> expanded_back(const Intermediates& z) {
  std::vector<Expr> out = z.expressions;
  for (std::size_t k = z.names.size(); k-- > 0;) {
    for (Expr& e : out) e = e.subs(GiNaC::exmap{{z.names[k], z.values[k]}});
  }
  return out;
}

TEST(CommonSubexpressions, RepeatedPartsNamedOnceAndBack) {
  // GiNaC flattens products, so the shared part sits inside functions here
  const Expr shared = m * l * GiNaC::cos(a - b);
  const std::vector<Expr> given{GiNaC::sin(shared) + 3, 2 * GiNaC::sin(shared) + GiNaC::pow(l, 2),
                                GiNaC::cos(a - b) * a, m + l};
  const Intermediates z = common_subexpressions(given);
  // cos(a − b) (twice: in the shared part and alone) before the sine that holds it, which uses z1;
  // a − b and m l cos(a − b) occur again only inside what is named already
  ASSERT_EQ(z.names.size(), 2u);
  EXPECT_EQ(canonical_text(z.names[0]), "z1");
  EXPECT_EQ(canonical_text(z.values[0]), "cos(a-b)");
  EXPECT_EQ(canonical_text(z.values[1]), "sin(l*m*z1)");
  EXPECT_EQ(canonical_text(z.expressions[1]), "l^2+2*z2");
  for (std::size_t k = 0; k < z.values.size(); ++k) {
    for (std::size_t j = k; j < z.names.size(); ++j) {
      EXPECT_FALSE(z.values[k].has(z.names[j])) << k << " uses z" << j + 1;
    }
  }
  // m + l occurs once: not named
  EXPECT_EQ(canonical_text(z.expressions[3]), "l+m");
  const std::vector<Expr> back = expanded_back(z);
  for (std::size_t i = 0; i < given.size(); ++i) {
    EXPECT_TRUE(GiNaC::expand(back[i] - given[i]).is_zero()) << given[i];
  }
}

TEST(CommonSubexpressions, AnExpressionAndItsNegativeAreOne) {
  // m l sin(a − b) and −m l sin(a − b), (a − b) written either way round inside a sine's argument
  const Expr part = m * l * GiNaC::sin(a - b);
  const std::vector<Expr> given{GiNaC::cos(part) * a, GiNaC::cos(-part) * b,
                                GiNaC::exp(l - m + a) + GiNaC::exp(m - l - a)};
  const Intermediates z = common_subexpressions(given);
  std::vector<std::string> values;
  for (const Expr& v : z.values) values.push_back(canonical_text(v));
  // one name for ±m l sin(a − b), one for ±(a + l − m): the positive ones
  EXPECT_NE(std::find(values.begin(), values.end(), "l*m*sin(a-b)"), values.end());
  EXPECT_NE(std::find(values.begin(), values.end(), "a+l-m"), values.end());
  for (const std::string& v : values) EXPECT_FALSE(v.starts_with("-")) << v;
  const std::vector<Expr> back = expanded_back(z);
  for (std::size_t i = 0; i < given.size(); ++i) {
    EXPECT_TRUE(GiNaC::expand(back[i] - given[i]).is_zero()) << given[i];
  }
}

}  // namespace
}  // namespace unidyn
