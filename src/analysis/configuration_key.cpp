// One configuration, whatever coordinates describe it: poses and potential energy compared.
#include "configuration_key.hpp"

#include <algorithm>
#include <cmath>

namespace unidyn {

ConfigurationKey::ConfigurationKey(const System& system, const CompiledSystem& compiled)
    : compiled_(compiled),
      bodies_(system.bodies.size()),
      poses_(system),
      data_(compiled.make_data()) {}

std::vector<double> ConfigurationKey::at(const OperatingPoint& point) {
  std::vector<double> key;
  poses_.append(point.t, point.q, point.parameters, key);
  // U: observed[1] (T, U, then the outputs); the rates, q̈ and λ do not enter it
  std::vector<double> observed(compiled_.observation_count());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(point.q.size());
  const Eigen::VectorXd no_multipliers =
      Eigen::VectorXd::Zero(static_cast<Eigen::Index>(compiled_.constraint_count()));
  compiled_.observe(point.t, point.q, rest, rest, no_multipliers, point.parameters, observed,
                    data_);
  key.push_back(observed[1]);
  return key;
}

bool ConfigurationKey::same(const std::vector<double>& a, const std::vector<double>& b) const {
  const auto close = [](double x, double y) {
    return std::abs(x - y) <= 1e-6 * (1.0 + std::abs(x));
  };
  std::size_t at = 0;
  // per body x̄ (3) and e (4): e or −e
  for (std::size_t body = 0; body < bodies_; ++body, at += 7) {
    for (std::size_t i = 0; i < 3; ++i) {
      if (!close(a[at + i], b[at + i])) return false;
    }
    bool plus = true, minus = true;
    for (std::size_t i = 3; i < 7; ++i) {
      plus = plus && close(a[at + i], b[at + i]);
      minus = minus && close(a[at + i], -b[at + i]);
    }
    if (!plus && !minus) return false;
  }
  // the particles' positions and U
  for (; at < a.size(); ++at) {
    if (!close(a[at], b[at])) return false;
  }
  return true;
}

}  // namespace unidyn
