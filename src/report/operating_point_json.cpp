// The report page's linearisation: the operating point, ẋ = A x, the modes and the verdict.
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "page_data.hpp"
#include "unidyn/io/json_text.hpp"

namespace unidyn {
namespace {

// A mode's shape: [name, modulus, phase in degrees] of each coordinate it moves by more than 1e-6
// of the largest (moduli to four digits, phases to a tenth of a degree).
std::string shape_json(const Mode& mode, const std::vector<std::string>& coordinates) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < mode.shape.size() && i < coordinates.size(); ++i) {
    const double modulus = std::abs(mode.shape[i]);
    if (modulus <= 1e-6) continue;
    // (−180°, 180°], to a tenth of a degree
    double degrees = std::round(std::arg(mode.shape[i]) * 1800.0 / std::numbers::pi) / 10.0;
    if (degrees == -180.0) degrees = 180.0;
    out.push_back(fmt::format("[{}, {:.4g}, {:.1f}]", unidyn::quoted(coordinates[i]), modulus,
                              degrees == 0.0 ? 0.0 : degrees));
  }
  return fmt::format("[{}]", fmt::join(out, ", "));
}

// A periodic motion: its period, each multiplier μ ("a±bi", six digits) with |μ| and the exponent
// log(μ)/T, and the verdict.
std::string floquet_json(const ReportOperatingPoint& point) {
  const FloquetAnalysis& floquet = *point.floquet;
  std::vector<std::string> multipliers;
  // on the unit circle (within the verdict's tolerance) the exponent's real part is 0
  const auto on_circle = [&](const FloquetMultiplier& m) {
    return std::abs(std::abs(m.multiplier) - 1.0) <= floquet.tolerance;
  };
  for (const FloquetMultiplier& m : floquet.multipliers) {
    const std::complex<double> exponent(0.0, m.exponent.imag());
    const auto text = [](std::complex<double> z) {
      return z.imag() == 0.0 ? fmt::format("{:.6g}", z.real())
                             : fmt::format("{:.6g}{}{:.6g}i", z.real(), z.imag() < 0 ? "-" : "+",
                                           std::abs(z.imag()));
    };
    multipliers.push_back(
        "{\"multiplier\": " + unidyn::quoted(text(m.multiplier)) +
        ", \"modulus\": " + page_number(std::abs(m.multiplier)) +
        ", \"exponent\": " + unidyn::quoted(text(on_circle(m) ? exponent : m.exponent)) + "}");
  }
  return "{\"label\": " + unidyn::quoted(point.label) +
         ", \"latex\": " + unidyn::quoted(point.latex) +
         ", \"period\": " + page_number(point.period) + ", \"multipliers\": [" +
         fmt::format("{}", fmt::join(multipliers, ",\n")) +
         "], \"stability\": " + unidyn::quoted(to_string(floquet.verdict)) +
         ", \"reason\": " + unidyn::quoted(floquet.reason) + "}";
}

}  // namespace

std::string operating_point_json(const ReportModel& model) {
  if (!model.operating_point) {
    return "{\"none\": " + unidyn::quoted(model.no_operating_point) + "}";
  }
  const ReportOperatingPoint& point = *model.operating_point;
  if (point.floquet) return floquet_json(point);
  std::vector<std::string> modes;
  const double tolerance = point.modes.tolerance;
  for (const Mode& mode : point.modes.modes) {
    // within the verdict's tolerance of 0: λ = 0 (no damping ratio), or Re λ = 0 (ζ = 0)
    const bool zero = std::abs(mode.eigenvalue) <= tolerance;
    const bool undamped = std::abs(mode.eigenvalue.real()) <= tolerance;
    modes.push_back(
        "{\"eigenvalue\": " + unidyn::quoted(eigenvalue_text(mode, tolerance)) +
        ", \"natural_frequency\": " + page_number(zero ? 0.0 : mode.natural_frequency) +
        ", \"damping_ratio\": " +
        (zero ? std::string("null") : page_number(undamped ? 0.0 : mode.damping_ratio)) +
        ", \"of_rates\": " + (mode.of_rates ? "true" : "false") +
        ", \"shape\": " + shape_json(mode, point.coordinates) + "}");
  }
  return "{\"label\": " + unidyn::quoted(point.label) +
         ", \"latex\": " + unidyn::quoted(point.latex) + ", \"modes\": [" +
         fmt::format("{}", fmt::join(modes, ",\n")) +
         "], \"stability\": " + unidyn::quoted(to_string(point.modes.verdict)) +
         ", \"reason\": " + unidyn::quoted(point.modes.reason) + "}";
}

}  // namespace unidyn
