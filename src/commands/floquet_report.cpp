// Text, JSON and LaTeX of a periodic motion's Floquet analysis.
#include "floquet_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "analysis_format.hpp"
#include "analysis_report.hpp"
#include "unidyn/io/json_text.hpp"

namespace unidyn::commands {

using namespace format;

namespace {

// "T = 0.0397 s (2 pi/158, ...)".
std::string period_text(const PeriodicLinearization& P) {
  return "T = " + number(P.period.period) + " s (" + P.period.how + ")";
}

std::vector<std::string> row_names(const Linearization& L, const std::string& prefix) {
  std::vector<std::string> out;
  for (const auto& s : L.state) out.push_back(prefix + s);
  return out;
}

}  // namespace

std::string periodic_text(const System& system, const OperatingPoint& point,
                          const PeriodicLinearization& P, const FloquetAnalysis* floquet) {
  const Linearization& L = P.at_start;
  std::string out = operating_point_text(system, point, L);
  out += (P.period.given ? "the motion through the point analysed as periodic, "
                         : "the equations depend on t periodically, ") +
         period_text(P) +
         ": the point is a periodic motion, and its stability is Floquet's, over one period from "
         "t = " +
         number(P.t0) + "\n";
  out += "state x = (" + joined(L.state) +
         ")\nx' = A(t) x, A(t + T) = A(t); at t = " + number(P.t0) + ", A =\n";
  out += table(L.A, row_names(L, "d/dt "), L.state);
  out += fmt::format(
      "monodromy matrix Phi, x(t0 + T) = Phi x(t0) (the motion and Phi' = A(t) Phi integrated "
      "over one period, DOP853 rtol 1e-12, {} steps; back at the point to {}) =\n",
      P.steps, number(P.return_gap, 3));
  out += table(P.monodromy, L.state, L.state);
  if (!floquet) return out;
  out +=
      "Floquet multipliers mu (eigenvalues of Phi: a perturbation is multiplied by mu each "
      "period) and exponents rho = log(mu)/T (Im rho up to multiples of 2 pi/T = " +
      number(2 * std::numbers::pi / P.period.period, 6) + "):\n";
  for (std::size_t k = 0; k < floquet->multipliers.size(); ++k) {
    const FloquetMultiplier& m = floquet->multipliers[k];
    const double modulus = std::abs(m.multiplier);
    const bool on_circle = std::abs(modulus - 1.0) <= floquet->tolerance;
    const std::complex<double> rho(on_circle ? 0.0 : m.exponent.real(), m.exponent.imag());
    out += fmt::format("  {}. mu = {}, |mu| = {}{}, rho = {}\n", k + 1,
                       complex_text(m.multiplier, 9), number(modulus, 9),
                       on_circle     ? " (on the unit circle)"
                       : modulus > 1 ? " (grows)"
                                     : " (decays)",
                       complex_text(rho, 9));
  }
  out += "stability: " + to_string(floquet->verdict) + ": " + floquet->reason + "\n";
  return out;
}

std::string periodic_json(const System& system, const OperatingPoint& point,
                          const PeriodicLinearization& P, const FloquetAnalysis* floquet) {
  const Linearization& L = P.at_start;
  std::string out = "{\n  \"model\": " + quoted(system.name) + ",\n" + point_json(system, point);
  out += "  \"period\": {\"T\": " + json_number(P.period.period) +
         ", \"from\": " + quoted(P.period.how) + ", \"t0\": " + json_number(P.t0) + "},\n";
  out += "  \"state\": " + json_names(L.state) + ",\n  \"A_at_t0\": " + json_matrix(L.A) +
         ",\n  \"monodromy\": " + json_matrix(P.monodromy) +
         ",\n  \"ignorable\": " + json_names(L.ignorable) +
         ",\n  \"dependent_coordinates\": " + json_names(L.dependent_coordinates) +
         ",\n  \"dependent_rates\": " + json_names(L.dependent_rates);
  if (floquet) {
    out += ",\n  \"multipliers\": [";
    for (std::size_t k = 0; k < floquet->multipliers.size(); ++k) {
      const FloquetMultiplier& m = floquet->multipliers[k];
      out += std::string(k ? ",\n" : "\n") + "    {\"re\": " + json_number(m.multiplier.real()) +
             ", \"im\": " + json_number(m.multiplier.imag()) +
             ", \"modulus\": " + json_number(std::abs(m.multiplier)) +
             ", \"exponent_re\": " + json_number(m.exponent.real()) +
             ", \"exponent_im\": " + json_number(m.exponent.imag()) + "}";
    }
    out += "\n  ],\n  \"stability\": " + quoted(to_string(floquet->verdict)) +
           ",\n  \"reason\": " + quoted(floquet->reason);
  }
  return out + "\n}\n";
}

std::string periodic_latex(const System& system, const OperatingPoint& point,
                           const PeriodicLinearization& P, const FloquetAnalysis* floquet) {
  const Linearization& L = P.at_start;
  std::string out = "% " + system.name + ": the periodic motion through";
  for (const std::string& v : given_values(system, point)) out += " " + v + ";";
  out += " " + period_text(P);
  if (!L.ignorable.empty()) out += "; ignorable, dropped: " + joined(L.ignorable);
  out += "\n\\begin{align}\n";
  std::vector<std::vector<std::string>> state;
  for (const std::string& s : L.state) state.push_back({latex_state(s)});
  out += "  \\dot{x} &= A(t)\\, x, \\quad A(t + T) = A(t), \\quad T = " +
         latex_number(P.period.period) + ", \\quad x = " + bmatrix(state) +
         " \\label{eq:periodic} \\\\\n";
  out += "  A(" + latex_number(P.t0) + ") &= " + latex_matrix(L.A) +
         " \\label{eq:state-matrix-t0} \\\\\n";
  out += "  \\Phi &= " + latex_matrix(P.monodromy) +
         ", \\quad x(t_0 + T) = \\Phi\\, x(t_0) \\label{eq:monodromy}\n\\end{align}\n";
  if (floquet) {
    for (const FloquetMultiplier& m : floquet->multipliers) {
      out += "% mu = " + complex_text(m.multiplier, 12) +
             ", |mu| = " + number(std::abs(m.multiplier)) + "\n";
    }
    out += "% stability: " + to_string(floquet->verdict) + ": " + floquet->reason + "\n";
  }
  return out;
}

std::vector<std::string> floquet_sweep_header(const FloquetSweep& sweep) {
  std::size_t size = 0;
  for (const FloquetSweepPoint& p : sweep.points) size = std::max(size, p.multipliers.size());
  std::vector<std::string> header{sweep.parameter, "period", "largest_modulus", "growth"};
  for (std::size_t k = 1; k <= size; ++k) {
    header.push_back(fmt::format("re(mu{})", k));
    header.push_back(fmt::format("im(mu{})", k));
  }
  return header;
}

std::vector<double> floquet_sweep_row(const FloquetSweepPoint& p, std::size_t multipliers) {
  const bool failed = !p.failure.empty();
  std::vector<double> row{p.value, failed ? NAN : p.period,
                          failed || p.multipliers.empty() ? NAN : std::abs(p.multipliers[0]),
                          p.growth};
  for (std::size_t k = 0; k < multipliers; ++k) {
    const bool has = k < p.multipliers.size();
    row.push_back(has ? p.multipliers[k].real() : NAN);
    row.push_back(has ? p.multipliers[k].imag() : NAN);
  }
  return row;
}

}  // namespace unidyn::commands
