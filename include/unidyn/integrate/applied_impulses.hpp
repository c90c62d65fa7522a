// The impulses a model applies at given times (model/system.hpp AppliedImpulse, book §9.8 and
// (11.13)–(11.15)): one event function each, t_k − t, reaching 0 at its time; there the rates jump
// by M Δq̇ = Φ̂ + Aᵀ ν with the constraints that hold keeping their rates (impulsive_jump.hpp) —
// a contact is not lifted by it, and a rough contact's friction takes no impulse (the book's cue
// strike); the rough contacts' phases are decided anew afterwards.
#pragma once

#include <Eigen/Dense>
#include <span>
#include <string>
#include <vector>

#include "unidyn/model/system.hpp"
#include "unidyn/numeric/compiled_system.hpp"
#include "unidyn/numeric/tape.hpp"

namespace unidyn {

class AppliedImpulses {
 public:
  // Throws std::invalid_argument for an impulse whose time is not after the start t0.
  AppliedImpulses(const System& system, const CompiledSystem& compiled,
                  std::span<const double> parameters, double t0);

  std::size_t event_count() const { return times_.size(); }
  // g_k = t_k − t until impulse k is applied, then 1 (it is applied once).
  void events(double t, std::span<double> g) const;

  // q̇ just after impulse k at (t, q), the constraints `active` (empty: all) keeping their rates;
  // returns the summary line. Throws std::runtime_error when the constraints are dependent.
  std::string apply(double t, const Eigen::VectorXd& q, Eigen::VectorXd& qdot, std::size_t k,
                    const std::vector<bool>& active);

 private:
  const System& system_;
  const CompiledSystem& compiled_;
  std::span<const double> parameters_;
  CompiledSystemData data_;
  // [t, q, q̇, p] → the generalised impulses Φ̂ of every impulse, n each (11.15)
  Tape tape_;
  TapeWorkspace workspace_;
  std::vector<double> times_;
  std::vector<bool> applied_;
};

}  // namespace unidyn
