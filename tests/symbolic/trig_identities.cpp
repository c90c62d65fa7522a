// Angle sums and homogenisation (symbolic/trig_identities.hpp): each result equals its input
// (checked by simplify on the difference and at numbers) and has the form the identity gives.
#include "unidyn/symbolic/trig_identities.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "unidyn/symbolic/canonical_text.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

const GiNaC::realsymbol a("a"), b("b"), K("K"), m("m");

// e and f agree at a few values of a and b.
void expect_equal_values(const Expr& e, const Expr& f) {
  for (const double x : {0.3, 1.7, -2.2}) {
    for (const double y : {0.9, -0.4}) {
      const GiNaC::exmap at{{a, x}, {b, y}, {K, 1.3}, {m, 0.7}};
      const double u = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
      const double v = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(f.subs(at))).to_double();
      EXPECT_NEAR(u, v, 1e-12 * (1 + std::abs(u)));
    }
  }
}

TEST(TrigIdentities, AngleSumsAndDifferences) {
  using GiNaC::cos;
  using GiNaC::sin;
  const struct {
    Expr in, out;
  } cases[] = {
      {K * cos(a) * cos(b) + K * sin(a) * sin(b), K * cos(a - b)},
      {K * cos(a) * cos(b) - K * sin(a) * sin(b), K * cos(a + b)},
      {K * sin(a) * cos(b) + K * cos(a) * sin(b), K * sin(a + b)},
      {K * sin(a) * cos(b) - K * cos(a) * sin(b), K * sin(a - b)},
      // with other factors, other terms, and a factor (m) that differs
      {m * K * cos(a) * cos(b) + m * K * sin(a) * sin(b) + sin(a), m * K * cos(a - b) + sin(a)},
      {cos(a) * cos(b) + m * sin(a) * sin(b), cos(a) * cos(b) + m * sin(a) * sin(b)},
      // the double pendulum with relative angles: sin(a + b) sin a + cos a cos(a + b) = cos b
      {sin(a + b) * sin(a) + cos(a) * cos(a + b), cos(b)},
      // the combined term joins a term of its kind, or cancels it
      {K * cos(a) * cos(b) + K * sin(a) * sin(b) + K * cos(a - b), 2 * K * cos(a - b)},
      {K * cos(a) * cos(b) + K * sin(a) * sin(b) + K * cos(a - b) + m * cos(a) * cos(b) +
           m * sin(a) * sin(b),
       2 * K * cos(a - b) + m * cos(a - b)},
      {K * cos(a) * cos(b) + K * sin(a) * sin(b) - K * cos(a - b) + m, m},
      // three angles: a combined term combines again (a rotation's entry)
      {cos(a) * cos(b) * cos(m) - sin(a) * sin(b) * cos(m) - sin(a) * cos(b) * sin(m) -
           cos(a) * sin(b) * sin(m),
       cos(a + b + m)},
  };
  for (const auto& c : cases) {
    const Expr combined = combine_angle_sums(c.in);
    EXPECT_EQ(canonical_text(combined), canonical_text(c.out)) << c.in;
    expect_equal_values(combined, c.in);
  }
}

// C − C sin²θ + A sin²θ = A sin²θ + C cos²θ (degree 2); odd and even degrees apart.
TEST(TrigIdentities, Homogenisation) {
  using GiNaC::cos;
  using GiNaC::pow;
  using GiNaC::sin;
  const Expr top = K - K * pow(sin(a), 2) + m * pow(sin(a), 2);
  const Expr h = homogenize_trig(top);
  EXPECT_EQ(canonical_text(h), canonical_text(K * pow(cos(a), 2) + m * pow(sin(a), 2)));
  expect_equal_values(h, top);
  // 1 + sin a + cos²a: the constant raised to degree 2, sin a alone in the odd class
  const Expr mixed = 1 + sin(a) + pow(cos(a), 2);
  const Expr hm = homogenize_trig(mixed);
  EXPECT_EQ(canonical_text(hm), canonical_text(2 * pow(cos(a), 2) + pow(sin(a), 2) + sin(a)));
  expect_equal_values(hm, mixed);
  // nothing below the top degree: unchanged
  EXPECT_EQ(canonical_text(homogenize_trig(K * pow(sin(b), 2))), "K*sin(b)^2");
}

// Collected in the sines and cosines: one term per product of their powers, the coefficients
// summed; none where a sine sits under a root or there is none.
TEST(TrigIdentities, CollectionInSinesAndCosines) {
  using GiNaC::cos;
  using GiNaC::pow;
  using GiNaC::sin;
  const Expr e = (K + m) * sin(a) + K * m * sin(a) * cos(b) - m * sin(a) * cos(b) +
                 K * pow(cos(a), 2) + m * pow(cos(a), 2) + K;
  const auto collected = collect_in_sines_and_cosines(e);
  ASSERT_TRUE(collected.has_value());
  EXPECT_EQ(canonical_text(*collected),
            canonical_text((K + m) * sin(a) + (K * m - m) * sin(a) * cos(b) +
                           (K + m) * pow(cos(a), 2) + K));
  expect_equal_values(*collected, e);
  // a term per product: four here
  ASSERT_TRUE(GiNaC::is_exactly_a<GiNaC::add>(*collected));
  EXPECT_EQ(collected->nops(), 4u);
  EXPECT_FALSE(collect_in_sines_and_cosines(K * GiNaC::sqrt(sin(a)) + sin(a)).has_value());
  EXPECT_FALSE(collect_in_sines_and_cosines(K / cos(a) + sin(a)).has_value());
  EXPECT_FALSE(collect_in_sines_and_cosines(K * m + K).has_value());
}

TEST(TrigIdentities, ArgumentsInTheCanonicalOrder) {
  const auto arguments = trig_arguments(GiNaC::cos(b) * GiNaC::sin(a + b) + GiNaC::sin(a));
  ASSERT_EQ(arguments.size(), 3u);
  EXPECT_EQ(canonical_text(arguments[0]), "a");
  EXPECT_EQ(canonical_text(arguments[1]), "a+b");
  EXPECT_EQ(canonical_text(arguments[2]), "b");
}

TEST(TrigIdentities, ArgumentsAreThoseGiNaCsFindGives) {
  // the outermost sines and the outermost cosines: sin(b) inside sin(a + sin b) is not one of
  // the sines found, though the cosine inside it is
  const Expr e = GiNaC::sin(a + GiNaC::sin(b)) * GiNaC::cos(m) +
                 K * GiNaC::sin(a + GiNaC::cos(b * b)) + GiNaC::cos(GiNaC::sin(K)) +
                 GiNaC::pow(GiNaC::cos(m), 2) * GiNaC::sqrt(1 + GiNaC::sin(a));
  GiNaC::exset found;
  e.find(GiNaC::sin(GiNaC::wild()), found);
  e.find(GiNaC::cos(GiNaC::wild()), found);
  std::set<std::string> expected;
  for (const Expr& f : found) expected.insert(canonical_text(f.op(0)));
  std::set<std::string> got;
  for (const Expr& x : trig_arguments(e)) got.insert(canonical_text(x));
  EXPECT_EQ(got, expected);
  EXPECT_EQ(got.count("b"), 0u);    // sin(b) inside a sine's argument
  EXPECT_EQ(got.count("b^2"), 1u);  // cos(b²) inside a sine's argument
  EXPECT_EQ(got.count("K"), 1u);    // sin(K) inside a cosine's argument
}

}  // namespace
}  // namespace unidyn
