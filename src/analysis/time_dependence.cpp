// How the equations depend on t, and their period.
#include "unidyn/analysis/time_dependence.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include "unidyn/numeric/number_text.hpp"
#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/real_value.hpp"
#include "unidyn/symbolic/zero_test.hpp"

namespace unidyn {
namespace {

// The largest denominator of a ratio of two frequencies that counts as commensurate.
constexpr long long kLargestDenominator = 1000;
// How close a ratio must be to its fraction.
constexpr double kRatioTolerance = 1e-12;

// An entry of the equations and what it belongs to ("the equation of phi", "constraint 'rod'"): M,
// f and the constraint rows A, e, b. Not Ψ: its t enters the motion through e = ∂Ψ/∂t (a coordinate
// turned at a constant rate, Ψ = φ − Ωt, has e = −Ω and equations that do not change with t).
struct Entry {
  Expr value;
  std::string where;
};

std::vector<Entry> entries(const System& system, const EquationsOfMotion& eq) {
  std::vector<Entry> out;
  const auto& q = system.coordinates();
  for (std::size_t i = 0; i < q.size(); ++i) {
    const std::string where = "the equation of " + q[i].name;
    for (std::size_t j = 0; j < q.size(); ++j) out.push_back({eq.mass_matrix(i, j), where});
    out.push_back({eq.forcing[i], where});
  }
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    const std::string where = "constraint '" + system.constraints[k].name + "'";
    for (std::size_t j = 0; j < q.size(); ++j) out.push_back({eq.constraint_matrix(k, j), where});
    out.push_back({eq.constraint_velocity_term[k], where});
    out.push_back({eq.constraint_bias[k], where});
  }
  return out;
}

// Whether e has a coordinate, a rate or an acceleration in it.
bool has_state(const Expr& e, const System& system) {
  for (const auto& q : system.coordinates()) {
    if (e.has(q.value) || e.has(q.rate) || e.has(q.acceleration)) return true;
  }
  return false;
}

// The frequencies of the sin, cos and tan of ω t + c in e into `out`; the first term with t
// elsewhere into `elsewhere` (the smallest expression holding t itself).
void collect(const Expr& e, const Expr& parent, const System& system,
             std::vector<TimeDependence::Frequency>& out, std::string& elsewhere) {
  const GiNaC::realsymbol& t = system.time();
  if (!e.has(t) || !elsewhere.empty()) return;
  if (e.is_equal(t)) {
    elsewhere = to_text(parent);
    return;
  }
  if (GiNaC::is_exactly_a<GiNaC::function>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    const Expr argument = e.op(0).expand();
    if ((name == "sin" || name == "cos" || name == "tan") && argument.is_polynomial(t) &&
        argument.degree(t) == 1) {
      const Expr omega = argument.coeff(t, 1);
      if (!has_state(omega, system)) {
        out.push_back({omega, to_text(e)});
        return;
      }
    }
  }
  for (std::size_t i = 0; i < e.nops(); ++i) collect(e.op(i), e, system, out, elsewhere);
}

// The fraction p/q (q ≤ kLargestDenominator) within kRatioTolerance of r > 0, by its continued
// fraction; nothing when there is none.
std::optional<std::pair<long long, long long>> fraction(double r) {
  long long p0 = 0, q0 = 1, p1 = 1, q1 = 0;
  double x = r;
  for (int step = 0; step < 64; ++step) {
    const double a = std::floor(x);
    if (a > 1e12) break;
    const auto whole = static_cast<long long>(a);
    const long long p2 = whole * p1 + p0, q2 = whole * q1 + q0;
    if (q2 > kLargestDenominator) break;
    if (std::abs(r - static_cast<double>(p2) / static_cast<double>(q2)) <= kRatioTolerance * r) {
      return std::pair{p2, q2};
    }
    p0 = p1, q0 = q1, p1 = p2, q1 = q2;
    if (x - a == 0.0) break;
    x = 1.0 / (x - a);
  }
  return std::nullopt;
}

// The largest difference between the compiled equations at t1 and t2, relative to their size, at
// random states: M, f, A, b of the dynamics, A and e of the constraints (not Ψ, which may grow with
// t: time_dependence). Outside the model's domain (a square root of a negative number) nothing is
// compared.
double difference_between(const CompiledSystem& compiled, const std::vector<double>& parameters,
                          double t1, double t2, std::mt19937_64& random) {
  const auto n = static_cast<Eigen::Index>(compiled.coordinate_count());
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<double> inputs{t1};
  for (Eigen::Index i = 0; i < 2 * n; ++i) inputs.push_back(unit(random));
  inputs.insert(inputs.end(), parameters.begin(), parameters.end());
  const std::size_t rows = compiled.constraint_count() * (compiled.coordinate_count() + 1);
  double most = 0.0;
  for (const Tape* tape : {&compiled.dynamics(), &compiled.constraint_tape()}) {
    inputs[0] = t1;
    const std::vector<double> now = tape->evaluate(inputs);
    inputs[0] = t2;
    const std::vector<double> later = tape->evaluate(inputs);
    const std::size_t compared = tape == &compiled.dynamics() ? now.size() : rows;
    double scale = 1.0;
    for (std::size_t k = 0; k < compared; ++k) {
      if (std::isfinite(now[k])) scale = std::max(scale, std::abs(now[k]));
    }
    for (std::size_t k = 0; k < compared; ++k) {
      if (!std::isfinite(now[k]) || !std::isfinite(later[k])) continue;
      most = std::max(most, std::abs(now[k] - later[k]) / scale);
    }
  }
  return most;
}

// Whether the compiled equations are the same at t and t + T, at random states and instants.
bool repeats_after(const CompiledSystem& compiled, const std::vector<double>& parameters,
                   double period) {
  std::mt19937_64 random(20261128u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int sample = 0; sample < 4; ++sample) {
    const double t = period * unit(random);
    if (difference_between(compiled, parameters, t, t + period, random) > 1e-9) return false;
  }
  return true;
}

}  // namespace

