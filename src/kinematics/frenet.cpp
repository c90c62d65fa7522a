// The Frenet triad of a space curve.
#include "unidyn/kinematics/frenet.hpp"

#include "unidyn/symbolic/canonical_text.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

Expr simplified(const Expr& e) {
  return normal_within_budget(expand_within_budget(e, "the Frenet triad"), "the Frenet triad");
}

VectorExpr simplified(const VectorExpr& v) {
  return {simplified(v[0]), simplified(v[1]), simplified(v[2])};
}

}  // namespace

FrenetTriad frenet_triad(const VectorExpr& r, const GiNaC::symbol& u) {
  const VectorExpr r1 = diff(r, u), r2 = diff(r1, u), r3 = diff(r2, u);
  const VectorExpr r1_x_r2 = simplified(cross(r1, r2));
  FrenetTriad triad;
  const Expr speed_squared = simplified(dot(r1, r1));
  const Expr area_squared = simplified(dot(r1_x_r2, r1_x_r2));
  triad.speed = GiNaC::sqrt(speed_squared);
  triad.tangent = simplified(r1 / triad.speed);
  triad.binormal = simplified(r1_x_r2 / GiNaC::sqrt(area_squared));
  triad.normal = simplified(cross(triad.binormal, triad.tangent));
  // κ = ‖r′ × r″‖ / ‖r′‖³, τ = (r′ × r″) · r‴ / ‖r′ × r″‖²
  triad.curvature =
      simplified(GiNaC::sqrt(area_squared) / GiNaC::pow(speed_squared, 3 / GiNaC::ex(2)));
  triad.torsion = simplified(dot(r1_x_r2, r3) / area_squared);
  return triad;
}

}  // namespace unidyn
