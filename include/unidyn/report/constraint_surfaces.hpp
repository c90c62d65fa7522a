// The surfaces the position constraints hold points on, where they are planes or spheres — for the
// report's 3-D scene. A constraint Ψ(q) = 0 holds a point P (a particle, or the contact point
// `at` of a body's friction) on the plane n · r = d when Ψ = a + b · r_P(q) identically, and on
// the sphere |r − c| = R when Ψ = a + b · r_P(q) + k |r_P(q)|² with k ≠ 0 (then c = −b/(2k),
// R² = |c|² − a/k). Whether Ψ has that form is decided numerically, as an identity: the fit of
// a, b (and k) to Ψ at 16 random configurations must leave no residual beyond round-off, and the
// positions there must span space (a point that never leaves a plane of its own fits many
// surfaces, and none is drawn). Constraints that change with time (a turning cone) are left out:
// the scene is drawn once.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

struct ConstraintSurface {
  enum class Kind { plane, sphere };
  std::string constraint;  // its name
  std::string point;       // the particle's or the body's name
  Kind kind = Kind::plane;
  // plane: the unit normal n (its first non-zero component positive) and d = n · r on it;
  // sphere: its centre and radius
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double offset = 0.0;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

// The planes and spheres of the system's position constraints at the parameters' values (one per
// constraint at most, in the constraints' order).
std::vector<ConstraintSurface> constraint_surfaces(const System& system,
                                                   const std::vector<double>& parameters);

}  // namespace unidyn
