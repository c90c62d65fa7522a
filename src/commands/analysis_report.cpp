// Text and JSON of an operating point, its linearisation and its modes.
#include "analysis_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "analysis_format.hpp"
#include "unidyn/io/json_text.hpp"
#include "unidyn/numeric/number_text.hpp"
#include "unidyn/symbolic/canonical_text.hpp"
#include "unidyn/symbolic/coordinates.hpp"

namespace unidyn::commands {

using namespace format;

namespace {

// What a mode does in time; a real part within `tolerance` of 0 is 0.
std::string behaviour(const Mode& mode, double tolerance) {
  const double re = std::abs(mode.eigenvalue.real()) <= tolerance ? 0.0 : mode.eigenvalue.real();
  if (mode.damped_frequency == 0.0) {
    if (re == 0.0) return "neutral";
    return std::string(re < 0 ? "decays" : "grows") + ", time constant " +
           number(1 / std::abs(re), 6) + " s";
  }
  return "natural frequency " + number(mode.natural_frequency, 6) + " rad/s, damped " +
         number(mode.damped_frequency, 6) + " rad/s (" +
         number(mode.damped_frequency / (2 * std::numbers::pi), 6) + " Hz), " +
         (re == 0.0 ? std::string("undamped") : "damping ratio " + number(mode.damping_ratio, 6));
}

}  // namespace

std::string analysis_latex(const System& system, const OperatingPoint& point,
                           const Linearization& L, const ModeAnalysis* modes,
                           const ExactLinearization& exact) {
  std::string out = "% " + system.name + ": linearised about";
  for (const std::string& v : given_values(system, point)) out += " " + v + ";";
  if (!L.ignorable.empty()) out += " ignorable, dropped: " + joined(L.ignorable);
  out += "\n\\begin{align}\n";
  std::vector<std::vector<std::string>> state;
  for (const std::string& s : L.state) state.push_back({latex_state(s)});
  out += "  \\dot{x} &= A x, \\quad x = " + bmatrix(state) + " \\label{eq:linearised} \\\\\n";
  out += "  A &= " + latex_matrix(L.A) + " \\label{eq:state-matrix}";
  const auto latex = [](const ExprMatrix& X) {
    std::vector<std::vector<std::string>> rows(X.rows);
    for (std::size_t i = 0; i < X.rows; ++i) {
      for (std::size_t j = 0; j < X.cols; ++j) rows[i].push_back(canonical_latex(X(i, j)));
    }
    return bmatrix(rows);
  };
  if (exact.state_matrix) {
    out += " \\\\\n  A &= " + latex(*exact.state_matrix) + " \\label{eq:state-matrix-exact}";
  }
  if (const auto& mck = exact.second_order) {
    out += " \\\\\n  M &= " + latex(mck->M) + ", \\quad C = " + latex(mck->C) +
           ", \\quad K = " + latex(mck->K) + " \\label{eq:mck}";
  }
  out += "\n\\end{align}\n";
  if (modes) {
    for (const Mode& m : modes->modes) {
      const double re =
          std::abs(m.eigenvalue.real()) <= modes->tolerance ? 0.0 : m.eigenvalue.real();
      out += "% lambda = " +
             (m.damped_frequency == 0.0 ? number(re)
                                        : number(re) + " +/- " + number(m.damped_frequency) + "i") +
             "\n";
    }
    out += "% stability: " + to_string(modes->verdict) + ": " + modes->reason + "\n";
  }
  return out;
}

std::string operating_point_text(const System& system, const OperatingPoint& point,
                                 const Linearization& linearization) {
  std::string out = "operating point of " + system.name + "\n";
  if (!point.source.empty()) out += "  from " + point.source + "\n";
  const std::vector<std::string> given = given_values(system, point);
  out +=
      "  given: " + (given.empty() ? std::string("nothing (all values 0)") : joined(given)) + "\n";
  if (!point.computed.empty())
    out += "  computed from the constraints: " + joined(point.computed) + "\n";
  if (!linearization.dependent_coordinates.empty()) {
    out += "  dependent coordinates: " + joined(linearization.dependent_coordinates) + "\n";
  }
  if (!linearization.dependent_rates.empty()) {
    out += "  dependent rates: " + joined(linearization.dependent_rates) + "\n";
  }
  if (!linearization.ignorable.empty()) {
    out += "  ignorable, dropped: " + joined(linearization.ignorable) + "\n";
  }
  return out;
}

std::string linearization_text(const Linearization& L) {
  std::string out = "state x = (" + joined(L.state) + ")\nx' = A x, A =\n";
  std::vector<std::string> rows;
  for (const auto& s : L.state) rows.push_back("d/dt " + s);
  out += table(L.A, rows, L.state);
  if (L.second_order) {
    out += "M q'' + C q' + K q = 0 (perturbations of every coordinate), M =\n";
    out += table(L.second_order->M, L.coordinates, L.coordinates);
    out += "C =\n" + table(L.second_order->C, L.coordinates, L.coordinates);
    out += "K =\n" + table(L.second_order->K, L.coordinates, L.coordinates);
  }
  return out;
}

namespace {

// [a, b; c, d] with each entry's canonical text.
std::string matrix_text(const ExprMatrix& X) {
  std::string out = "[";
  for (std::size_t i = 0; i < X.rows; ++i) {
    out += i ? "; " : "";
    for (std::size_t j = 0; j < X.cols; ++j) out += (j ? ", " : "") + canonical_text(X(i, j));
  }
  return out + "]";
}

// [["a", "b"], ["c", "d"]].
std::string matrix_json(const ExprMatrix& X) {
  std::string out = "[";
  for (std::size_t i = 0; i < X.rows; ++i) {
    out += i ? ", [" : "[";
    for (std::size_t j = 0; j < X.cols; ++j)
      out += (j ? ", " : "") + quoted(canonical_text(X(i, j)));
    out += "]";
  }
  return out + "]";
}

std::string exact_json(const ExactLinearization& exact) {
  if (exact.state_matrix) return "{\"A\": " + matrix_json(*exact.state_matrix) + "}";
  const ExactSecondOrder& mck = *exact.second_order;
  return "{\"M\": " + matrix_json(mck.M) + ", \"C\": " + matrix_json(mck.C) +
         ", \"K\": " + matrix_json(mck.K) + "}";
}

}  // namespace

std::string exact_text(const System& system, const Linearization& L,
                       const ExactLinearization& exact) {
  if (exact.state_matrix) {
    return "in closed form (the parameters as symbols), x' = A x with\n  A = " +
           matrix_text(*exact.state_matrix) + "\n  (state in order: " + joined(L.state) + ")\n";
  }
  if (!exact.second_order) return "";
  const ExactSecondOrder& mck = *exact.second_order;
  std::string out = "in closed form (the parameters as symbols), M q'' + C q' + K q = 0 with\n";
  out += "  M = " + matrix_text(mck.M) + "\n  C = " + matrix_text(mck.C) +
         "\n  K = " + matrix_text(mck.K) + "\n  (coordinates in order: ";
  for (std::size_t i = 0; i < system.coordinates().size(); ++i) {
    out += (i ? ", " : "") + system.coordinates()[i].name;
  }
  return out + ")\n";
}

std::string modes_text(const Linearization& L, const ModeAnalysis& modes) {
  std::string out = fmt::format(
      "modes (eigenvalues of A; complex ones in pairs, lambda and its conjugate; real parts "
      "below {} shown as 0, shape entries below 1e-9 left out):\n",
      number(modes.tolerance, 3));
  for (std::size_t k = 0; k < modes.modes.size(); ++k) {
    const Mode& mode = modes.modes[k];
    const double re =
        std::abs(mode.eigenvalue.real()) <= modes.tolerance ? 0.0 : mode.eigenvalue.real();
    const std::string lambda = mode.damped_frequency == 0.0 ? number(re)
                               : re == 0.0
                                   ? "±" + number(mode.damped_frequency) + "i"
                                   : number(re) + " ± " + number(mode.damped_frequency) + "i";
    out += fmt::format("  {}. lambda = {}: {}\n", k + 1, lambda, behaviour(mode, modes.tolerance));
    std::vector<std::string> shape;
    for (std::size_t i = 0; i < mode.shape.size(); ++i) {
      // the largest entry is 1: below 1e-9, round-off
      const auto snap = [](double x) { return std::abs(x) < 1e-9 ? 0.0 : x; };
      const std::complex<double> z(snap(mode.shape[i].real()), snap(mode.shape[i].imag()));
      if (z == 0.0) continue;
      shape.push_back(L.coordinates[i] + " " + complex_text(z, 6));
    }
    out += std::string("     shape") + (mode.of_rates ? " (of the rates)" : "") + ": " +
           (shape.empty() ? std::string("none") : joined(shape)) + "\n";
  }
  out += "stability: " + to_string(modes.verdict) + ": " + modes.reason + "\n";
  return out;
}

std::string analysis_json(const System& system, const OperatingPoint& point, const Linearization& L,
                          const ModeAnalysis* modes, const ExactLinearization& exact) {
  std::string out = "{\n  \"model\": " + quoted(system.name) + ",\n" + point_json(system, point);
  out += "  \"state\": " + json_names(L.state) + ",\n  \"A\": " + json_matrix(L.A) + ",\n";
  out += "  \"ignorable\": " + json_names(L.ignorable) +
         ",\n  \"dependent_coordinates\": " + json_names(L.dependent_coordinates) +
         ",\n  \"dependent_rates\": " + json_names(L.dependent_rates);
  if (L.second_order) {
    out += ",\n  \"coordinates\": " + json_names(L.coordinates) +
           ",\n  \"M\": " + json_matrix(L.second_order->M) +
           ",\n  \"C\": " + json_matrix(L.second_order->C) +
           ",\n  \"K\": " + json_matrix(L.second_order->K);
  }
  if (exact.state_matrix || exact.second_order) out += ",\n  \"exact\": " + exact_json(exact);
  if (modes) {
    out += ",\n  \"modes\": [";
    for (std::size_t k = 0; k < modes->modes.size(); ++k) {
      const Mode& m = modes->modes[k];
      out += std::string(k ? ",\n" : "\n") + "    {\"re\": " + json_number(m.eigenvalue.real()) +
             ", \"im\": " + json_number(m.eigenvalue.imag()) +
             ", \"natural_frequency\": " + json_number(m.natural_frequency) +
             ", \"damping_ratio\": " + json_number(m.damping_ratio) +
             ", \"of_rates\": " + (m.of_rates ? "true" : "false") + ", \"shape\": {";
      for (std::size_t i = 0; i < m.shape.size(); ++i) {
        out += (i ? ", " : "") + quoted(L.coordinates[i]) + ": [" + json_number(m.shape[i].real()) +
               ", " + json_number(m.shape[i].imag()) + "]";
      }
      out += "}}";
    }
    out += "\n  ],\n  \"stability\": " + quoted(to_string(modes->verdict)) +
           ",\n  \"reason\": " + quoted(modes->reason);
  }
  return out + "\n}\n";
}

std::string equilibria_text(const System& system, const EquilibriumSearchResult& result,
                            std::size_t starts) {
  const std::vector<Equilibrium>& found = result.equilibria;
  const bool steady = !result.cyclic.empty();
  const auto on_continua = static_cast<std::size_t>(std::count_if(
      found.begin(), found.end(), [](const Equilibrium& e) { return e.continuum > 0; }));
  const std::size_t isolated = found.size() - on_continua;
  const auto kind = [&](std::size_t count) {
    return steady ? (count == 1 ? "steady motion" : "steady motions")
                  : (count == 1 ? "equilibrium" : "equilibria");
  };
  std::string out = fmt::format("{} {}", isolated, kind(isolated));
  if (on_continua > 0) {
    out = fmt::format("{} isolated {} and {} point{} of continua of {}", isolated, kind(isolated),
                      on_continua, on_continua == 1 ? "" : "s", kind(2));
  }
  out += fmt::format(" of {} ({}{} starts; angles in (-pi, pi]):\n", system.name,
                     steady ? "cyclic: " + joined(result.cyclic) + "; " : "", starts);
  // the points of continua after the first few are counted, not listed
  constexpr std::size_t kContinuumPointsListed = 3;
  std::size_t continuum_points = 0;
  const auto& q = system.coordinates();
  const auto has = [](const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  for (std::size_t k = 0; k < found.size(); ++k) {
    const Equilibrium& e = found[k];
    if (e.continuum > 0 && ++continuum_points > kContinuumPointsListed) continue;
    std::vector<std::string> values, rates;
    for (std::size_t i = 0; i < q.size(); ++i) {
      const auto index = static_cast<Eigen::Index>(i);
      values.push_back(q[i].name + " = " +
                       (has(result.cyclic, q[i].name)               ? std::string("any (cyclic)")
                        : has(e.linearization.ignorable, q[i].name) ? std::string("any (ignorable)")
                                                                    : number(e.point.q[index])));
      if (e.point.qdot[index] != 0.0) {
        rates.push_back("der(" + q[i].name + ") = " + number(e.point.qdot[index]));
      }
    }
    out += fmt::format("  {}. {}\n", k + 1, joined(values));
    if (!rates.empty()) out += fmt::format("     {}\n", joined(rates));
    if (e.continuum > 0) {
      out += fmt::format(
          "     one point of a {}-dimensional continuum of {} (the forces balance all along it)\n",
          e.continuum, steady ? "steady motions" : "equilibria");
    }
    out += fmt::format("     {}: {}\n", to_string(e.modes.verdict), e.modes.reason);
    if (e.potential_minimum) {
      if (e.amended) {
        out += *e.potential_minimum
                   ? "     the amended potential's Hessian is positive definite on the "
                     "constraints, a strict minimum: stable at these momenta (Routh)\n"
                   : "     the amended potential's Hessian is not positive definite on the "
                     "constraints: no minimum there\n";
      } else {
        out += *e.potential_minimum
                   ? "     K is positive definite on the constraints, a strict minimum of the "
                     "potential (amended by any steady drive): stable (Lagrange-Dirichlet)\n"
                   : "     K is not positive definite on the constraints: no minimum of the "
                     "potential there\n";
      }
    }
  }
  if (continuum_points > kContinuumPointsListed) {
    out += fmt::format("not listed: {} more points of continua (--format json lists every one)\n",
                       continuum_points - kContinuumPointsListed);
  }
  if (result.singular > 0) {
    out += fmt::format(
        "left out: {} start{} converged where the equations are singular (Euler angles at gimbal "
        "lock: describe the rotation by another set, or by Euler parameters, to see what is "
        "there)\n",
        result.singular, result.singular == 1 ? "" : "s");
  }
  if (result.not_steady > 0) {
    out += fmt::format(
        "left out: {} solution{} of the balance that move (a rate of a coordinate "
        "that is not ignorable, or a unilateral contact that would have to pull)\n",
        result.not_steady, result.not_steady == 1 ? "" : "s");
  }
  return out;
}

std::string equilibria_json(const System& system, const EquilibriumSearchResult& result) {
  const std::vector<Equilibrium>& found = result.equilibria;
  const auto& q = system.coordinates();
  std::string out = "{\n  \"model\": " + quoted(system.name) +
                    ",\n  \"cyclic\": " + json_names(result.cyclic) + ",\n  \"equilibria\": [";
  for (std::size_t k = 0; k < found.size(); ++k) {
    const Equilibrium& e = found[k];
    out += std::string(k ? ",\n" : "\n") + "    {\"coordinates\": {";
    for (std::size_t i = 0; i < q.size(); ++i) {
      out += (i ? ", " : "") + quoted(q[i].name) + ": " +
             json_number(e.point.q[static_cast<Eigen::Index>(i)]);
    }
    out += "}, \"rates\": {";
    for (std::size_t i = 0; i < q.size(); ++i) {
      out += (i ? ", " : "") + quoted("der(" + q[i].name + ")") + ": " +
             json_number(e.point.qdot[static_cast<Eigen::Index>(i)]);
    }
    out += "}, \"ignorable\": " + json_names(e.linearization.ignorable) +
           ", \"stability\": " + quoted(to_string(e.modes.verdict)) +
           ", \"reason\": " + quoted(e.modes.reason) +
           ", \"continuum\": " + std::to_string(e.continuum) + ", \"potential_minimum\": " +
           (e.potential_minimum ? (*e.potential_minimum ? "true" : "false") : "null") +
           ", \"amended_potential\": " + (e.amended ? "true" : "false") + "}";
  }
  return out + fmt::format("\n  ],\n  \"starts_singular\": {},\n  \"starts_moving\": {}\n}}\n",
                           result.singular, result.not_steady);
}

}  // namespace unidyn::commands
