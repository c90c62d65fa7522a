// Inertia of standard shapes, parallel axes, Euler tensor.
#include "unidyn/kinematics/inertia.hpp"

#include <map>
#include <stdexcept>

namespace unidyn {
namespace {

const std::map<std::string, std::vector<std::string>>& shapes() {
  static const std::map<std::string, std::vector<std::string>> table = {
      {"sphere", {"radius"}},
      {"hollow_sphere", {"radius"}},
      {"cylinder", {"radius", "height"}},
      {"hollow_cylinder", {"radius", "height"}},
      {"disk", {"radius"}},
      {"rod", {"length"}},
      {"box", {"a", "b", "c"}},
      {"ellipsoid", {"a", "b", "c"}},
      {"cone", {"radius", "height"}}};
  return table;
}

}  // namespace

std::vector<std::string> shape_dimensions(const std::string& shape) {
  const auto it = shapes().find(shape);
  return it == shapes().end() ? std::vector<std::string>{} : it->second;
}

std::vector<Expr> shape_principal_moments(const std::string& shape, const Expr& m,
                                          const std::vector<Expr>& d) {
  const auto names = shape_dimensions(shape);
  if (names.empty()) throw std::invalid_argument("unknown shape '" + shape + "'");
  if (d.size() != names.size()) throw std::invalid_argument("wrong dimensions for " + shape);
  const auto sq = [](const Expr& x) { return x * x; };
  if (shape == "sphere") return {m * sq(d[0]) * 2 / 5, m * sq(d[0]) * 2 / 5, m * sq(d[0]) * 2 / 5};
  if (shape == "hollow_sphere") {
    return {m * sq(d[0]) * 2 / 3, m * sq(d[0]) * 2 / 3, m * sq(d[0]) * 2 / 3};
  }
  if (shape == "cylinder") {
    const Expr A = m * (3 * sq(d[0]) + sq(d[1])) / 12;
    return {A, A, m * sq(d[0]) / 2};
  }
  if (shape == "hollow_cylinder") {
    const Expr A = m * (6 * sq(d[0]) + sq(d[1])) / 12;
    return {A, A, m * sq(d[0])};
  }
  if (shape == "disk") return {m * sq(d[0]) / 4, m * sq(d[0]) / 4, m * sq(d[0]) / 2};
  if (shape == "rod") return {m * sq(d[0]) / 12, m * sq(d[0]) / 12, 0};
  if (shape == "box") {
    return {m * (sq(d[1]) + sq(d[2])) / 12, m * (sq(d[0]) + sq(d[2])) / 12,
            m * (sq(d[0]) + sq(d[1])) / 12};
  }
  if (shape == "ellipsoid") {
    return {m * (sq(d[1]) + sq(d[2])) / 5, m * (sq(d[0]) + sq(d[2])) / 5,
            m * (sq(d[0]) + sq(d[1])) / 5};
  }
  // cone
  const Expr A = m * sq(d[0]) * 3 / 20 + m * sq(d[1]) * 3 / 80;
  return {A, A, m * sq(d[0]) * 3 / 10};
}

Tensor parallel_axis(const Tensor& J_center, double mass, const Vec3& d) {
  return J_center + mass * (d.squaredNorm() * Tensor::Identity() - tensor_product(d, d));
}

Tensor inertia_from_euler_tensor(const Tensor& E) {
  // (7.19) J = (tr E) I − E
  return E.trace() * Tensor::Identity() - E;
}

Tensor euler_tensor_from_inertia(const Tensor& J) {
  // tr J = 2 tr E, so E = ½ (tr J) I − J
  return 0.5 * J.trace() * Tensor::Identity() - J;
}

bool is_realisable_inertia(const Tensor& J, double relative_tolerance) {
  if (!J.allFinite() || (J - J.transpose()).cwiseAbs().maxCoeff() >
                            relative_tolerance * (1 + J.cwiseAbs().maxCoeff())) {
    return false;
  }
  // the Euler tensor Σ m x⊗x of any mass distribution is positive semi-definite
  const Vec3 e = spectral_decomposition(euler_tensor_from_inertia(J)).values;
  return e.minCoeff() >= -relative_tolerance * (1 + J.cwiseAbs().maxCoeff());
}

}  // namespace unidyn
