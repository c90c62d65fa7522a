// The rattleback (celt), named in book §9.9: models/rattleback.yaml, an ellipsoidal body whose
// principal axes of inertia are turned by δ from its shape's, rolling without slip. Spun about the
// vertical it rocks, stops and spins the other way — with E conserved (rolling does no work); with
// δ = 0 it keeps its spin; and δ → −δ mirrors the motion (ω3 → −ω3 from the mirrored start).
// models/rattleback-kane-levinson.yaml, Kane and Levinson's published rattleback (1982), against
// the rolling equations written by hand below: its motion by RK4, its rocking modes' growth rates
// (the time scale of the reversal) and, with a resisting moment, its one preferred sense.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "support/linearized_model.hpp"
#include "support/model_run.hpp"

namespace unidyn {
namespace {

test::ModelRun spin(double rate, double delta, double t_end) {
  return test::run_model(
      "rattleback", {{"spin", rate}, {"delta", delta}},
      [&](SimulationOptions& o) { o.t_end = t_end; }, true);
}

TEST(Rattleback, SpinReversesOnlyWithMisalignedAxes) {
  const test::ModelRun turned = spin(5, 0.05, 6.5);
  ASSERT_TRUE(turned.summary.ok) << turned.summary.message;
  EXPECT_LT(turned.summary.energy_relative_drift, 1e-8);
  const std::vector<double> w3 = turned.column("w3");
  EXPECT_NEAR(w3.front(), 5, 1e-12);
  EXPECT_LT(*std::min_element(w3.begin(), w3.end()), -4) << "spins the other way";
  const test::ModelRun aligned = spin(5, 0, 4);
  ASSERT_TRUE(aligned.summary.ok) << aligned.summary.message;
  for (const double w : aligned.column("w3")) EXPECT_NEAR(w, 5, 1e-3);
  const test::ModelRun mirrored = spin(-5, -0.05, 6.5);
  ASSERT_TRUE(mirrored.summary.ok) << mirrored.summary.message;
  ASSERT_EQ(mirrored.rows.size(), turned.rows.size());
  for (std::size_t i = 0; i < turned.rows.size(); ++i) {
    EXPECT_NEAR(mirrored.at(i, "w3"), -turned.at(i, "w3"), 1e-6) << turned.at(i, "t");
  }
}

// Kane and Levinson's rattleback (models/rattleback-kane-levinson.yaml, their published numbers) by
// hand, in the body's basis (e3 up): the state is ω and γ = E3 on e1, e2, e3. The contact point
// from the centre of mass is r(γ) = h e3 − Bγ/√(γ·Bγ), B = diag(a², b², c²) (the ellipsoid's lowest
// point); rolling makes v̄ = r × ω, and with the contact force F = m (dv̄/dt + g γ) (dv̄/dt the
// inertial acceleration) Euler's law J ω̇ + ω × Jω = r × F − σ ω gives
//   (J − m [r]×[r]×) ω̇ = −ω × Jω + m r × (ṙ × ω + ω × (r × ω) + g γ) − σ ω,
//   γ̇ = γ × ω,  ṙ = ∂r/∂γ γ̇ = −(B/s − Bγ (Bγ)ᵀ/s³) γ̇,  s = √(γ·Bγ),
// with σ ω a resisting moment (the air resistance of Kane and Levinson's model); its energy
// E = ½ ω·Jω + ½ m |r × ω|² − m g γ·r is conserved when σ = 0.
using CeltState = Eigen::Matrix<double, 6, 1>;

struct Celt {
  double m, g, h, sigma;
  Eigen::Matrix3d J, B;

