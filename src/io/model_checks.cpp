// Checks of a model that need its values: masses positive, inertia tensors that a body can have
// (positive semi-definite, principal moments within the triangle inequalities (7.18′)), no body
// turning about an axis along which it has no inertia, no coordinate that moves nothing.
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "model_reader.hpp"

namespace unidyn::model_reading {
namespace {

// Values of every coordinate, rate, t and parameter for one random state (parameters as given).
GiNaC::exmap random_state(const System& system, std::mt19937& random) {
  std::uniform_real_distribution<double> value(-1.3, 1.7);
  GiNaC::exmap values = system.parameter_values();
  values[system.time()] = value(random);
  for (const auto& q : system.coordinates()) {
    values[q.value] = value(random);
    values[q.rate] = value(random);
  }
  return values;
}

}  // namespace

void ModelReader::expect_positive_mass(const YAML::Node& node, const Expr& mass,
                                       const System& system) const {
  const auto value = real_value(mass, system.parameter_values());
  if (value && *value <= 0) {
    fail(node,
         "a mass must be positive; with the parameters' values it is " + std::to_string(*value));
  }
}

void ModelReader::expect_realisable_inertia(const YAML::Node& node, const GiNaC::matrix& J,
                                            const System& system) const {
  Eigen::Matrix3d values;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned k = 0; k < 3; ++k) {
      const auto v = real_value(J(i, k), system.parameter_values());
      if (!v) return;  // not a number with the parameters' values: nothing to check here
      values(i, k) = *v;
    }
  }
  const Eigen::Vector3d moments =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(values).eigenvalues();
  const double tolerance = 1e-12 * std::max(1.0, moments.cwiseAbs().maxCoeff());
  const auto text = [&] {
    return fmt::format("the principal moments are {}, {}, {}", moments[0], moments[1], moments[2]);
  };
  if (moments.minCoeff() < -tolerance) {
    fail(node, "an inertia tensor must be positive semi-definite: " + text());
  }
  // (7.18′) each principal moment at most the sum of the other two (a lamina on the boundary)
  for (int i = 0; i < 3; ++i) {
    if (moments[i] > moments[(i + 1) % 3] + moments[(i + 2) % 3] + tolerance) {
      fail(node,
           "no body has this inertia: a principal moment exceeds the sum of the other two "
           "(7.18'): " +
               text());
    }
  }
}

void ModelReader::expect_inertia_about_rotation_axes(const YAML::Node& node, std::size_t b,
                                                     const System& system) const {
  const Body& body = system.bodies[b];
  Eigen::Matrix3d values;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned k = 0; k < 3; ++k) {
      const auto v = real_value(body.inertia(i, k), system.parameter_values());
      if (!v) return;
      values(i, k) = *v;
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(values);
  const double scale = std::max(1e-300, eigen.eigenvalues().cwiseAbs().maxCoeff());
  const VectorExpr omega = system.angular_velocity(b);
  std::mt19937 random(20261123);
  for (int a = 0; a < 3; ++a) {
    if (eigen.eigenvalues()[a] > 1e-12 * scale) continue;
    // the axis of zero inertia, on e1, e2, e3, and as a vector Q a
    const Eigen::Vector3d axis = eigen.eigenvectors().col(a);
    Expr along = 0;
    for (unsigned i = 0; i < 3; ++i) {
      for (unsigned k = 0; k < 3; ++k)
        along += omega[static_cast<int>(i)] * body.rotation(i, k) * axis[k];
    }
    for (int trial = 0; trial < 3; ++trial) {
      const GiNaC::exmap state = random_state(system, random);
      const auto w = real_value(along, state);
      double size = 0;
      for (int i = 0; i < 3; ++i) size += std::pow(real_value(omega[i], state).value_or(0), 2);
      if (w && std::abs(*w) > 1e-9 * (1 + std::sqrt(size))) {
        fail(node, "body '" + body.name + "' turns about its axis " +
                       fmt::format("[{:.6g}, {:.6g}, {:.6g}]", axis[0], axis[1], axis[2]) +
                       " (on e1, e2, e3), along which its inertia is zero (a rod lies along e3): "
                       "that rotation would have no inertia; turn the body so that it rotates "
                       "about another axis, or give it inertia about this one");
      }
    }
  }
}

void ModelReader::expect_every_coordinate_moves(const System& system) const {
  // the symbols of every particle's position and every body's centre and rotation
  SymbolsIn placed;
  for (const auto& p : system.particles) placed.add(p.position);
  for (const auto& body : system.bodies) {
    placed.add(body.center);
    placed.add(Expr(body.rotation));
  }
  const auto& q = system.coordinates();
  for (std::size_t i = 0; i < q.size(); ++i) {
    const bool any = placed.has(q[i].value);
    if (!any) {
      throw ModelError(coordinate_at_[i],
                       "coordinate '" + q[i].name +
                           "' moves nothing: no particle's position and no body's centre or "
                           "rotation depends on it, so it has no inertia");
    }
  }
}

}  // namespace unidyn::model_reading
