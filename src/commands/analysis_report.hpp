// The analysis commands' output: the operating point, the linearisation and the modes as text or
// JSON. Numbers: twelve significant digits in text, the shortest exact form in JSON.
#pragma once

#include <string>

#include "unidyn/analysis/equilibria.hpp"
#include "unidyn/analysis/exact_linearization.hpp"
#include "unidyn/analysis/linearization.hpp"
#include "unidyn/analysis/modes.hpp"

namespace unidyn::commands {

// The point, given and computed values, then what was eliminated and dropped.
std::string operating_point_text(const System& system, const OperatingPoint& point,
                                 const Linearization& linearization);
// The state, A, and (without constraints) M, C and K.
std::string linearization_text(const Linearization& linearization);
// M, C and K in closed form.
// The closed forms there are (nothing where there are none).
std::string exact_text(const System& system, const Linearization& linearization,
                       const ExactLinearization& exact);
// The eigenvalues with their frequencies, damping ratios and shapes, then the verdict.
std::string modes_text(const Linearization& linearization, const ModeAnalysis& modes);

// An align environment (amsmath): the state, A, M, C and K in closed form where there are, the
// eigenvalues and the verdict (as comments); names set as the book sets them (\dot{\phi}).
std::string analysis_latex(const System& system, const OperatingPoint& point,
                           const Linearization& linearization, const ModeAnalysis* modes,
                           const ExactLinearization& exact);

// One JSON object: "model", "operating_point" {coordinates, rates, accelerations}, "computed",
// "state", "A", "ignorable", "dependent_coordinates", "dependent_rates", "M", "C", "K" (without
// constraints), "exact" {M, C, K as texts} or {A as texts} (at an exact point without or with
// constraints), and with modes
// "modes" [{re, im, natural_frequency, damping_ratio, shape {name: [re, im]}}], "stability",
// "reason".
std::string analysis_json(const System& system, const OperatingPoint& point,
                          const Linearization& linearization, const ModeAnalysis* modes,
                          const ExactLinearization& exact);

// One line per equilibrium: its coordinates (angles in (−π, π]; an ignorable one "any"), its
// verdict and the reason, and Lagrange–Dirichlet's word where it applies; then what was left out.
std::string equilibria_text(const System& system, const EquilibriumSearchResult& found,
                            std::size_t starts);
std::string equilibria_json(const System& system, const EquilibriumSearchResult& found);

}  // namespace unidyn::commands
