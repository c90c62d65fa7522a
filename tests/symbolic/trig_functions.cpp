// sin x and cos x made once for each argument (symbolic/trig_functions.hpp): GiNaC's own sin and
// cos, evaluated alike (multiples of π), and one node for one argument.
#include <gtest/gtest.h>

#include "unidyn/symbolic/trig_functions.hpp"

namespace unidyn {
namespace {

TEST(TrigFunctions, AreGiNaCsSineAndCosine) {
  const GiNaC::realsymbol q1("q1"), q2("q2");
  for (const Expr& x :
       {Expr(q1), q1 + q2, -q1, q1 - 2 * q2, Expr(0), GiNaC::Pi / 2, Expr(GiNaC::numeric(1, 3))}) {
    EXPECT_TRUE(sine_of(x).is_equal(GiNaC::sin(x))) << x;
    EXPECT_TRUE(cosine_of(x).is_equal(GiNaC::cos(x))) << x;
  }
  // (GiNaC's evaluation kept: cos(π/2) = 0, sin(π/2) = 1)
  EXPECT_TRUE(cosine_of(GiNaC::Pi / 2).is_zero());
  EXPECT_TRUE(sine_of(GiNaC::Pi / 2).is_equal(1));
}

TEST(TrigFunctions, OneNodeForOneArgument) {
  const GiNaC::realsymbol q1("q1"), q2("q2");
  const Expr a = sine_of(q1 + q2), b = sine_of(q2 + q1);
  EXPECT_EQ(&GiNaC::ex_to<GiNaC::basic>(a), &GiNaC::ex_to<GiNaC::basic>(b));
}

}  // namespace
}  // namespace unidyn
