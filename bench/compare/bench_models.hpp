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

// The first coordinate (e0) of each ball or floating joint's Euler parameters, in order: a robot
// file's peer state is (qpos, qvel) with 3 velocities for each 4 such coordinates (ω on the body's
// frame, as MuJoCo's).
std::vector<std::size_t> euler_parameter_blocks(const BenchModel& model);

// Peer state → unidyn (q, q̇): pendulums as they are; bodies from quaternion (w, x, y, z) and ω_b;
// a robot file's (qpos, qvel) with ė = ½ e ⊗ (0, ω_b) of each Euler-parameter block.
void from_peer_state(const BenchModel& model, const Eigen::VectorXd& peer, Eigen::VectorXd& q,
                     Eigen::VectorXd& qdot);
// unidyn (q, q̇) → peer state (quaternion with w ≥ 0).
Eigen::VectorXd to_peer_state(const BenchModel& model, const Eigen::VectorXd& q,
                              const Eigen::VectorXd& qdot);
// unidyn q̈ at (q, q̇) → the peer's accelerations: q̈ for pendulums, ω̇_b for bodies (and for each
// Euler-parameter block of a robot file, ω̇_b = 2 G(e) ë).
Eigen::VectorXd to_peer_acceleration(const BenchModel& model, const Eigen::VectorXd& q,
                                     const Eigen::VectorXd& qdot, const Eigen::VectorXd& qddot);

}  // namespace unidyn::bench
