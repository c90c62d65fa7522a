// Test problems of the integrate layer with their closed-form solutions, computed here
// independently of the code under test, and helpers to run a stepper and to measure convergence
// orders.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <vector>

#include "unidyn/integrate/ode.hpp"
#include "unidyn/integrate/stepper.hpp"

namespace unidyn::test {

// y' = −y: y = y0 e^(−t).
inline void decay(double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
  dydt = -y;
}

// y' = y cos t: y = y0 e^(sin t); non-autonomous, so the stage times are exercised.
inline void cosine_growth(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
  dydt = std::cos(t) * y;
}
inline double cosine_growth_exact(double t) {
  return std::exp(std::sin(t));
}

// x'' = −ω² x as (x, v) from (1, 0): x = cos ωt, v = −ω sin ωt.
inline OdeFunction oscillator(double omega) {
  return [omega](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    dydt[0] = y[1];
    dydt[1] = -omega * omega * y[0];
  };
}
inline Eigen::Vector2d oscillator_exact(double omega, double t) {
  return {std::cos(omega * t), -omega * std::sin(omega * t)};
}

// The Kepler problem r'' = −μ r/|r|³ with μ = 1, semi-major axis a = 1 and eccentricity e, state
// (x, y, vx, vy), starting at periapsis. Period 2π sqrt(a³/μ), energy −μ/(2a), angular momentum
// sqrt(μ a (1 − e²)).
struct Kepler {
  double e = 0.5;

  static constexpr double kPeriod = 2.0 * std::numbers::pi;

  static void rhs(double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    const double r = std::hypot(y[0], y[1]);
    const double r3 = r * r * r;
    dydt << y[2], y[3], -y[0] / r3, -y[1] / r3;
  }

  double energy() const { return -0.5; }
  double angular_momentum() const { return std::sqrt(1.0 - e * e); }

  static double energy_of(const Eigen::VectorXd& y) {
    return 0.5 * (y[2] * y[2] + y[3] * y[3]) - 1.0 / std::hypot(y[0], y[1]);
  }
  static double angular_momentum_of(const Eigen::VectorXd& y) { return y[0] * y[3] - y[1] * y[2]; }

  // The state at time t from Kepler's equation E − e sin E = t (mean motion 1), solved by Newton.
  Eigen::VectorXd exact(double t) const {
    double E = t;
    for (int i = 0; i < 50; ++i) {
      const double correction = (E - e * std::sin(E) - t) / (1.0 - e * std::cos(E));
      E -= correction;
      if (std::abs(correction) < 1e-15) break;
    }
    const double b = std::sqrt(1.0 - e * e);
    const double E_rate = 1.0 / (1.0 - e * std::cos(E));
    Eigen::VectorXd y(4);
    y << std::cos(E) - e, b * std::sin(E), -std::sin(E) * E_rate, b * std::cos(E) * E_rate;
    return y;
  }
};

// Options of an adaptive stepper (DormandPrinceOptions, CvodeOptions) with the given tolerances.
template <class Options>
Options tolerances(double rtol, double atol) {
  Options options;
  options.rtol = rtol;
  options.atol = atol;
  return options;
}

// Step from (t0, y0) to t_end; returns the state there.
inline Eigen::VectorXd solve(Stepper& stepper, double t0, const Eigen::VectorXd& y0, double t_end) {
  stepper.initialize(t0, y0);
  while (stepper.t() != t_end) stepper.step(t_end);
  return stepper.y();
}

// Observed orders log2(e_k / e_{k+1}) of errors measured with the step halved each time.
inline std::vector<double> observed_orders(const std::vector<double>& errors) {
  std::vector<double> orders;
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    orders.push_back(std::log2(errors[i] / errors[i + 1]));
  }
  return orders;
}

inline Eigen::VectorXd vector(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double value : values) v[i++] = value;
  return v;
}

// The largest error of the dense output at θ = 0.21, 0.5, 0.83 inside every step of y' = y cos t
// from y(0) = 1 to t = 5 (stepper not yet initialised).
inline double cosine_growth_dense_error(Stepper& stepper) {
  stepper.initialize(0.0, vector({1.0}));
  double error = 0.0;
  while (stepper.t() != 5.0) {
    stepper.step(5.0);
    for (double theta : {0.21, 0.5, 0.83}) {
      const double t = stepper.t_previous() + theta * (stepper.t() - stepper.t_previous());
      error = std::max(error, std::abs(stepper.dense(t)[0] - cosine_growth_exact(t)));
    }
  }
  return error;
}

}  // namespace unidyn::test
