// Floquet multipliers along a parameter (`unidyn modes --sweep` of a driven system): at each value
// the period (analysis/time_dependence.hpp: it changes with a swept frequency), the operating
// point completed anew and its monodromy matrix (analysis/floquet.hpp). Where the largest |μ|
// crosses 1 between two values (beyond the unit circle's tolerance, 1e-6), the value where it does
// is found by bisection to 1e-12 (relative), on the function that changes sign there smoothly:
// det(Φ − I) where a real multiplier passes through +1 (the Mathieu equation's a0, b2, a2, …
// curves), det(Φ + I) where one passes through −1 (b1, a1, …: parametric resonance), else the
// largest |μ| − 1 (a complex pair leaving the circle).
#pragma once

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "unidyn/analysis/floquet.hpp"
#include "unidyn/analysis/parameter_sweep.hpp"

namespace unidyn {

struct FloquetSweepPoint {
  double value = 0.0;
  double period = 0.0;
  // The multipliers, by |μ| from the largest; empty where it failed.
  std::vector<std::complex<double>> multipliers;
  // The largest log|μ|/T (the largest real part of the exponents); NaN on failure.
  double growth = 0.0;
  bool growing = false;  // the largest |μ| is beyond 1 + 1e-6
  std::string failure;   // why there are no multipliers there
};

struct FloquetSweep {
  std::string parameter;
  std::vector<FloquetSweepPoint> points;
  std::vector<StabilityBoundary> boundaries;
};

// As sweep_modes (analysis/parameter_sweep.hpp), for equations that depend on t as `dependence`
// says; `period` the one given (--period), else found at each value.
FloquetSweep sweep_floquet(const System& system, const CompiledSystem& compiled,
                           const TimeDependence& dependence, const std::vector<GivenValue>& given,
                           const std::vector<std::pair<std::string, double>>& parameters,
                           const std::string& name, double from, double to, std::size_t count,
                           std::optional<double> period = std::nullopt);

}  // namespace unidyn
