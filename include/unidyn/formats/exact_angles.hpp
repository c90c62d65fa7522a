// Angles that robot files write as rounded multiples of π (URDF's rpy="1.5707963267948966 0 0",
// "3.14159265358979"): written as the exact multiple in the model language, so that the equations
// hold cos(pi/2) = 0 rather than the sine and cosine of a 17-digit rational, which no
// simplification removes (a 7-link arm's derivation takes minutes with them, seconds without).
#pragma once

#include <optional>
#include <string>

namespace unidyn::formats {

// The largest distance from k π/4 at which an angle is taken for it: a number typed with 13
// significant digits or more (1.5707963267949 is 3.2e-14 from π/2); 1.5708 (3.7e-6) is not.
inline constexpr double kExactAngleTolerance = 1e-12;

// What the importers' note says of an angle written as the multiple.
inline constexpr const char* kExactAngleNote =
    " (within 1e-12 rad of it: its sine and cosine exact)";

// "pi/2", "-3*pi/4", "0", … when `radians` is within kExactAngleTolerance of k π/4; else none.
std::optional<std::string> exact_quarter_pi_multiple(double radians);

}  // namespace unidyn::formats
