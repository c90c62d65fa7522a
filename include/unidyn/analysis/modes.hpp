// The modes of a linearisation ẋ = A x (analysis/linearization.hpp): eigenvalues λ, mode shapes
// in the named coordinates, frequencies and damping ratios, and the verdict on stability.
//
// A mode e^{λt} v: for λ = σ ± iω_d, the natural frequency ω_n = |λ|, the damped one ω_d, the
// damping ratio ζ = −σ/|λ| (0 undamped, 1 critical; negative where it grows). Its shape is v
// carried to every coordinate, the ignorable ones included (their motion δq̇ = a·v integrated:
// δq = a·v/λ), scaled so that its largest coordinate is 1.
//
// The verdict, with a tolerance of 1e-6 of the largest |λ| (at least 1e-6) for "on the imaginary
// axis" and "the same eigenvalue" (coarser than round-off: an eigenvalue of multiplicity 2 without
// two eigenvectors splits by the square root of the perturbation):
//   - unstable: an eigenvalue with Re λ > 0 (they are listed);
//   - asymptotically stable: every Re λ < 0;
//   - linearly stable: every Re λ ≤ 0, those on the imaginary axis semisimple (as many independent
//     eigenvectors as their multiplicity: bounded motion; whether the nonlinear terms keep it
//     bounded is another question), zero eigenvalues among them a neighbouring steady motion;
//   - inconclusive: an eigenvalue on the imaginary axis without enough eigenvectors (a Jordan
//     block: the linear motion grows like t, and the nonlinear terms decide).
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "unidyn/analysis/linearization.hpp"

namespace unidyn {

struct Mode {
  std::complex<double> eigenvalue;
  double natural_frequency = 0.0;  // |λ|, rad/s
  double damped_frequency = 0.0;   // |Im λ|, rad/s
  double damping_ratio = 0.0;      // −Re λ / |λ| (NaN for λ = 0)
  // δq of each coordinate (Linearization::coordinates), the largest of modulus 1; of a mode that
  // moves no coordinate (λ = 0 along a rate), δq̇ instead, and `of_rates`.
  std::vector<std::complex<double>> shape;
  bool of_rates = false;
};

enum class Stability { asymptotically_stable, linearly_stable, unstable, inconclusive };

struct ModeAnalysis {
  // One per eigenvalue: real ones, then one of each complex pair (Im λ > 0), each group by Re λ
  // from the largest down (equal ones, within the tolerance, by Im λ from the smallest).
  std::vector<Mode> modes;
  Stability verdict = Stability::inconclusive;
  std::string reason;
  // Below this |Re λ| an eigenvalue counts as on the imaginary axis.
  double tolerance = 0.0;
};

ModeAnalysis analyse_modes(const Linearization& linearization);

// "asymptotically stable", "linearly stable", "unstable", "inconclusive".
std::string to_string(Stability s);

// A mode's eigenvalue as text: "-0.38±3.87i" for a complex pair (one of each is listed), six
// significant digits, a real part within `tolerance` of 0 written 0.
std::string eigenvalue_text(const Mode& mode, double tolerance);

}  // namespace unidyn