TimeDependence time_dependence(const System& system, const EquationsOfMotion& eq) {
  TimeDependence out;
  const GiNaC::realsymbol& t = system.time();
  for (const Entry& entry : entries(system, eq)) {
    if (!entry.value.has(t) || identically_zero(derivative(entry.value, t))) continue;
    out.depends = true;
    std::string elsewhere;
    collect(entry.value, entry.value, system, out.frequencies, elsewhere);
    if (!elsewhere.empty() && out.not_periodic.empty()) {
      out.not_periodic = elsewhere + ", in " + entry.where;
    }
  }
  if (!out.depends) out.frequencies.clear();
  // each function once
  std::vector<TimeDependence::Frequency> unique;
  for (const TimeDependence::Frequency& f : out.frequencies) {
    if (std::none_of(unique.begin(), unique.end(),
                     [&](const auto& u) { return u.source == f.source; })) {
      unique.push_back(f);
    }
  }
  // in the order of their texts: GiNaC's order of terms changes from run to run
  std::sort(unique.begin(), unique.end(),
            [](const auto& a, const auto& b) { return a.source < b.source; });
  out.frequencies = std::move(unique);
  return out;
}

bool changes_with_t(const CompiledSystem& compiled, const std::vector<double>& parameters) {
  std::mt19937_64 random(20261128u);
  for (const double later : {0.7236067977499790, 2.6457513110645906, 9.8696044010893586}) {
    if (difference_between(compiled, parameters, 0.0, later, random) > 1e-9) return true;
  }
  return false;
}

std::optional<DrivePeriod> drive_period(const System& system, const CompiledSystem& compiled,
                                        const TimeDependence& dependence,
                                        const std::vector<double>& parameters,
                                        std::optional<double> given) {
  if (given) {
    if (!(std::isfinite(*given) && *given > 0.0)) {
      throw NotPeriodic("--period " + detail::to_short_text(*given) +
                        ": expected a positive number of seconds");
    }
    if (!repeats_after(compiled, parameters, *given)) {
      throw NotPeriodic("--period " + detail::to_short_text(*given) +
                        ": the equations of motion are not the same at t and t + " +
                        detail::to_short_text(*given) + " (compared at random states)");
    }
    return DrivePeriod{*given, "given (--period)", true};
  }
  if (!dependence.not_periodic.empty()) {
    throw NotPeriodic("the equations of motion depend on t, and not periodically: t appears in " +
                      dependence.not_periodic +
                      ", outside sin, cos and tan of a multiple of t; the motion has no period "
                      "to analyse it over, and at one instant it would be frozen (if it is "
                      "periodic all the same, give the period with --period T)");
  }
  // The frequencies at the parameters' values; those that are 0 drive nothing.
  const GiNaC::exmap values = system.parameter_values(parameters);
  std::vector<double> omega;
  std::vector<std::string> sources;
  for (const TimeDependence::Frequency& f : dependence.frequencies) {
    const std::optional<double> w = real_value(f.omega, values);
    if (!w || !std::isfinite(*w)) {
      throw NotPeriodic("the frequency " + to_text(f.omega) + " of " + f.source +
                        " is not a real number at the parameters' values");
    }
    if (*w == 0.0) continue;
    omega.push_back(std::abs(*w));
    sources.push_back(f.source);
  }
  if (omega.empty()) return std::nullopt;
  // ω_k = ω_1 n_k / L, then ω₀ = ω_1 gcd(n_k) / L.
  std::vector<std::pair<long long, long long>> ratios;
  long long L = 1;
  for (std::size_t k = 0; k < omega.size(); ++k) {
    const auto r = fraction(omega[k] / omega[0]);
    if (!r) {
      throw NotPeriodic("the equations of motion depend on t through " + sources[0] + " and " +
                        sources[k] + ", whose frequencies " + detail::to_short_text(omega[0]) +
                        " and " + detail::to_short_text(omega[k]) +
                        " are not commensurate: the motion is quasi-periodic, with no period to "
                        "analyse it over (give one with --period T if you know it)");
    }
    ratios.push_back(*r);
    L = std::lcm(L, r->second);
  }
  long long g = 0;
  for (const auto& [p, q] : ratios) g = std::gcd(g, p * (L / q));
  const double fundamental = omega[0] * static_cast<double>(g) / static_cast<double>(L);
  DrivePeriod out{2.0 * std::numbers::pi / fundamental, ""};
  out.how = "2 pi/omega, omega = " + detail::to_short_text(fundamental) +
            " the fundamental frequency of ";
  for (std::size_t k = 0; k < sources.size(); ++k) {
    out.how += (k == 0 ? "" : k + 1 == sources.size() ? " and " : ", ") + sources[k];
  }
  if (!repeats_after(compiled, parameters, out.period)) {
    throw NotPeriodic("the equations of motion are not the same at t and t + " +
                      detail::to_short_text(out.period) + " (" + out.how +
                      "), compared at random states: the period cannot be trusted");
  }
  return out;
}

}  // namespace unidyn
