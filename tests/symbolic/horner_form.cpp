// Common factors taken out of sums (symbolic/horner_form.hpp).
#include "unidyn/symbolic/horner_form.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <complex>
#include <map>
#include <random>

#include "support/random_expressions.hpp"
#include "unidyn/symbolic/canonical_text.hpp"

namespace unidyn {
namespace {

using GiNaC::is_a;

// The arithmetic operations a tree costs, nothing shared: a sum of k terms k − 1 additions, a
// product of k factors (its number counted unless ±1) k − 1 multiplications, an integer power n
// by repeated squaring, any other power and each function one call, and all their parts.
int operations(const Expr& e) {
  if (is_a<GiNaC::add>(e) || is_a<GiNaC::mul>(e)) {
    int count = static_cast<int>(e.nops()) - 1;
    for (std::size_t k = 0; k < e.nops(); ++k) {
      const Expr& part = e.op(k);
      if (is_a<GiNaC::numeric>(part)) {
        if (is_a<GiNaC::mul>(e) && abs(GiNaC::ex_to<GiNaC::numeric>(part)).is_equal(1)) --count;
        continue;
      }
      count += operations(part);
    }
    return count;
  }
  if (is_a<GiNaC::power>(e)) {
    const Expr& n = e.op(1);
    int count = operations(e.op(0));
    if (!n.info(GiNaC::info_flags::integer)) return count + 1 + operations(n);
    long k = std::abs(GiNaC::ex_to<GiNaC::numeric>(n).to_long());
    if (GiNaC::ex_to<GiNaC::numeric>(n).is_negative()) ++count;  // the reciprocal
    for (; k > 1; k >>= 1) count += (k & 1) ? 2 : 1;
    return count;
  }
  if (is_a<GiNaC::function>(e)) {
    int count = 1;
    for (std::size_t k = 0; k < e.nops(); ++k) count += operations(e.op(k));
    return count;
  }
  return 0;
}

// e's value with each of the test symbols given a value of its own (complex where a root or a
// logarithm of a negative number asks for it).
std::complex<double> value(const Expr& e, const GiNaC::exmap& point) {
  const Expr v = GiNaC::evalf(e.subs(point));
  if (!is_a<GiNaC::numeric>(v)) return {NAN, NAN};
  const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(v);
  return {GiNaC::real(n).to_double(), GiNaC::imag(n).to_double()};
}

const GiNaC::realsymbol a("a"), b("b"), d("d"), x("x"), y("y"), z("z");

TEST(HornerForm, TakesOutTheFactorMostTermsHold) {
  EXPECT_EQ(canonical_text(horner_form(a * x + a * y + b * x)), "(x+y)*a+b*x");
  // then again inside: a b x + a b y + a z = a (b (x + y) + z)
  EXPECT_EQ(canonical_text(horner_form(a * b * x + a * b * y + a * z)), "((x+y)*b+z)*a");
  // a denominator is a factor like any other
  EXPECT_EQ(canonical_text(horner_form(x / d + y / d)), "(x+y)*d^(-1)");
  // a power only where it is held at that power
  EXPECT_EQ(canonical_text(horner_form(x * x * y + x * x * z)), "(y+z)*x^2");
  EXPECT_EQ(canonical_text(horner_form(GiNaC::pow(x, 3) * y + x * z)), "x*z+x^3*y");
  // numbers stay in the terms; nothing shared, nothing changes
  EXPECT_EQ(canonical_text(horner_form(2 * a * x + 3 * a * y + 1)), "1+(2*x+3*y)*a");
  EXPECT_EQ(canonical_text(horner_form(a * x + b * y)), "a*x+b*y");
  // inside functions and factors
  EXPECT_EQ(canonical_text(horner_form(GiNaC::sin(a * x + a * y) * (b * x + b * z))),
            "(x+z)*b*sin((x+y)*a)");
}

// Which factor goes first among equals follows the canonical order, not GiNaC's order of the
// moment: the same result whichever symbols were made first. That includes the sign GiNaC gives a
// sum inside a product (x − y or −(y − x)), which follows its order too.
TEST(HornerForm, TiesBrokenInTheCanonicalOrder) {
  for (int k = 0; k < 20; ++k) {
    // symbols made in another order each time, so that GiNaC's order changes
    std::vector<GiNaC::realsymbol> made;
    for (const char* name : {"x", "y", "a", "b", "c"}) made.emplace_back(name);
    if (k % 2 == 1) std::reverse(made.begin(), made.end());
    std::rotate(made.begin(), made.begin() + k % 5, made.end());
    std::map<std::string, Expr> s;
    for (const auto& m : made) s[m.get_name()] = m;
    const Expr &x_ = s["x"], &y_ = s["y"], &a_ = s["a"], &b_ = s["b"], &c_ = s["c"];
    EXPECT_EQ(canonical_text(horner_form(a_ * x_ + a_ * y_ + b_ * x_ + b_ * y_)),
              "(x+y)*a+(x+y)*b");
    const Expr e = (x_ - y_) * a_ * c_ + (y_ - x_) * b_ * c_ + (x_ - y_) * b_ + a_ * b_;
    EXPECT_EQ(canonical_text(horner_form(e)), "-((-1+c)*(x-y)-a)*b+(x-y)*a*c") << k;
  }
}

// On 2 000 random expressions: the same value at a point, and never more operations as a tree.
TEST(HornerForm, SameValueNeverMoreOperations) {
  using test::L;
  using test::m;
  using test::q1;
  using test::q2;
  using test::u;
  std::mt19937 rng(7);
  const GiNaC::exmap point{{q1, 0.37}, {q2, -1.21}, {u, 0.83}, {m, 1.7}, {L, 2.3}};
  int fewer = 0;
  for (int k = 0; k < 2000; ++k) {
    // expanded, so that sums share factors to take out
    const Expr e = GiNaC::expand(test::random_expression(rng, 3));
    const Expr h = horner_form(e);
    const std::complex<double> want = value(e, point), got = value(h, point);
    if (std::isfinite(want.real()) && std::isfinite(want.imag()) && std::abs(want) < 1e12) {
      EXPECT_LE(std::abs(got - want), 1e-9 * (1 + std::abs(want))) << e << "\n" << h;
    }
    EXPECT_LE(operations(h), operations(e)) << e << "\n" << h;
    if (operations(h) < operations(e)) ++fewer;
  }
  // and the test is not idle: a good many of them got cheaper (174 of the 2 000)
  EXPECT_GT(fewer, 100);
}

// Subexpressions met in several expressions are treated once, with one result.
TEST(HornerForm, BatchEqualsOneByOne) {
  const Expr shared = a * x + a * y;
  const std::vector<Expr> es{shared, GiNaC::sin(shared) + b, shared * z};
  const std::vector<Expr> together = horner_form(es);
  ASSERT_EQ(together.size(), es.size());
  for (std::size_t k = 0; k < es.size(); ++k) {
    EXPECT_EQ(canonical_text(together[k]), canonical_text(horner_form(es[k])));
  }
}

}  // namespace
}  // namespace unidyn
