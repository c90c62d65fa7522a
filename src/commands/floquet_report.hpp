// The analysis commands' output for a periodic motion of a driven system (analysis/floquet.hpp):
// the period and how it was found, A(t) at the start, the monodromy matrix, the Floquet
// multipliers and exponents and the verdict, as text, JSON and LaTeX.
#pragma once

#include <string>

#include "unidyn/analysis/floquet.hpp"
#include "unidyn/analysis/floquet_sweep.hpp"

namespace unidyn::commands {

// The point (as for a linearisation), the period, the state, A(t0) and Φ; with `floquet`, the
// multipliers and the verdict.
std::string periodic_text(const System& system, const OperatingPoint& point,
                          const PeriodicLinearization& linearization,
                          const FloquetAnalysis* floquet);

// One JSON object: "model", "operating_point", "computed", "state", "period" {T, from, t0},
// "A_at_t0", "monodromy", "ignorable", "dependent_coordinates", "dependent_rates", and with the
// multipliers "multipliers" [{re, im, modulus, exponent_re, exponent_im}], "stability", "reason".
std::string periodic_json(const System& system, const OperatingPoint& point,
                          const PeriodicLinearization& linearization,
                          const FloquetAnalysis* floquet);

// An align environment: ẋ = A(t) x, A(t + T) = A(t), A(t0) and Φ; multipliers and the verdict as
// comments.
std::string periodic_latex(const System& system, const OperatingPoint& point,
                           const PeriodicLinearization& linearization,
                           const FloquetAnalysis* floquet);

// modes --sweep of a driven system: the CSV header and a row per value (NAME, period, the largest
// |mu|, growth, re(mu1), im(mu1), ...), and the lines for standard error.
std::vector<std::string> floquet_sweep_header(const FloquetSweep& sweep);
std::vector<double> floquet_sweep_row(const FloquetSweepPoint& point, std::size_t multipliers);

}  // namespace unidyn::commands
