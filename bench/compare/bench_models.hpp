// The benchmark models of bench/MODELS.md for unidyn: the model text, and the conversions between
// unidyn's coordinates and the peers' state convention (quaternion and body angular velocity).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "pendulum_model.hpp"
#include "unidyn/model/system.hpp"
#include "unidyn/rotation/euler_angles.hpp"

namespace unidyn::bench {

// A benchmark model: its system, and for a body model the Euler set of its angles.
struct BenchModel {
  std::string name;
  System system;
  std::optional<EulerSet> euler;  // heavy-top (3-1-3), torque-free (3-2-1)
};

// pendulum-N (generated), heavy-top, torque-free, rolling-disk, kepler or bicycle (models/);
// `models` is the directory of the bundled model files. Throws std::invalid_argument for another
// name.
BenchModel bench_model(const std::string& name, const std::string& models);

// Peer state → unidyn (q, q̇): pendulums as they are; bodies from quaternion (w, x, y, z) and ω_b.
void from_peer_state(const BenchModel& model, const Eigen::VectorXd& peer, Eigen::VectorXd& q,
                     Eigen::VectorXd& qdot);
// unidyn (q, q̇) → peer state (quaternion with w ≥ 0).
Eigen::VectorXd to_peer_state(const BenchModel& model, const Eigen::VectorXd& q,
                              const Eigen::VectorXd& qdot);
// unidyn q̈ at (q, q̇) → the peer's accelerations: q̈ for pendulums, ω̇_b for bodies.
Eigen::VectorXd to_peer_acceleration(const BenchModel& model, const Eigen::VectorXd& q,
                                     const Eigen::VectorXd& qdot, const Eigen::VectorXd& qddot);

}  // namespace unidyn::bench
