// The report page's 3-D scene: bodies, particles, the motion's box.
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "page_data.hpp"
#include "unidyn/io/json_text.hpp"
#include "unidyn/report/constraint_surfaces.hpp"
#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

// A body's shape for the viewer: {"shape", "dimensions" (numbers), "color"}, or null.
std::string visual_json(const BodyVisual& visual, const GiNaC::exmap& values) {
  if (visual.shape.empty() && visual.color.empty()) return "null";
  std::vector<std::string> dimensions;
  for (const Expr& d : visual.dimensions) dimensions.push_back(json_number(real_value(d, values)));
  return "{\"shape\": " + unidyn::quoted(visual.shape) + ", \"dimensions\": [" +
         fmt::format("{}", fmt::join(dimensions, ", ")) +
         "], \"color\": " + unidyn::quoted(visual.color) + "}";
}

// [x, y, z].
std::string vector_json(const Eigen::Vector3d& v) {
  return "[" + page_number(v[0]) + ", " + page_number(v[1]) + ", " + page_number(v[2]) + "]";
}

// The planes and spheres the constraints hold points on (report/constraint_surfaces.hpp).
std::string surfaces_json(const ReportModel& model) {
  std::vector<std::string> out;
  for (const ConstraintSurface& s : constraint_surfaces(model.system, model.parameters)) {
    const bool plane = s.kind == ConstraintSurface::Kind::plane;
    out.push_back("{\"constraint\": " + unidyn::quoted(s.constraint) +
                  ", \"point\": " + unidyn::quoted(s.point) +
                  (plane ? ", \"kind\": \"plane\", \"normal\": " + vector_json(s.normal) +
                               ", \"offset\": " + page_number(s.offset)
                         : ", \"kind\": \"sphere\", \"center\": " + vector_json(s.center) +
                               ", \"radius\": " + page_number(s.radius)) +
                  "}");
  }
  return fmt::format("[{}]", fmt::join(out, ", "));
}

}  // namespace

// The 3-D scene: each body's shape (its `visual:` or inertia shape) and its ellipsoid of inertia
// (the uniform ellipsoid with its mass and principal moments: a² = 5 (B + C − A)/(2m) and
// cyclically, along its principal axes in the body basis) for a body without one, each particle's
// sphere, the box the motion stays in, and the constraints' planes and spheres.
// Past this the scene's grid and camera (4 extents across, in 32-bit floats) would overflow.
constexpr double kDrawableExtent = 1e30;

std::string scene_json(const ReportModel& model, const ReportRun& run) {
  const System& system = model.system;
  const GiNaC::exmap values = system.parameter_values(model.parameters);
  // the box the centres and particles stay in
  Eigen::Vector3d low = Eigen::Vector3d::Constant(INFINITY), high = -low;
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(run.columns.begin(), run.columns.end(), name) -
                                    run.columns.begin());
  };
  std::vector<std::string> moving;
  for (const Body& b : system.bodies) moving.push_back(b.name);
  for (const Particle& p : system.particles) moving.push_back(p.name);
  for (const std::string& name : moving) {
    const std::size_t x = column(name + ".x");
    if (x + 2 >= run.columns.size()) continue;
    for (const auto& row : run.rows) {
      const Eigen::Vector3d r(row[x], row[x + 1], row[x + 2]);
      // a position the page's 32-bit floats cannot draw (a run that flew off) leaves the box
      // drawable: the page shows where the motion stays within kDrawableExtent
      if (!r.allFinite() || r.cwiseAbs().maxCoeff() > kDrawableExtent) continue;
      low = low.cwiseMin(r);
      high = high.cwiseMax(r);
    }
  }
  if (!low.allFinite()) low = high = Eigen::Vector3d::Zero();
  std::vector<std::string> bodies;
  double largest = 0.0;
  for (const Body& b : system.bodies) {
    const double m = real_value(b.mass, values).value_or(0.0);
    Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
    for (unsigned i = 0; i < 3; ++i) {
      for (unsigned k = 0; k < 3; ++k) {
        J(i, k) = real_value(b.inertia(i, k), values).value_or(0.0);
      }
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(0.5 * (J + J.transpose()));
    const Eigen::Vector3d I = principal.eigenvalues();
    Eigen::Vector3d axes;
    for (int i = 0; i < 3; ++i) {
      const double square = m > 0 ? 5.0 * (I.sum() - 2 * I[i]) / (2 * m) : 0.0;
      axes[i] = std::sqrt(std::max(square, 0.0));
    }
    // no thinner than a twentieth of its largest axis (a thin disk's is 0)
    axes = axes.cwiseMax(0.05 * axes.maxCoeff());
    largest = std::max(largest, axes.maxCoeff());
    const Eigen::Matrix3d& V = principal.eigenvectors();
    bodies.push_back("{\"name\": " + unidyn::quoted(b.name) + ", \"semi_axes\": [" +
                     page_number(axes[0]) + ", " + page_number(axes[1]) + ", " +
                     page_number(axes[2]) + "], \"principal_axes\": [" +
                     fmt::format("[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]", page_number(V(0, 0)),
                                 page_number(V(0, 1)), page_number(V(0, 2)), page_number(V(1, 0)),
                                 page_number(V(1, 1)), page_number(V(1, 2)), page_number(V(2, 0)),
                                 page_number(V(2, 1)), page_number(V(2, 2))) +
                     "], \"visual\": " + visual_json(b.visual, values) + "}");
  }
  const Eigen::Vector3d center = 0.5 * (low + high);
  const double extent = std::max({0.5 * (high - low).norm(), 2 * largest, 1e-3});
  std::vector<std::string> particles;
  for (const Particle& p : system.particles) {
    particles.push_back("{\"name\": " + unidyn::quoted(p.name) +
                        ", \"radius\": " + page_number(0.04 * extent) + "}");
  }
  return fmt::format(
      "{{\"extent\": {}, \"center\": [{}, {}, {}], \"lowest\": {}, \"bodies\": [{}], "
      "\"particles\": [{}], \"forces\": {}, \"surfaces\": {}}}",
      page_number(extent), page_number(center[0]), page_number(center[1]), page_number(center[2]),
      page_number(low[2]), fmt::join(bodies, ", "), fmt::join(particles, ", "),
      json_names(run.force_owners), surfaces_json(model));
}

}  // namespace unidyn
