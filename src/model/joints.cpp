// Ball joints and pins as constraints with their Lagrange representation (8.22)–(8.24).
#include "unidyn/model/joints.hpp"

#include "unidyn/symbolic/printing.hpp"

#include <array>
#include <stdexcept>

namespace unidyn {
namespace {

// The end's point in space x_P and its arm π_P = x_P − x̄ (0 on the ground).
struct Placed {
  VectorExpr position;
  VectorExpr arm;
};

Placed place(const System& system, const JointEnd& end) {
  if (!end.body) return {end.point, VectorExpr{}};
  const Body& body = system.bodies[*end.body];
  const VectorExpr arm = times(body.rotation, end.point);
  return {body.center + arm, arm};
}

// A vector on the end's body basis carried into space (Q A), or the ground's fixed vector.
VectorExpr in_space(const System& system, const JointEnd& end, const VectorExpr& v) {
  return end.body ? times(system.bodies[*end.body].rotation, v) : v;
}

Constraint row(const std::string& joint, int k, const Expr& psi, const SourcePosition& where,
               Constraint::Kind kind = Constraint::Kind::position) {
  const std::string name = joint + "_" + std::to_string(k);
  return {name,
          kind,
          psi,
          GiNaC::realsymbol("lambda(" + name + ")",
                            "\\mu_{\\mathrm{" + joint + "}," + std::to_string(k) + "}"),
          false,
          std::nullopt,
          where,
          joint,
          {},
          false,
          0,
          {}};
}

// Adds (f, h) on the end's body, if it has one.
void load(Constraint& c, const JointEnd& end, const VectorExpr& f, const VectorExpr& h) {
  if (end.body) c.loads.push_back({*end.body, f, h});
}

// A unit vector of exact numbers, from numbers.
VectorExpr unit_numeric(const VectorExpr& v, const char* which) {
  for (int i = 0; i < 3; ++i) {
    if (!GiNaC::is_a<GiNaC::numeric>(v[i])) {
      throw std::invalid_argument(std::string("the ") + which +
                                  " of a pin must be a vector of numbers");
    }
  }
  const Expr length = norm(v);
  if (length.is_zero()) throw std::invalid_argument(std::string("the ") + which + " is zero");
  return v / length;
}

// B1, B2 completing the unit vector of numbers A to an orthonormal triad {A, B1, B2}: B1 from the
// basis vector least aligned with A.
std::array<VectorExpr, 2> perpendiculars(const VectorExpr& A) {
  const auto size = [&](int k) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(GiNaC::abs(A[k - 1]))).to_double();
  };
  int least = 1;
  for (int k = 2; k <= 3; ++k) {
    if (size(k) < size(least)) least = k;
  }
  VectorExpr B1 = cross(A, basis_vector_expr(least));
  B1 = B1 / norm(B1);
  return {B1, cross(A, B1)};
}

// The tangents t_1, t_2 of a surface with normal n: for numbers, completing n/‖n‖ to an
// orthonormal triad; for an expression of the coordinates, perpendicular to a basis vector E_k
// throughout (a cylinder about E_k), t_1 = E_k and t_2 = n × E_k/‖n‖, defined wherever n ≠ 0.
std::array<VectorExpr, 2> surface_tangents(const VectorExpr& normal) {
  bool numeric = true;
  for (int i = 0; i < 3; ++i) numeric = numeric && GiNaC::is_a<GiNaC::numeric>(normal[i]);
  if (numeric) return perpendiculars(unit_numeric(normal, "normal"));
  for (int k = 1; k <= 3; ++k) {
    const VectorExpr E = basis_vector_expr(k);
    if (simplify(dot(normal, E)).is_zero()) return {E, cross(normal, E) / norm(normal)};
  }
  throw std::invalid_argument(
      "a normal that changes with the coordinates must be perpendicular to one of E1, E2, E3 "
      "throughout (a cylinder about that axis), so that its tangents E_k and n x E_k are defined "
      "everywhere; give the normal as numbers for a plane");
}

}  // namespace

std::vector<Constraint> rolling_contact(const System& system, const std::string& name,
                                        std::size_t body, const VectorExpr& contact,
                                        const VectorExpr& normal, const SourcePosition& where) {
  const VectorExpr arm = contact - system.bodies[body].center;
  // v_P = v̄ + ω × (x_P − x̄), the velocity of the body's material point at the contact
  const VectorExpr v_P = system.center_velocity(body) + cross(system.angular_velocity(body), arm);
  std::vector<Constraint> rows;
  int k = 1;
  for (const VectorExpr& t : surface_tangents(normal)) {
    // v_P · t = 0: f = t, h = (x_P − x̄) × t
    Constraint c = row(name, k++, dot(v_P, t), where, Constraint::Kind::velocity);
    c.loads.push_back({body, t, cross(arm, t)});
    rows.push_back(std::move(c));
  }
  return rows;
}

std::vector<Constraint> ball_joint(const System& system, const std::string& name,
                                   const JointEnd& first, const JointEnd& second,
                                   const SourcePosition& where) {
  const Placed p1 = place(system, first), p2 = place(system, second);
  std::vector<Constraint> rows;
  for (int k = 1; k <= 3; ++k) {
    // Ψ_k = (x_P1 − x_P2) · E_k, f = ±E_k, h = ±π_P × E_k
    const VectorExpr E = basis_vector_expr(k);
    Constraint c = row(name, k, dot(p1.position - p2.position, E), where);
    load(c, first, E, cross(p1.arm, E));
    load(c, second, -E, -cross(p2.arm, E));
    rows.push_back(std::move(c));
  }
  return rows;
}

std::vector<Constraint> pin_joint(const System& system, const std::string& name,
                                  const JointEnd& first, const JointEnd& second,
                                  const SourcePosition& where) {
  std::vector<Constraint> rows = ball_joint(system, name, first, second, where);
  const VectorExpr A1 = unit_numeric(first.axis, "first axis");
  const VectorExpr A2 = unit_numeric(second.axis, "second axis");
  const VectorExpr a1 = in_space(system, first, A1);
  int k = 4;
  for (const VectorExpr& B : perpendiculars(A2)) {
    // Ψ = a_1 · b_j, f = 0, h = ±a_1 × b_j
    const VectorExpr b = in_space(system, second, B);
    Constraint c = row(name, k++, dot(a1, b), where);
    const VectorExpr h = cross(a1, b);
    load(c, first, VectorExpr{}, h);
    load(c, second, VectorExpr{}, -h);
    rows.push_back(std::move(c));
  }
  return rows;
}

}  // namespace unidyn
