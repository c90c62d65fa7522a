// The Frenet triad of a space curve.
#include "unidyn/kinematics/frenet.hpp"

#include "unidyn/symbolic/canonical_text.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

Expr normal_form(const Expr& e) {
  return normal_within_budget(expand_within_budget(e, "the Frenet triad"), "the Frenet triad");
}

VectorExpr normal_form(const VectorExpr& v) {
  return {normal_form(v[0]), normal_form(v[1]), normal_form(v[2])};
}

}  // namespace

FrenetTriad frenet_triad(const VectorExpr& r, const GiNaC::symbol& u) {
  const VectorExpr r1 = diff(r, u), r2 = diff(r1, u), r3 = diff(r2, u);
  const VectorExpr r1_x_r2 = normal_form(cross(r1, r2));
  FrenetTriad triad;
  const Expr speed_squared = normal_form(dot(r1, r1));
  const Expr area_squared = normal_form(dot(r1_x_r2, r1_x_r2));
  triad.speed = GiNaC::sqrt(speed_squared);
  triad.tangent = normal_form(r1 / triad.speed);
  triad.binormal = normal_form(r1_x_r2 / GiNaC::sqrt(area_squared));
  triad.normal = normal_form(cross(triad.binormal, triad.tangent));
  // κ = ‖r′ × r″‖ / ‖r′‖³, τ = (r′ × r″) · r‴ / ‖r′ × r″‖²
  triad.curvature =
      normal_form(GiNaC::sqrt(area_squared) / GiNaC::pow(speed_squared, 3 / GiNaC::ex(2)));
  triad.torsion = normal_form(dot(r1_x_r2, r3) / area_squared);
  return triad;
}

}  // namespace unidyn