  static Celt of(const test::ModelRun& run, double sigma) {
    Celt celt{run.parameter("m"), run.parameter("g"), run.parameter("h"), sigma, {}, {}};
    const double D = run.parameter("D");
    celt.J << run.parameter("A"), D, 0, D, run.parameter("B"), 0, 0, 0, run.parameter("C");
    celt.B = Eigen::Vector3d(std::pow(run.parameter("a"), 2), std::pow(run.parameter("b"), 2),
                             std::pow(run.parameter("c"), 2))
                 .asDiagonal();
    return celt;
  }
  Eigen::Vector3d contact(const Eigen::Vector3d& up) const {
    return Eigen::Vector3d(0, 0, h) - B * up / std::sqrt(up.dot(B * up));
  }
  CeltState rates(const CeltState& x) const {
    const Eigen::Vector3d w = x.head<3>(), up = x.tail<3>();
    const double s = std::sqrt(up.dot(B * up));
    const Eigen::Vector3d r = contact(up), up_rate = up.cross(w);
    const Eigen::Vector3d Bu = B * up;
    const Eigen::Vector3d r_rate = -(B / s - Bu * Bu.transpose() / (s * s * s)) * up_rate;
    Eigen::Matrix3d rx;
    rx << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
    const Eigen::Vector3d moment =
        -w.cross(J * w) + m * r.cross(r_rate.cross(w) + w.cross(r.cross(w)) + g * up) - sigma * w;
    CeltState out;
    out << (J - m * rx * rx).lu().solve(moment), up_rate;
    return out;
  }
  double energy(const CeltState& x) const {
    const Eigen::Vector3d w = x.head<3>(), up = x.tail<3>(), r = contact(up);
    return 0.5 * w.dot(J * w) + 0.5 * m * r.cross(w).squaredNorm() - m * g * up.dot(r);
  }
  // Classical RK4 over dt in n steps.
  CeltState rk4(CeltState x, double dt, int n) const {
    const double k = dt / n;
    for (int i = 0; i < n; ++i) {
      const CeltState k1 = rates(x), k2 = rates(x + k / 2 * k1), k3 = rates(x + k / 2 * k2),
                      k4 = rates(x + k * k3);
      x += k / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return x;
  }
  // The eigenvalues of the rates' Jacobian (central differences) at the steady spin ω = s E3, γ =
  // e3 whose real part is not zero: the two rocking modes (pitch about e2, roll about e1), sorted
  // by frequency.
  std::vector<std::complex<double>> rocking_modes(double s) const {
    CeltState x0;
    x0 << 0, 0, s, 0, 0, 1;
    Eigen::Matrix<double, 6, 6> jacobian;
    const double d = 1e-6;
    for (int k = 0; k < 6; ++k) {
      const CeltState e = CeltState::Unit(k) * d;
      jacobian.col(k) = (rates(x0 + e) - rates(x0 - e)) / (2 * d);
    }
    std::vector<std::complex<double>> modes;
    for (const auto& lambda : test::eigenvalues(jacobian)) {
      if (std::abs(lambda) > 1) modes.push_back(lambda);
    }
    std::sort(modes.begin(), modes.end(), [](auto p, auto q) {
      return p.imag() != q.imag() ? p.imag() < q.imag() : p.real() < q.real();
    });
    return modes;
  }
};

// The row's ω and γ (the model's outputs omega_body, up: ω and E3 on the body's basis).
CeltState celt_state(const test::ModelRun& run, std::size_t i) {
  CeltState x;
  x << run.at(i, "omega_body.x"), run.at(i, "omega_body.y"), run.at(i, "omega_body.z"),
      run.at(i, "up.x"), run.at(i, "up.y"), run.at(i, "up.z");
  return x;
}

// Kane and Levinson's start: tilted by φ = tilt about e1 and θ = −tilt about e2 (3-1-2 angles, so
// γ = (−cos φ sin θ, sin φ, cos φ cos θ)), spinning at `spin` about E3 (ω = spin γ).
CeltState celt_start(double spin, double tilt) {
  const double phi = tilt, theta = -tilt;
  CeltState x;
  const Eigen::Vector3d up(-std::cos(phi) * std::sin(theta), std::sin(phi),
                           std::cos(phi) * std::cos(theta));
  x << spin * up, up;
  return x;
}

// The first time the spin about the vertical, ω·γ, changes sign (linear interpolation between
// rows), or −1.
double first_reversal(const std::vector<double>& t, const std::vector<double>& spin) {
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (spin[i] * spin[0] <= 0) {
      return t[i - 1] + (t[i] - t[i - 1]) * spin[i - 1] / (spin[i - 1] - spin[i]);
    }
  }
  return -1;
}

struct CeltComparison {
  double omega_error = 0, up_error = 0, reversal_run = -1, reversal_rk4 = -1;
};

// The run against the hand equations by RK4 (400 steps per 0.01 s row) from Kane and Levinson's
// start.
CeltComparison compare_with_rk4(const test::ModelRun& run, const Celt& celt, double spin) {
  CeltComparison out;
  CeltState x = celt_start(spin, run.parameter("tilt"));
  std::vector<double> t, w_run, w_rk4;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    if (i > 0) x = celt.rk4(x, run.at(i, "t") - run.at(i - 1, "t"), 400);
    const CeltState y = celt_state(run, i);
    out.omega_error = std::max(out.omega_error, (y.head<3>() - x.head<3>()).norm());
    out.up_error = std::max(out.up_error, (y.tail<3>() - x.tail<3>()).norm());
    t.push_back(run.at(i, "t"));
    w_run.push_back(run.at(i, "w3"));
    w_rk4.push_back(x.head<3>().dot(x.tail<3>()));
  }
  out.reversal_run = first_reversal(t, w_run);
  out.reversal_rk4 = first_reversal(t, w_rk4);
  return out;
}

// Kane and Levinson's rattleback without dissipation, from their start (tilted 0.5° about each
// horizontal axis, spinning at 5 rad/s): ω and γ of the run against the hand equations above by
// RK4, through the first reversal, and E conserved by both. Spun counterclockwise (seen from above)
// it reverses within 3 s; clockwise it keeps its sense four times longer (then reverses too: each
// sense has a growing rocking mode, `Rattleback.KaneLevinsonGrowthRatesAgainstHandLinearisation`).
TEST(Rattleback, KaneLevinsonRunAgainstRollingEquationsByRk4) {
  for (const auto& [spin, t_end] : {std::pair{5.0, 5.0}, std::pair{-5.0, 14.0}}) {
    const test::ModelRun run = test::run_model(
        "rattleback-kane-levinson", {{"spin", spin}},
        [&](SimulationOptions& o) {
          o.t_end = t_end;
          o.rtol = 1e-12;
        },
        true);
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    const Celt celt = Celt::of(run, 0);
    EXPECT_NEAR(run.at(0, "energy"), celt.energy(celt_start(spin, run.parameter("tilt"))), 1e-12);
    EXPECT_LT(run.summary.energy_relative_drift, 1e-8);
    const CeltComparison c = compare_with_rk4(run, celt, spin);
    std::printf(
        "spin %+g: |omega - rk4| %.2e rad/s, |gamma - rk4| %.2e, first reversal at %.6f s "
        "(rk4 %.6f s)\n",
        spin, c.omega_error, c.up_error, c.reversal_run, c.reversal_rk4);
    // the run's rtol 1e-12 over up to 14 s of growing rocking (RK4's own error is below 1e-9)
    EXPECT_LT(c.omega_error, 5e-7);
    EXPECT_LT(c.up_error, 1e-8);
    EXPECT_NEAR(c.reversal_run, c.reversal_rk4, 1e-7);
    if (spin > 0) {
      EXPECT_GT(c.reversal_run, 2);
      EXPECT_LT(c.reversal_run, 3);
    } else {
      EXPECT_GT(c.reversal_run, 11);
    }
  }
}

// The time scale: unidyn's linearisation about the steady spin ψ̇ = s (analysis/linearization.hpp,
// the nonholonomic state (φ, θ, ψ̇, φ̇, θ̇)) against the hand equations' Jacobian: the same
// rocking modes, pitch near 109 rad/s and roll near 34 rad/s. Their growth rates are odd in s
// (time reversal): at s = 5 rad/s the pitch grows at 2.12 /s and the roll decays at 0.20 /s, at
// s = −5 the roll grows at 0.20 /s: without dissipation each sense reverses, through a different
// mode, the counterclockwise spin ten times faster (2.8 s against 11.5 s from the start above).
TEST(Rattleback, KaneLevinsonGrowthRatesAgainstHandLinearisation) {
  const test::ModelRun start =
      test::run_model("rattleback-kane-levinson", {}, [](SimulationOptions& o) { o.t_end = 0.01; });
  const Celt celt = Celt::of(start, 0);
  double worst = 0;
  for (const double s : {-10.0, -5.0, -2.0, 2.0, 5.0, 10.0}) {
    const test::LinearizedModel model("rattleback-kane-levinson",
                                      {"der(psi)=" + std::to_string(s)});
    std::vector<std::complex<double>> ours;
    for (const auto& lambda : test::sorted_eigenvalues(model.linearization.A)) {
      if (std::abs(lambda) > 1) ours.push_back(lambda);
    }
    std::sort(ours.begin(), ours.end(), [](auto p, auto q) {
      return p.imag() != q.imag() ? p.imag() < q.imag() : p.real() < q.real();
    });
    const std::vector<std::complex<double>> hand = celt.rocking_modes(s);
    ASSERT_EQ(ours.size(), 4u) << s;
    ASSERT_EQ(hand.size(), 4u) << s;
    for (std::size_t k = 0; k < 4; ++k) {
      worst = std::max(worst, std::abs(ours[k] - hand[k]));
      EXPECT_NEAR(ours[k].real(), hand[k].real(), 1e-6) << s;
      EXPECT_NEAR(ours[k].imag(), hand[k].imag(), 1e-6) << s;
    }
    // the upper half: roll (about 34 rad/s), then pitch (about 109 rad/s)
    const double roll = hand[2].real(), pitch = hand[3].real();
    std::printf("s = %+5.1f: roll %+.6f %+.4fi, pitch %+.6f %+.4fi (unidyn %+.6f, %+.6f)\n", s,
                roll, hand[2].imag(), pitch, hand[3].imag(), ours[2].real(), ours[3].real());
    EXPECT_LT(roll * pitch, 0) << "one rocking mode grows in each sense";
    EXPECT_GT(s * pitch, 0) << "the pitch grows when spun counterclockwise";
    if (std::abs(s) == 5) {
      EXPECT_NEAR(std::abs(pitch), 2.1207, 1e-4);
      EXPECT_NEAR(std::abs(roll), 0.2025, 1e-4);
    }
  }
  std::printf("largest |lambda(unidyn) - lambda(hand)| %.2e\n", worst);
}

// Spin bias needs dissipation: with Kane and Levinson's resisting moment −σ ω (σ = 2e-4 N m s
// chosen here, not theirs) the roll mode decays when spun clockwise (the hand linearisation: every
// rocking mode decays at −5 rad/s, the pitch still grows at +5), so spun
// clockwise the celt slows down without reversing, while spun counterclockwise it reverses within
// 2.5 s and then spins clockwise, slowing down. The run against the hand equations by RK4 with σ.
TEST(Rattleback, WithAirResistanceOnlyTheCounterclockwiseSpinReverses) {
  std::ifstream file(test::model_path("rattleback-kane-levinson"));
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::string gravity = "  - gravity: -g*E3\n";
  const std::size_t at = text.find(gravity);
  ASSERT_NE(at, std::string::npos);
  const double sigma = 2e-4;
  text.insert(at + gravity.size(), "  - moment: {on: celt, value: -2e-4*celt.omega}\n");
  const System system = parse_model(text, "rattleback-air.yaml");
  for (const double spin : {5.0, -5.0}) {
    const test::ModelRun run = test::run_system(
        system, {{"spin", spin}},
        [](SimulationOptions& o) {
          o.t_end = 25;
          o.rtol = 1e-12;
        },
        true);
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    const Celt celt = Celt::of(run, sigma);
    const std::vector<std::complex<double>> modes = celt.rocking_modes(spin);
    const CeltComparison c = compare_with_rk4(run, celt, spin);
    const std::vector<double> w3 = run.column("w3");
    const auto [low, high] = std::minmax_element(w3.begin(), w3.end());
    const double tilt_end = std::acos(run.rows.back()[run.index("up.z")]);
    std::printf(
        "sigma %g, spin %+g: roll %+.4f, pitch %+.4f /s; |omega - rk4| %.2e, |gamma - rk4| "
        "%.2e; first reversal %.6f s (rk4 %.6f); w3 in [%.4f, %.4f], final tilt %.2e\n",
        sigma, spin, modes[2].real(), modes[3].real(), c.omega_error, c.up_error, c.reversal_run,
        c.reversal_rk4, *low, *high, tilt_end);
    EXPECT_LT(c.omega_error, 1e-7);
    EXPECT_LT(c.up_error, 1e-9);
    EXPECT_NEAR(c.reversal_run, c.reversal_rk4, 1e-7);
    EXPECT_LT(tilt_end, 1e-3) << "the rocking dies out";
    if (spin > 0) {
      EXPECT_GT(modes[3].real(), 1) << "the pitch grows";
      EXPECT_GT(c.reversal_run, 0);
      EXPECT_LT(c.reversal_run, 2.5);
      EXPECT_LT(*low, -2.5) << "then it spins clockwise";
    } else {
      EXPECT_LT(modes[2].real(), 0);
      EXPECT_LT(modes[3].real(), 0);
      EXPECT_EQ(c.reversal_run, -1);
      EXPECT_LT(*high, 0) << "it never turns counterclockwise";
    }
  }
}

}  // namespace
}  // namespace unidyn
