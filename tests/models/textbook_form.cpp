// The printed equations against the book's own (`unidyn derive`, the textbook form) for ten bundled
// models: each grouped coefficient equals the book's, term by term, printed the same way after
// normalisation (the book's expression built here and printed by the same canonical printer), so
// the line is as long as the book's.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "support/model_run.hpp"
#include "unidyn/equations/reduction.hpp"
#include "unidyn/io/textbook_equations.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/textbook_form.hpp"

namespace unidyn {
namespace {

// A parameter's symbol.
Expr parameter(const System& system, const char* name) {
  return system.parameters[*system.find_parameter(name)].symbol;
}

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

// One equation per model, each against the book's (cited), the model's symbols standing for the
// book's.
TEST(TextbookForm, MoreOfTheBooksEquations) {
  using GiNaC::cos;
  using GiNaC::pow;
  using GiNaC::sin;
  // §3.3 (3.3), the spherical pendulum (φ the polar angle from E3, the particle on the sphere L):
  //   m L² φ̈ − m L² sin φ cos φ θ̇² − m g L sin φ = 0
  {
    const System s = load_model(test::model_path("spherical-pendulum"));
    const Expr m = parameter(s, "m"), g = parameter(s, "g"), L = parameter(s, "L");
    const auto& q = s.coordinates();
    const Expr phi = q[0].value;
    EXPECT_EQ(printed_line(s, "phi"),
              book_line({{m * L * L, q[0].acceleration},
                         {-m * L * L * cos(phi) * sin(phi), pow(q[1].rate, 2)},
                         {-m * g * L * sin(phi), 1}}));
  }
  // Exercise 3.7 (3.25), the bead on the rotating hoop: φ̈ = (Ω² cos φ + g/R0) sin φ, times m R0²
  {
    const System s = load_model(test::model_path("rotating-hoop"));
    const Expr m = parameter(s, "m"), g = parameter(s, "g"), R0 = parameter(s, "R0"),
               W = parameter(s, "Omega");
    const auto& q = s.coordinates();
    EXPECT_EQ(printed_line(s, "phi"),
              book_line({{m * R0 * R0, q[0].acceleration},
                         {-m * R0 * (W * W * R0 * cos(q[0].value) + g) * sin(q[0].value), 1}}));
  }
  // §9 (the compound pendulum, the parallel-axis theorem (7.x)): (C + m d²) θ̈ + m g d sin θ = 0
  {
    const System s = load_model(test::model_path("compound-pendulum"));
    const Expr m = parameter(s, "m"), g = parameter(s, "g"), d = parameter(s, "d"),
               C = parameter(s, "C");
    const auto& q = s.coordinates();
    EXPECT_EQ(printed_line(s, "theta"),
              book_line({{C + m * d * d, q[0].acceleration}, {m * g * d * sin(q[0].value), 1}}));
  }
  // §3.3 (3.3), a free particle in spherical coordinates (R, φ from E3, θ), gravity −g E3:
  //   m (R̈ − R φ̇² − R sin²φ θ̇²) = −m g cos φ
  {
    const System s = load_model(test::model_path("free-particle-spherical"));
    const Expr m = parameter(s, "m"), g = parameter(s, "g");
    const auto& q = s.coordinates();
    const Expr R = q[0].value, phi = q[1].value;
    EXPECT_EQ(printed_line(s, "R"), book_line({{m, q[0].acceleration},
                                               {-R * m, pow(q[1].rate, 2)},
                                               {-R * m * pow(sin(phi), 2), pow(q[2].rate, 2)},
                                               {g * m * cos(phi), 1}}));
  }
  // §9.4 (9.8), the unbalanced rotor turning about E3: (J33 + m ε²) θ̈ = M·E3 = 0
  {
    const System s = load_model(test::model_path("unbalanced-rotor"));
    const Expr m = parameter(s, "m"), eps = parameter(s, "eps"), J33 = parameter(s, "J33");
    EXPECT_EQ(printed_line(s, "theta"),
              book_line({{J33 + m * eps * eps, s.coordinates()[0].acceleration}}));
  }
  // Exercise 3.1 (3.20), the particle on the paraboloid in parabolic coordinates: the u equation
  // before v = c and the conserved h are put in,
  //   m (u² + v²) ü + m u u̇² + 2 m v u̇ v̇ − m u v̇² − m u v² θ̇² + m g u = 0
  {
    const System s = load_model(test::model_path("paraboloid"));
    const Expr m = parameter(s, "m"), g = parameter(s, "g");
    const auto& q = s.coordinates();
    const Expr u = q[0].value, v = q[1].value;
    EXPECT_EQ(printed_line(s, "u"), book_line({{(u * u + v * v) * m, q[0].acceleration},
                                               {m * u, pow(q[0].rate, 2)},
                                               {2 * m * v, q[0].rate * q[1].rate},
                                               {-m * u, pow(q[1].rate, 2)},
                                               {-m * u * v * v, pow(q[2].rate, 2)},
                                               {g * m * u, 1}}));
  }
  // §5.4 (5.11)–(5.12), the pendulum on a cart by approach II (y, z1, z2 eliminated): the x and θ
  // rows of M q̈ + f = 0, f1 = −2 m2 ṙ θ̇ sin θ − m2 r θ̇² cos θ, f3 = 2 m2 r ṙ θ̇ + m2 g r cos θ
  {
    const System s = eliminate_constraints(load_model(test::model_path("pendulum-cart"))).system;
    const Expr m1 = parameter(s, "m1"), m2 = parameter(s, "m2"), g = parameter(s, "g");
    const auto& q = s.coordinates();  // x, r, θ
    ASSERT_EQ(q.size(), 3u);
    const Expr r = q[1].value, th = q[2].value;
    EXPECT_EQ(printed_line(s, "x"), book_line({{m1 + m2, q[0].acceleration},
                                               {m2 * cos(th), q[1].acceleration},
                                               {-m2 * r * sin(th), q[2].acceleration},
                                               {-2 * m2 * sin(th), q[1].rate * q[2].rate},
                                               {-m2 * r * cos(th), pow(q[2].rate, 2)}}));
    EXPECT_EQ(printed_line(s, "theta"), book_line({{-m2 * r * sin(th), q[0].acceleration},
                                                   {m2 * r * r, q[2].acceleration},
                                                   {2 * m2 * r, q[1].rate * q[2].rate},
                                                   {g * m2 * r * cos(th), 1}}));
  }
  // §3.8 (3.18), the particle on the helix by approach II (r = R, η = 0):
  //   θ̈ = −g α/(R (1 + α²)), times m R² (1 + α²)
  {
    const System s = eliminate_constraints(load_model(test::model_path("helix"))).system;
    const Expr m = parameter(s, "m"), g = parameter(s, "g"), R = parameter(s, "R"),
               alpha = parameter(s, "alpha");
    ASSERT_EQ(s.coordinates().size(), 1u);
    EXPECT_EQ(printed_line(s, "theta"),
              book_line({{(1 + alpha * alpha) * R * R * m, s.coordinates()[0].acceleration},
                         {R * alpha * g * m, 1}}));
  }
  // §2.8 (2.7)–(2.18), Kepler's problem in polar coordinates: the angular momentum m r² θ̇ is
  // constant, d/dt(m r² θ̇) = m r² θ̈ + 2 m r ṙ θ̇ = 0
  {
    const System s = load_model(test::model_path("kepler"));
    const Expr m = parameter(s, "m");
    const auto& q = s.coordinates();
    const Expr r = q[0].value;
    EXPECT_EQ(printed_line(s, "theta"),
              book_line({{m * r * r, q[1].acceleration}, {2 * m * r, q[0].rate * q[1].rate}}));
  }
}

}  // namespace
}  // namespace unidyn
