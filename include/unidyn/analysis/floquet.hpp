// Floquet analysis of a periodic motion: the stability of a driven system's rest state or
// periodic response (a pendulum on a vibrating pivot, Kapitza's inverted pendulum, parametric
// resonance; the Mathieu equation x'' + (a − 2q cos 2τ) x = 0).
//
// With equations of period T (analysis/time_dependence.hpp), the perturbations of the motion from
// the point, in the independent coordinates and speeds of analysis/linearization.hpp (constraints,
// velocity constraints and ignorable coordinates as there), obey
//
//   ẋ = F(t) x,   F(t + T) = F(t)            (the variational equations, F exact: the tapes'
//                                            forward-mode derivatives along the motion)
//   Φ̇ = F(t) Φ,  Φ(t0) = I,                 x(t0 + T) = Φ(t0 + T) x(t0),
//
// Φ(t0 + T) the monodromy matrix. Its eigenvalues μ are the Floquet multipliers: for each, a
// solution e^{ρ t} p(t), p of period T, with the exponent ρ = log(μ)/T (its imaginary part only up
// to multiples of 2π/T). The motion and Φ are integrated together over one period (DOP853, rtol
// 1e-12); the motion must come back to the point after it (a rest state the drive keeps, or a
// periodic response), else NotAnOperatingPoint.
//
// The verdict, with |μ| within 1e-6 of 1 counted on the unit circle (a Jordan block of size 2
// splits by the square root of the error in Φ):
//   - unstable: a multiplier with |μ| > 1 (a perturbation grows by |μ| each period);
//   - asymptotically stable: every |μ| < 1;
//   - linearly stable: every |μ| ≤ 1, those on the unit circle semisimple: the linear motion stays
//     bounded, and linear theory says no more (the nonlinear terms decide, as for an undamped
//     Mathieu equation between its transition curves);
//   - inconclusive: a multiplier on the unit circle without enough eigenvectors (on a transition
//     curve: the linear motion grows like t).
// The ignorable coordinates are those no other state depends on anywhere along the period; they
// are dropped as in the linearisation (their multipliers, 1, are structural).
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "unidyn/analysis/modes.hpp"
#include "unidyn/analysis/time_dependence.hpp"

namespace unidyn {

// |μ| this close to 1 is on the unit circle; multipliers this close are one.
constexpr double kFloquetOnCircle = 1e-6;

struct PeriodicLinearization {
  DrivePeriod period;
  double t0 = 0.0;
  // The reduction at t0 (state names, dependent and ignorable coordinates, maps), its A = F(t0)
  // over the kept states.
  Linearization at_start;
  // Φ(t0 + T) over the kept states, in the order of at_start.state.
  Eigen::MatrixXd monodromy;
  // How far the motion from the point is from it after one period (the kept states), and the
  // integrator's accepted steps.
  double return_gap = 0.0;
  std::size_t steps = 0;
};

// Throws NotAnOperatingPoint when the motion from the point does not come back to it after one
// period, std::runtime_error when the integration fails or the equations are singular on the way.
PeriodicLinearization linearize_periodic(const System& system, const CompiledSystem& compiled,
                                         const OperatingPoint& point, const DrivePeriod& period);

struct FloquetMultiplier {
  std::complex<double> multiplier;  // μ
  std::complex<double> exponent;    // ρ = log(μ)/T, principal
};

struct FloquetAnalysis {
  // By |μ| from the largest (equal ones, within the tolerance, by arg μ from the smallest); both
  // of a complex pair.
  std::vector<FloquetMultiplier> multipliers;
  Stability verdict = Stability::inconclusive;
  std::string reason;
  // |μ| within this of 1 is on the unit circle.
  double tolerance = 0.0;
};

FloquetAnalysis analyse_floquet(const PeriodicLinearization& linearization);

// The largest |μ| of a monodromy matrix (0 without states).
double largest_multiplier(const Eigen::MatrixXd& monodromy);

}  // namespace unidyn
