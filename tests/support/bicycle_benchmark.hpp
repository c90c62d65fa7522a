// The benchmark bicycle of Meijaard, Papadopoulos, Ruina & Schwab (2007), Proc. R. Soc. A 463:
// linearised about upright straight running at speed v, the roll φ and steer δ obey
//   M q̈ + v C1 q̇ + (g K0 + v² K2) q = 0,   q = (φ, δ),
// with the matrices of their (A1)–(A4), given there to 14 digits (g = 9.81, the rear wheel's
// radius 0.3 m), and the speeds of their Table 2 where the weave motion becomes stable and the
// capsize motion unstable.
#pragma once

#include <Eigen/Dense>

namespace unidyn::test {

constexpr double kBenchmarkGravity = 9.81, kBenchmarkRearRadius = 0.3;
constexpr double kWeaveSpeed = 4.29238253634111, kCapsizeSpeed = 6.02426201538837;

// (A1)–(A4)
inline const Eigen::Matrix2d kBenchmarkM{{80.81722, 2.31941332208709},
                                         {2.31941332208709, 0.29784188199686}};
inline const Eigen::Matrix2d kBenchmarkC1{{0, 33.86641391492494},
                                          {-0.85035641456978, 1.68540397397560}};
inline const Eigen::Matrix2d kBenchmarkK0{{-80.95, -2.59951685249872},
                                          {-2.59951685249872, -0.80329488458618}};
inline const Eigen::Matrix2d kBenchmarkK2{{0, 76.59734589573222}, {0, 2.65431523794604}};

// The benchmark's state matrix of (φ, δ, φ̇, δ̇) at speed v.
inline Eigen::Matrix4d benchmark_state_matrix(double v) {
  const Eigen::Matrix2d Minv = kBenchmarkM.inverse();
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  A.topRightCorner<2, 2>() = Eigen::Matrix2d::Identity();
  A.bottomLeftCorner<2, 2>() = -Minv * (kBenchmarkGravity * kBenchmarkK0 + v * v * kBenchmarkK2);
  A.bottomRightCorner<2, 2>() = -v * Minv * kBenchmarkC1;
  return A;
}

}  // namespace unidyn::test
