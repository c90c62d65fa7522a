// How the equations of motion depend on t, and their period when they are periodic: a system
// with a moving support (§2.7: a pendulum on a vibrating pivot, a bead on a hoop turning at a
// varying rate) is rheonomic, and its rest states are not equilibria of frozen equations but
// periodic motions, whose stability is Floquet's (analysis/floquet.hpp).
//
// The equations depend on t when some entry of M, f, A, b or e has a derivative along t that is not
// identically zero (symbolic/zero_test.hpp: a hoop turning at a constant rate Ω has Ω t in its
// positions, and equations that do not change with t). Ψ's own t enters the motion through
// e = ∂Ψ/∂t: a coordinate turned at a constant rate, Ψ = φ − Ωt, leaves the equations as they are.
// They are periodic when every t is inside sin, cos or tan of ω t + c, ω a number or an expression
// in the parameters: with the frequencies ω_k at the parameters' values commensurate (each ratio
// ω_k/ω_1 a fraction p/q, q ≤ 1000, to 1e-12), the period is T = 2π/ω₀, ω₀ = |ω_1| gcd(n_k)/L for
// ω_k = |ω_1| n_k/L. A period the user gives (`--period T`) is taken instead, once the compiled
// equations are seen to repeat after it: the same at t and t + T, at random states and instants.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {

struct TimeDependence {
  // Whether the equations change with t.
  bool depends = false;
  // Each trigonometric function of ω t + c in them: its ω and its text ("cos(Omega*t)").
  struct Frequency {
    Expr omega;
    std::string source;
  };
  std::vector<Frequency> frequencies;
  // Where t appears otherwise, when it does: the term and the equation ("l0+v*t, in the equation
  // of phi"); empty when the dependence is periodic.
  std::string not_periodic;
};

// How the equations `eq` of `system` depend on t.
TimeDependence time_dependence(const System& system, const EquationsOfMotion& eq);

// Whether the compiled equations (M, f, A, b, e) change with t at the parameters' values, by
// evaluating them at random states at three instants: no symbols needed, for the layers that have
// only the compiled system (analysis/equilibria.hpp). A nonzero difference proves dependence; equal
// values at random irrational instants make it improbable.
bool changes_with_t(const CompiledSystem& compiled, const std::vector<double>& parameters);

// The period of a periodic dependence at the parameters' values, and how it was found.
struct DrivePeriod {
  double period = 0.0;
  std::string how;
  bool given = false;  // by the user (--period), not found in the equations
};

// The period of the equations at `parameters`: `given` (checked on the compiled equations), or
// the one their frequencies have. Nothing when every frequency is 0 there (the drive stands
// still: the equations do not change with t at these values). Throws NotPeriodic when the
// dependence is not periodic, the frequencies are not commensurate, or the equations do not
// repeat after the period given.
class NotPeriodic : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};
std::optional<DrivePeriod> drive_period(const System& system, const CompiledSystem& compiled,
                                        const TimeDependence& dependence,
                                        const std::vector<double>& parameters,
                                        std::optional<double> given = std::nullopt);

}  // namespace unidyn
