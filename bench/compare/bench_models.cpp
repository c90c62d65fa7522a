// Benchmark models and state conversions (bench/MODELS.md).
#include "bench_models.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "unidyn/formats/mjcf.hpp"
#include "unidyn/formats/urdf.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/rotation/euler_parameters.hpp"

namespace unidyn::bench {
namespace {

// The Euler angles of a body model: its first three coordinates.
Vec3 angles_of(const Eigen::VectorXd& v) {
  return {v[0], v[1], v[2]};
}

// A bundled model's text without its outputs and conserved quantities: the equations alone, as
// SymPy, MuJoCo and Simbody are given them.
System equations_only(const std::string& path) {
  std::ifstream in(path);
  std::string text, line;
  bool skipping = false;
  while (std::getline(in, line)) {
    const bool top_level = !line.empty() && line[0] != ' ' && line[0] != '#' && line[0] != '-';
    if (top_level) skipping = line.starts_with("outputs:") || line.starts_with("conserved:");
    if (!skipping) text += line + "\n";
  }
  return parse_model(text, path);
}

}  // namespace

BenchModel bench_model(const std::string& name, const std::string& models) {
  // a robot file, imported as `unidyn` imports it: its (q, q̇) are the peer's state
  if (name.ends_with(".urdf")) {
    return {name, parse_model(formats::import_urdf_file(name).yaml, name), std::nullopt};
  }
  if (name.ends_with(".xml")) {
    return {name, parse_model(formats::import_mjcf_file(name).yaml, name), std::nullopt};
  }
  if (name.starts_with("pendulum-")) {
    const int links = std::stoi(name.substr(9));
    if (links < 1 || links > 50) throw std::invalid_argument("pendulum-N needs 1 <= N <= 50");
    return {name, parse_model(pendulum_text(links), name + ".yaml"), std::nullopt};
  }
  if (name == "heavy-top") {
    return {name, equations_only(models + "/heavy-top.yaml"), EulerSet::parse("3-1-3")};
  }
  if (name == "torque-free") {
    return {name, equations_only(models + "/torque-free-body.yaml"), EulerSet::parse("3-2-1")};
  }
  if (name == "rolling-disk") return {name, equations_only(models + "/rolling-disk.yaml"), {}};
  if (name == "kepler") return {name, equations_only(models + "/kepler.yaml"), {}};
  if (name == "bicycle") return {name, equations_only(models + "/bicycle.yaml"), {}};
  throw std::invalid_argument("unknown benchmark model " + name);
}

std::vector<std::size_t> euler_parameter_blocks(const BenchModel& model) {
  std::vector<std::size_t> blocks;
  for (const Body& body : model.system.bodies) {
    if (!body.joint) continue;
    const TreeJoint& joint = *body.joint;
    if (joint.kind == TreeJoint::Kind::ball || joint.kind == TreeJoint::Kind::floating) {
      blocks.push_back(joint.coordinates[joint.coordinates.size() - 4]);
    }
  }
  std::sort(blocks.begin(), blocks.end());
  return blocks;
}

namespace {

// ω_b = 2 G(e) ė of unit Euler parameters: 2 (e0 ε̇ − ė0 ε − ε × ε̇).
Eigen::Vector3d body_rate(const Eigen::Vector4d& e, const Eigen::Vector4d& rate) {
  return 2 * (e[0] * rate.tail<3>() - rate[0] * e.tail<3>() - e.tail<3>().cross(rate.tail<3>()));
}

// ė = ½ e ⊗ (0, ω_b): (−ε · ω / 2, (e0 ω + ε × ω) / 2).
Eigen::Vector4d parameter_rates(const Eigen::Vector4d& e, const Eigen::Vector3d& w) {
  Eigen::Vector4d rate;
  rate[0] = -0.5 * e.tail<3>().dot(w);
  rate.tail<3>() = 0.5 * (e[0] * w + e.tail<3>().cross(w));
  return rate;
}

// unidyn's n rates from the peer's velocities (ω_b for each block), or back (`to_peer`), with
// `map(e, from, to)` taking one block's 4 rates or 3 velocities.
template <class Block>
Eigen::VectorXd map_rates(const std::vector<std::size_t>& blocks, const Eigen::VectorXd& q,
                          const Eigen::VectorXd& from, Eigen::Index size, Block block) {
  Eigen::VectorXd out(size);
  Eigen::Index i = 0, j = 0;  // the positions in from and out
  const bool to_peer = size < from.size();
  for (Eigen::Index k = 0; k < q.size();) {
    if (std::find(blocks.begin(), blocks.end(), static_cast<std::size_t>(k)) == blocks.end()) {
      out[j++] = from[i++];
      ++k;
      continue;
    }
    block(Eigen::Vector4d(q.segment<4>(k)), from, i, out, j);
    i += to_peer ? 4 : 3;
    j += to_peer ? 3 : 4;
    k += 4;
  }
  return out;
}

}  // namespace

void from_peer_state(const BenchModel& model, const Eigen::VectorXd& peer, Eigen::VectorXd& q,
                     Eigen::VectorXd& qdot) {
  const auto n = static_cast<Eigen::Index>(model.system.coordinates().size());
  if (!model.euler) {
    const std::vector<std::size_t> blocks = euler_parameter_blocks(model);
    q = peer.head(n);
    const Eigen::VectorXd qvel = peer.tail(peer.size() - n);
    qdot = map_rates(blocks, q, qvel, n,
                     [](const Eigen::Vector4d& e, const Eigen::VectorXd& from, Eigen::Index i,
                        Eigen::VectorXd& out, Eigen::Index j) {
                       out.segment<4>(j) = parameter_rates(e, from.segment<3>(i));
                     });
    return;
  }
  // Q from the quaternion, the angles of Q, ω = Q ω_b, the angle rates of ω
  const Tensor Q = rotation_tensor(EulerParameters{peer[0], {peer[1], peer[2], peer[3]}});
  const Vec3 angles = euler_angles(*model.euler, Q).angles;
  const Vec3 rates = euler_angle_rates(*model.euler, angles, Q * peer.segment<3>(4));
  q = Eigen::VectorXd::Zero(n);
  qdot = Eigen::VectorXd::Zero(n);
  q.head<3>() = angles;
  qdot.head<3>() = rates;
}

Eigen::VectorXd to_peer_state(const BenchModel& model, const Eigen::VectorXd& q,
                              const Eigen::VectorXd& qdot) {
  if (!model.euler) {
    const std::vector<std::size_t> blocks = euler_parameter_blocks(model);
    const Eigen::VectorXd qvel =
        map_rates(blocks, q, qdot, q.size() - static_cast<Eigen::Index>(blocks.size()),
                  [](const Eigen::Vector4d& e, const Eigen::VectorXd& from, Eigen::Index i,
                     Eigen::VectorXd& out,
                     Eigen::Index j) { out.segment<3>(j) = body_rate(e, from.segment<4>(i)); });
    Eigen::VectorXd peer(q.size() + qvel.size());
    peer << q, qvel;
    return peer;
  }
  const Tensor Q = rotation_tensor(*model.euler, angles_of(q));
  const EulerParameters p = euler_parameters(Q);
  const Vec3 omega_b =
      Q.transpose() * angular_velocity(*model.euler, angles_of(q), angles_of(qdot));
  Eigen::VectorXd peer(7);
  peer << p.e0, p.e, omega_b;
  return peer;
}

Eigen::VectorXd to_peer_acceleration(const BenchModel& model, const Eigen::VectorXd& q,
                                     const Eigen::VectorXd& qdot, const Eigen::VectorXd& qddot) {
  // ω̇_b = 2 G(e) ë + 2 G(ė) ė, and G(ė) ė = 0
  if (!model.euler) {
    const std::vector<std::size_t> blocks = euler_parameter_blocks(model);
    return map_rates(blocks, q, qddot, q.size() - static_cast<Eigen::Index>(blocks.size()),
                     [](const Eigen::Vector4d& e, const Eigen::VectorXd& from, Eigen::Index i,
                        Eigen::VectorXd& out,
                        Eigen::Index j) { out.segment<3>(j) = body_rate(e, from.segment<4>(i)); });
  }
  // (6.21) differentiated: ω̇ = Σ γ̈ⁱ gᵢ + γ̇¹ γ̇² g1 × g2 + γ̇³ (γ̇¹ g1 + γ̇² g2) × g3, since g1 is
  // fixed, g2 turns at γ̇¹ g1 and g3 at γ̇¹ g1 + γ̇² g2; then ω̇_b = Qᵀ ω̇ (ω × ω = 0)
  const Vec3 angles = angles_of(q), rates = angles_of(qdot);
  const Tensor g = euler_basis(*model.euler, angles);
  const Vec3 g1 = g.col(0), g2 = g.col(1), g3 = g.col(2);
  const Vec3 omega_dot = g * angles_of(qddot) + rates[0] * rates[1] * g1.cross(g2) +
                         rates[2] * (rates[0] * g1 + rates[1] * g2).cross(g3);
  return rotation_tensor(*model.euler, angles).transpose() * omega_dot;
}

}  // namespace unidyn::bench
