// Angles written as exact multiples of π/4 (include/unidyn/formats/exact_angles.hpp).
#include "unidyn/formats/exact_angles.hpp"

#include <cmath>
#include <numbers>

namespace unidyn::formats {

std::optional<std::string> exact_quarter_pi_multiple(double radians) {
  const double quarters = std::round(radians / (std::numbers::pi / 4));
  if (!std::isfinite(radians) || std::abs(quarters) > 64 ||
      std::abs(radians - quarters * std::numbers::pi / 4) > kExactAngleTolerance) {
    return std::nullopt;
  }
  // k/4 in lowest terms: k π/4, k π/2 or k π
  long k = std::lround(quarters);
  long denominator = 4;
  while (denominator > 1 && k % 2 == 0) {
    k /= 2;
    denominator /= 2;
  }
  if (k == 0) return "0";
  std::string text = k == 1 ? "pi" : k == -1 ? "-pi" : std::to_string(k) + "*pi";
  if (denominator > 1) text += "/" + std::to_string(denominator);
  return text;
}

}  // namespace unidyn::formats
