// Where each body and particle is along a run — the columns a viewer needs (`simulate --poses`,
// `unidyn report`): per body its centre x̄ and its orientation as Euler parameters e0, e1, e2, e3
// (§6.9, from Q by Shepperd's method, rotation/euler_parameters.hpp), per particle its position,
// all on the fixed basis E1, E2, E3. e and −e are one rotation: the first row has e0 ≥ 0 and each
// later one the sign nearer the row before, so that the columns are continuous.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "unidyn/model/system.hpp"
#include "unidyn/numeric/tape.hpp"
#include "unidyn/rotation/euler_parameters.hpp"

namespace unidyn {

class Poses {
 public:
  explicit Poses(const System& system);

  // "B.x", "B.y", "B.z", "B.e0", "B.e1", "B.e2", "B.e3" per body, then "P.x", "P.y", "P.z" per
  // particle.
  const std::vector<std::string>& columns() const { return columns_; }

  // The values of the columns at (t, q), appended to `row`.
  void append(double t, const Eigen::VectorXd& q, const std::vector<double>& parameters,
              std::vector<double>& row);

 private:
  std::vector<std::string> columns_;
  std::size_t bodies_ = 0, particles_ = 0, coordinates_ = 0;
  // inputs [t, q, q̇, p]; outputs per body x̄ (3) and Q row by row (9), per particle r (3)
  Tape tape_;
  TapeWorkspace workspace_;
  std::vector<double> inputs_, outputs_;
  std::vector<EulerParameters> previous_;
};

}  // namespace unidyn
