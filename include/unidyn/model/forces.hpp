// The force elements of a model (book §2.4–2.5, §4.5): each gives its potential energy and the
// forces it exerts on particles.
#pragma once

#include <optional>

#include "unidyn/model/angle_joint.hpp"
#include "unidyn/model/system.hpp"

namespace unidyn {

// A point a force element acts at or between: a particle, a material point of a body (the force
// then acts on the body there, with its moment about x̄), or a fixed point.
struct ForcePoint {
  std::optional<std::size_t> particle;
  VectorExpr position;
  std::optional<std::size_t> body;
};

// An empty element of a kind.
ForceElement new_element(ForceElement::Kind kind, const std::string& label, bool conservative);

// Uniform gravity g (a vector, e.g. −g E3) on every particle and body: U = −Σ m g · r (r = x̄ for a
// body), F = m g (at the centre of mass of a body).
ForceElement uniform_gravity(const System& system, const VectorExpr& g);

// (2.5) A spring between two points with energy U(s) of its stretch s = ‖r_to − r_from‖ − L0
// (U = ½ K s² for a linear spring): F_to = −U'(s) e, F_from = U'(s) e, e = (r_to − r_from)/‖·‖.
ForceElement spring(const ForcePoint& from, const ForcePoint& to, const Expr& rest_length,
                    const GiNaC::symbol& stretch, const Expr& energy);

// A linear damper: F_to = −c ṡ e, F_from = c ṡ e with ṡ = e · (v_to − v_from).
ForceElement damper(const System& system, const ForcePoint& from, const ForcePoint& to,
                    const Expr& coefficient);

// A force F(q, q̇, t) on a particle.
ForceElement applied_force(std::size_t particle, const VectorExpr& force);

// A force F(q, q̇, t) on a body at the point x (its centre, or a material point).
ForceElement body_force(std::size_t body, const VectorExpr& point, const VectorExpr& force);

// A pure moment M(q, q̇, t) on a body (e.g. a non-conservative moment, Ziegler's follower torque).
ForceElement body_moment(std::size_t body, const VectorExpr& moment);

// (8.25) MacCullagh's far-field approximation to the gravitation of a sphere (G M, centre x_O) on
// body B, with R = ‖x̄ − x_O‖, c = (x̄ − x_O)/R and J = Q J0 Qᵀ the inertia about x̄:
//   U = −G M m/R − (G M/(2R³)) tr J + (3 G M/(2R³)) c · J c
//   F = −(G M m/R²) c − (3 G M/(2R⁴)) (2 J c + (tr J − 5 c · J c) c)   at x̄
//   M = (3 G M/R³) c × J c                                             about x̄
ForceElement gravity_gradient(const System& system, std::size_t body, const Expr& GM,
                              const VectorExpr& attractor);

// A torsion spring on an angle γ: one of a body's Euler angles (Ex. 8.6) or a joint's angle
// (model/angle_joint.hpp), given by its unit-torque moments: U = ½ K (γ − γ0)², and by (8.27) the
// conservative moments −K (γ − γ0) m_B (along the dual Euler basis vector for an Euler angle, not
// along the angle's axis; ±w on the joint's two bodies).
ForceElement torsion_spring(const System& system, std::size_t angle,
                            const std::vector<AngleTorque>& unit_torque, const Expr& K,
                            const Expr& rest_angle);

// A torsion damper on such an angle: the moments −c γ̇ m_B, whose power is −c γ̇².
ForceElement torsion_damper(const System& system, std::size_t angle,
                            const std::vector<AngleTorque>& unit_torque, const Expr& c);

// A damper in body B's prismatic joint (its displacement d along the unit axis u = Q_B a): the
// force −c ḋ u on B at its frame's origin o and c ḋ u on its parent at the joint's origin, a point
// of the parent on the same line (none on the ground). The two bodies turn together, so the
// points' relative velocity along u is ḋ: the power is −c ḋ², the generalised force −c ḋ on d
// alone.
ForceElement slide_damper(const System& system, std::size_t body, const Expr& c);

// A potential energy U(q, t) given directly in the coordinates.
ForceElement coordinate_potential(const Expr& U);

// (2.5) Newtonian gravitation between two particles: U = −G m1 m2 / ‖r2 − r1‖.
ForceElement gravitation(const System& system, std::size_t first, std::size_t second,
                         const Expr& G);

}  // namespace unidyn
