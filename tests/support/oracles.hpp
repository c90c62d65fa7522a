// Shared helpers for the tests: reproducible random rotations and vectors, and finite differences.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "unidyn/tensor/tensor.hpp"

namespace unidyn::test {

inline constexpr double kPi = std::numbers::pi;

// A seeded generator so that every failure reproduces.
class Random {
 public:
  explicit Random(unsigned seed = 20261121u) : engine_(seed) {}

  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(engine_);
  }

  Vec3 vector(double scale = 1.0) {
    return Vec3(uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale));
  }

  Vec3 unit_vector() {
    std::normal_distribution<double> normal;
    Vec3 v(normal(engine_), normal(engine_), normal(engine_));
    return v.normalized();
  }

  // A rotation uniformly distributed on SO(3): a uniformly random unit quaternion (Shoemake),
  // built here directly from its components so it does not depend on the code under test.
  Tensor rotation() {
    const double u1 = uniform(0.0, 1.0), u2 = uniform(0.0, 2.0 * kPi), u3 = uniform(0.0, 2.0 * kPi);
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    const double w = a * std::sin(u2), x = a * std::cos(u2), y = b * std::sin(u3),
                 z = b * std::cos(u3);
    Tensor Q;
    Q << 1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),  //
        2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),   //
        2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y);
    return Q;
  }

 private:
  std::mt19937_64 engine_;
};

// (6.8) typed from the book, also for a non-unit r, column by column:
// L(φ, r) a = cos φ (a − (r·a) r) − sin φ (a × r) + (r·a) r, since (εr) a = a × r.
inline Tensor book_L(double phi, const Vec3& r) {
  Tensor L;
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = Vec3::Unit(k);
    L.col(k) = std::cos(phi) * (a - r.dot(a) * r) - std::sin(phi) * a.cross(r) + r.dot(a) * r;
  }
  return L;
}

// Fourth-order central difference of a tensor-valued function of time: error O(h⁴).
inline Tensor derivative(const std::function<Tensor(double)>& f, double t, double h = 1e-3) {
  return (8.0 * (f(t + h) - f(t - h)) - (f(t + 2 * h) - f(t - 2 * h))) / (12.0 * h);
}

// Fourth-order central difference of a scalar function of time.
inline double derivative(const std::function<double(double)>& f, double t, double h = 1e-3) {
  return (8.0 * (f(t + h) - f(t - h)) - (f(t + 2 * h) - f(t - 2 * h))) / (12.0 * h);
}

// Keeps a measured error in the test report (--gtest_output=xml).
inline void record(const std::string& name, double value) {
  std::ostringstream text;
  text << std::scientific << std::setprecision(3) << value;
  ::testing::Test::RecordProperty(name, text.str());
}

// Largest absolute entry of the difference.
template <class A, class B>
double max_abs_diff(const A& a, const B& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

}  // namespace unidyn::test
