// Eigenvalues along a parameter or a value of the operating point (`unidyn modes --sweep`: the
// bicycle's speed v, a top's spin der(phi)): at each value the operating point is completed anew
// (its given values may be expressions in the parameter: der(thR)=v/rR), linearised
// and its eigenvalues found; where the growth — the largest real part of the eigenvalues but the
// zero ones of neighbouring steady motions (as many as A's singular values below 1e-12 of the
// largest) — turns positive or stops being so between two values (beyond round-off: 1e-13 of the
// largest |λ|), the value where it does is found by bisection to 1e-12 (relative): the speeds where
// a bicycle's weave becomes stable and its capsize unstable, the spin that keeps a disk upright.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "unidyn/analysis/linearization.hpp"

namespace unidyn {

struct SweepPoint {
  double value = 0.0;
  // All eigenvalues, by real part from the largest, then imaginary part; empty where it failed.
  std::vector<std::complex<double>> eigenvalues;
  // The largest real part but for the zero eigenvalues (−∞ when all are zero); NaN on failure.
  double growth = 0.0;
  std::size_t zeros = 0;  // the zero eigenvalues left out
  // The growth is above round-off (1e-13 of the largest |λ|, at least of 1).
  bool growing = false;
  std::string failure;  // why there is no linearisation there (not an operating point, ...)
};

struct StabilityBoundary {
  double value = 0.0;
  bool becomes_stable = false;  // the largest growth goes from positive to negative
};

struct ParameterSweep {
  std::string parameter;
  std::vector<SweepPoint> points;
  std::vector<StabilityBoundary> boundaries;
};

// `count` ≥ 2 values from `from` to `to` of `name`: a parameter (the others as in `parameters`, the
// parameters defined by expressions computed anew), or a coordinate or der(coordinate), given at
// each value in place of what `given` says of it. Throws std::invalid_argument for an unknown name
// or a count below 2.
ParameterSweep sweep_modes(const System& system, const CompiledSystem& compiled,
                           const std::vector<GivenValue>& given,
                           const std::vector<std::pair<std::string, double>>& parameters,
                           const std::string& name, double from, double to, std::size_t count);

}  // namespace unidyn
