// The representative point in E^{3N} and its coordinate bases.
#include "unidyn/kinematics/representative_point.hpp"

#include <stdexcept>

#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"

namespace unidyn {

Expr dot(const PointVector& u, const PointVector& v) {
  Expr sum = 0;
  for (std::size_t K = 0; K < u.size(); ++K) sum += u[K] * v[K];
  return sum;
}

RepresentativePoint representative_point(const System& system) {
  if (!system.bodies.empty()) {
    throw std::invalid_argument("the representative point (§4.7) is of a system of particles only");
  }
  RepresentativePoint point;
  for (const Particle& p : system.particles) point.mass += p.mass;
  // (4.15) r = Σ (r_i · E_j) √(m_i/m) ē_K
  for (const Particle& p : system.particles) {
    const Expr scale = GiNaC::sqrt(p.mass / point.mass);
    for (int j = 0; j < 3; ++j) {
      point.scale.push_back(scale);
      point.position.push_back(scale * p.position[j]);
    }
  }
  const std::size_t n = system.coordinates().size(), dimension = point.position.size();
  // a_K = ∂r/∂q^K, and a_JK = a_J · a_K
  for (const auto& q : system.coordinates()) {
    PointVector a;
    for (const Expr& x : point.position) a.push_back(derivative(x, q.value));
    point.covariant.push_back(std::move(a));
  }
  const auto size = static_cast<unsigned>(n);
  point.metric = GiNaC::matrix(size, size);
  for (unsigned J = 0; J < n; ++J) {
    for (unsigned K = 0; K < n; ++K) {
      point.metric(J, K) = normal_within_budget(dot(point.covariant[J], point.covariant[K]),
                                                "the metric of the representative point");
    }
  }
  if (n != dimension) return point;
  // a^J = grad q^J: on ē_K, the rows of (∂x/∂q)⁻¹ times √(m/m_i), x the plain Cartesian
  // components (the Jacobian of r divided by the scales)
  GiNaC::matrix jacobian(size, size);
  for (unsigned K = 0; K < n; ++K) {
    for (unsigned J = 0; J < n; ++J) jacobian(K, J) = point.covariant[J][K] / point.scale[K];
  }
  GiNaC::matrix inverse;
  try {
    inverse = jacobian.inverse();
  } catch (const std::exception&) {
    return point;  // the coordinates do not fix the particles one to one
  }
  for (unsigned J = 0; J < n; ++J) {
    PointVector a;
    for (unsigned K = 0; K < n; ++K)
      a.push_back(normal_within_budget(inverse(J, K) / point.scale[K], "the vectors a^J"));
    point.contravariant.push_back(std::move(a));
  }
  return point;
}

}  // namespace unidyn
