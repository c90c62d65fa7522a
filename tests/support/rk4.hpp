// The classical fourth-order Runge–Kutta method, for the oracles the tests integrate themselves:
// never unidyn's integrators. A State is anything indexed like a vector of doubles with size():
// std::array<double, N>, Eigen::VectorXd or a fixed-size Eigen vector; f(t, y) returns the rates
// of y as a State.
#pragma once

namespace unidyn::test {

// One step of h from (t, y): the rates k1..k4 and y + h/6 (k1 + 2 k2 + 2 k3 + k4).
template <class State, class Rates>
State rk4_step(const State& y, double t, double h, const Rates& f) {
  using Index = decltype(y.size());
  State x = y;  // where the next rates are taken, then the result
  const State k1 = f(t, y);
  for (Index j = 0; j < y.size(); ++j) x[j] = y[j] + h / 2 * k1[j];
  const State k2 = f(t + h / 2, x);
  for (Index j = 0; j < y.size(); ++j) x[j] = y[j] + h / 2 * k2[j];
  const State k3 = f(t + h / 2, x);
  for (Index j = 0; j < y.size(); ++j) x[j] = y[j] + h * k3[j];
  const State k4 = f(t + h, x);
  for (Index j = 0; j < y.size(); ++j) {
    x[j] = y[j] + h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  }
  return x;
}

// From t0 to t1 in `steps` equal steps (t1 < t0 integrates backwards).
template <class State, class Rates>
State rk4(State y, double t0, double t1, int steps, const Rates& f) {
  const double h = (t1 - t0) / steps;
  for (int i = 0; i < steps; ++i) y = rk4_step(y, t0 + i * h, h, f);
  return y;
}

}  // namespace unidyn::test
