// Whether two states at rest are one configuration of the system, whatever coordinates describe
// it: every particle at the same place, every body's centre and rotation the same (Euler
// parameters e and −e are one rotation, §6.9), and the same potential energy (a torsion spring
// wound a turn further is another state). Two sets of Euler angles describe almost every attitude
// — (ψ, θ, φ) and (ψ + π, π − θ, φ + π) for 3-2-1, (φ + π, −θ, ψ + π) for 3-1-3 (§6.5) — so an
// equilibrium found in both is one equilibrium.
#pragma once

#include <vector>

#include "unidyn/analysis/operating_point.hpp"
#include "unidyn/model/system.hpp"
#include "unidyn/numeric/compiled_system.hpp"
#include "unidyn/numeric/poses.hpp"

namespace unidyn {

class ConfigurationKey {
 public:
  ConfigurationKey(const System& system, const CompiledSystem& compiled);

  // The poses at the point (per body x̄ and e, per particle r), then U.
  std::vector<double> at(const OperatingPoint& point);

  // Whether two keys are one configuration (to 1e-6 relative).
  bool same(const std::vector<double>& a, const std::vector<double>& b) const;

 private:
  const CompiledSystem& compiled_;
  std::size_t bodies_;
  Poses poses_;
  CompiledSystemData data_;
};

}  // namespace unidyn
