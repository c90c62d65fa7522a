// Bodies' centres and Euler parameters, particles' positions, along a run.
#include "unidyn/numeric/poses.hpp"

#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {

Poses::Poses(const System& system)
    : bodies_(system.bodies.size()),
      particles_(system.particles.size()),
      coordinates_(system.coordinates().size()) {
  std::vector<GiNaC::ex> outputs;
  for (const Body& body : system.bodies) {
    for (const char* c : {"x", "y", "z", "e0", "e1", "e2", "e3"}) {
      columns_.push_back(body.name + "." + c);
    }
    for (int i = 0; i < 3; ++i) outputs.push_back(body.center[i]);
    for (unsigned i = 0; i < 3; ++i) {
      for (unsigned k = 0; k < 3; ++k) outputs.push_back(body.rotation(i, k));
    }
  }
  for (const Particle& particle : system.particles) {
    for (const char* c : {"x", "y", "z"}) columns_.push_back(particle.name + "." + c);
    for (int i = 0; i < 3; ++i) outputs.push_back(particle.position[i]);
  }
  tape_ = Tape::compile(outputs, tape_inputs(system, false));
  workspace_.reserve(tape_);
  inputs_.assign(tape_.input_count(), 0.0);
  outputs_.assign(tape_.output_count(), 0.0);
}

void Poses::append(double t, const Eigen::VectorXd& q, const std::vector<double>& parameters,
                   std::vector<double>& row) {
  // inputs [t, q, q̇ (not needed: 0), p]
  inputs_[0] = t;
  for (std::size_t i = 0; i < coordinates_; ++i) inputs_[1 + i] = q[static_cast<Eigen::Index>(i)];
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    inputs_[1 + 2 * coordinates_ + k] = parameters[k];
  }
  tape_.evaluate(inputs_, outputs_, workspace_);
  const bool first = previous_.empty();
  previous_.resize(bodies_);
  std::size_t at = 0;
  for (std::size_t b = 0; b < bodies_; ++b, at += 12) {
    for (std::size_t i = 0; i < 3; ++i) row.push_back(outputs_[at + i]);
    Tensor Q;
    for (Eigen::Index i = 0; i < 3; ++i) {
      for (Eigen::Index k = 0; k < 3; ++k) {
        Q(i, k) = outputs_[at + 3 + static_cast<std::size_t>(3 * i + k)];
      }
    }
    EulerParameters e = euler_parameters(Q);
    // the sign nearer the row before's (e0 ≥ 0 at the first row, as Shepperd's method gives)
    const EulerParameters& before = previous_[b];
    if (!first && e.e0 * before.e0 + e.e.dot(before.e) < 0) {
      e.e0 = -e.e0;
      e.e = -e.e;
    }
    previous_[b] = e;
    row.push_back(e.e0);
    for (Eigen::Index i = 0; i < 3; ++i) row.push_back(e.e[i]);
  }
  for (std::size_t p = 0; p < particles_; ++p, at += 3) {
    for (std::size_t i = 0; i < 3; ++i) row.push_back(outputs_[at + i]);
  }
}

}  // namespace unidyn
