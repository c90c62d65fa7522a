// Inertia of rigid bodies (book Ch. 7): standard shapes, the parallel-axis theorem, the Euler
// tensor and the realisability of an inertia tensor.
#pragma once

#include <string>
#include <vector>

#include "unidyn/symbolic/expression.hpp"
#include "unidyn/tensor/tensor.hpp"

namespace unidyn {

// The principal moments (A, B, C) about the centre of mass along e1, e2, e3 of a uniform shape of
// mass m. Axis-symmetric shapes have their axis along e3; a box has sides (a, b, c) along e1, e2,
// e3.
//   sphere {radius}: 2/5 m R²           hollow_sphere {radius}: 2/3 m R²
//   cylinder {radius, height}: A = m(3R² + h²)/12, C = m R²/2
//   hollow_cylinder {radius, height}: A = m(6R² + h²)/12, C = m R²
//   disk {radius}: A = m R²/4, C = m R²/2             rod {length}: A = m L²/12, C = 0
//   box {a, b, c}: A = m(b² + c²)/12, ...             ellipsoid {a, b, c}: A = m(b² + c²)/5, ...
//   cone {radius, height} (centre h/4 above the base): A = 3/20 m R² + 3/80 m h², C = 3/10 m R²
// Throws std::invalid_argument for an unknown shape or wrong dimensions (their names are listed
// by shape_dimensions).
std::vector<Expr> shape_principal_moments(const std::string& shape, const Expr& mass,
                                          const std::vector<Expr>& dimensions);
// The dimension names each shape takes, in order ({} for an unknown shape).
std::vector<std::string> shape_dimensions(const std::string& shape);

// Parallel-axis theorem: the inertia about a point at d from the centre of mass,
// J_P = J + m (‖d‖² I − d⊗d).
Tensor parallel_axis(const Tensor& J_center, double mass, const Vec3& d);

// (7.17)–(7.19) Euler tensor E and inertia tensor J: J = (tr E) I − E, E = ½ (tr J) I − J.
Tensor inertia_from_euler_tensor(const Tensor& E);
Tensor euler_tensor_from_inertia(const Tensor& J);

// (7.18′) An inertia tensor a body can have: symmetric, positive semi-definite Euler tensor, i.e.
// principal moments ≥ 0 that satisfy the triangle inequalities A + B ≥ C, B + C ≥ A, C + A ≥ B.
bool is_realisable_inertia(const Tensor& J, double relative_tolerance = 1e-12);

}  // namespace unidyn
