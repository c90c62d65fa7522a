// Textbook simplification (symbolic/textbook_form.hpp) of what has no textbook form to find: the
// result still equals the input.
#include "unidyn/symbolic/textbook_form.hpp"

#include <gtest/gtest.h>

#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

// A sine under a root (the bicycle's front contact): collecting in the sines has no degree there
// (GiNaC throws); the expression is tidied without it.
TEST(TextbookForm, SineUnderARootIsLeftUncollected) {
  const GiNaC::realsymbol a("a"), b("b");
  const Expr e = b * b * GiNaC::sin(a) * GiNaC::sqrt(2 - pow(GiNaC::sin(a), 2)) + b * GiNaC::cos(a);
  Expr simple;
  ASSERT_NO_THROW(simple = textbook_simplify(e));
  const GiNaC::exmap at{{a, 0.7}, {b, -1.3}};
  EXPECT_NEAR(*real_value(simple, at), *real_value(e, at), 1e-14);
}

}  // namespace
}  // namespace unidyn
