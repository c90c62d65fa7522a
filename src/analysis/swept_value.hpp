// One value of a sweep put in place: a parameter's (the others as given), or a value of the
// operating point's (in place of what --at said of it). Shared by the sweeps of modes
// (analysis/parameter_sweep.hpp) and of Floquet multipliers (analysis/floquet_sweep.hpp).
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "unidyn/analysis/operating_point.hpp"

namespace unidyn::detail {

inline void put_swept_value(const System& system, const std::string& name, double value,
                            std::vector<GivenValue>& given,
                            std::vector<std::pair<std::string, double>>& parameters) {
  if (system.find_parameter(name)) {
    parameters.emplace_back(name, value);
    return;
  }
  std::erase_if(given, [&](const GivenValue& g) { return g.name == name; });
  given.push_back({name, given_number(value)});
}

// Throws std::invalid_argument for a name that is not a parameter, coordinate or rate, or a count
// below 2.
inline void expect_sweepable(const System& system, const std::string& name, std::size_t count) {
  if (!system.find_parameter(name) && !state_value(system, name)) {
    throw std::invalid_argument("--sweep " + name +
                                ": not a parameter, coordinate or der(coordinate) of the model");
  }
  if (count < 2) throw std::invalid_argument("--sweep needs at least 2 values");
}

// The count values from `from` to `to`, the last exactly `to`.
inline double swept_value(double from, double to, std::size_t k, std::size_t count) {
  return k + 1 == count
             ? to
             : from + (to - from) * static_cast<double>(k) / static_cast<double>(count - 1);
}

}  // namespace unidyn::detail
