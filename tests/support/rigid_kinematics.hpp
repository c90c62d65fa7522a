// A rigid body's basis and angular velocity, computed by the tests themselves from a row's Euler
// parameters (e0, e1, e2, e3) and their rates: never unidyn's kinematics.
#pragma once

#include <array>
#include <cstddef>

#include "support/model_run.hpp"

namespace unidyn::test {

// Components on E1, E2, E3: basis[i] = e_i = Q E_i, and ω.
struct EulerParameterKinematics {
  std::array<std::array<double, 3>, 3> basis;
  std::array<double, 3> omega;
};

// From the Euler parameters (e0, e) and their rates (ė0, ė): e_i = Q E_i with
// Q a = (e0² − e·e) a + 2 (e·a) e + 2 e0 e × a, and ω = 2 (e0 ė − ė0 e + e × ė).
inline EulerParameterKinematics euler_parameter_kinematics(double e0,
                                                           const std::array<double, 3>& e,
                                                           double e0dot,
                                                           const std::array<double, 3>& edot) {
  using V = std::array<double, 3>;
  const auto dot = [](const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const auto cross = [](const V& a, const V& b) {
    return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  EulerParameterKinematics r;
  for (std::size_t i = 0; i < 3; ++i) {
    V E{0, 0, 0};
    E[i] = 1;
    const V ea = cross(e, E);
    for (std::size_t j = 0; j < 3; ++j) {
      r.basis[i][j] = (e0 * e0 - dot(e, e)) * E[j] + 2 * dot(e, E) * e[j] + 2 * e0 * ea[j];
    }
  }
  const V c = cross(e, edot);
  for (std::size_t j = 0; j < 3; ++j) r.omega[j] = 2 * (e0 * edot[j] - e0dot * e[j] + c[j]);
  return r;
}

// The same from row k of a run whose coordinates include e0, e1, e2, e3.
inline EulerParameterKinematics euler_parameter_kinematics(const ModelRun& run, std::size_t k) {
  return euler_parameter_kinematics(
      run.at(k, "e0"), {run.at(k, "e1"), run.at(k, "e2"), run.at(k, "e3")}, run.at(k, "der(e0)"),
      {run.at(k, "der(e1)"), run.at(k, "der(e2)"), run.at(k, "der(e3)")});
}

}  // namespace unidyn::test
