// Coordinate symbols and the total time derivative.
#include "unidyn/symbolic/coordinates.hpp"
#include "unidyn/symbolic/derivative.hpp"

#include <cctype>

namespace unidyn {

std::size_t subscript_start(const std::string& name) {
  std::size_t digits = name.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(name[digits - 1]))) --digits;
  return digits == 0 ? name.size() : digits;
}

// GiNaC prints a symbol's LaTeX name verbatim; Greek names get a backslash, trailing digits a
// subscript, other names of several letters \mathrm.
std::string latex_name(const std::string& name) {
  static const char* const greek[] = {
      "alpha",   "beta",   "gamma", "delta",   "epsilon", "zeta",  "eta",   "theta", "iota",
      "kappa",   "lambda", "mu",    "nu",      "xi",      "pi",    "rho",   "sigma", "tau",
      "upsilon", "phi",    "chi",   "psi",     "omega",   "Gamma", "Delta", "Theta", "Lambda",
      "Xi",      "Pi",     "Sigma", "Upsilon", "Phi",     "Psi",   "Omega"};
  for (const char* g : greek) {
    if (name == g) return std::string("\\") + name;
  }
  // mu_d → \mu_{d}
  if (const std::size_t underscore = name.find('_');
      underscore != std::string::npos && underscore > 0 && underscore + 1 < name.size()) {
    return latex_name(name.substr(0, underscore)) + "_{" + latex_name(name.substr(underscore + 1)) +
           "}";
  }
  // x1 → x_{1}
  const std::size_t digits = subscript_start(name);
  if (digits < name.size()) {
    return latex_name(name.substr(0, digits)) + "_{" + name.substr(digits) + "}";
  }
  if (name.size() > 1) return "\\mathrm{" + name + "}";
  return name;
}

namespace {

// \dot{θ}_{1} for θ1: the accent on the name, the subscript after it.
std::string accented(const char* accent, const std::string& name) {
  const std::size_t digits = subscript_start(name);
  const std::string base = std::string(accent) + "{" + latex_name(name.substr(0, digits)) + "}";
  return digits < name.size() ? base + "_{" + name.substr(digits) + "}" : base;
}

}  // namespace

CoordinateSymbols::CoordinateSymbols(const std::string& coordinate_name)
    : name(coordinate_name),
      value(GiNaC::realsymbol(coordinate_name, latex_name(coordinate_name))),
      rate(GiNaC::realsymbol(coordinate_name + "'", accented("\\dot", coordinate_name))),
      acceleration(GiNaC::realsymbol(coordinate_name + "''", accented("\\ddot", coordinate_name))) {
}

Configuration::Configuration() : time_(GiNaC::realsymbol("t")) {}

std::size_t Configuration::add(const std::string& name) {
  coordinates_.emplace_back(name);
  return coordinates_.size() - 1;
}

Configuration Configuration::without(std::size_t k) const {
  Configuration reduced = *this;
  reduced.coordinates_.erase(reduced.coordinates_.begin() + static_cast<std::ptrdiff_t>(k));
  return reduced;
}

Expr Configuration::total_derivative(const Expr& f) const {
  // (1.8) ḟ = ∂f/∂t + Σ ∂f/∂q q̇ + Σ ∂f/∂q̇ q̈
  std::vector<Expr> x{time_};
  for (const auto& q : coordinates_) {
    x.push_back(q.value);
    x.push_back(q.rate);
  }
  const std::vector<Expr> g = gradient(f, x);
  Expr result = g[0];
  for (std::size_t k = 0; k < coordinates_.size(); ++k) {
    result += g[1 + 2 * k] * coordinates_[k].rate + g[2 + 2 * k] * coordinates_[k].acceleration;
  }
  return result;
}

Expr Configuration::convective_derivative(const Expr& f) const {
  std::vector<Expr> x{time_};
  for (const auto& q : coordinates_) x.push_back(q.value);
  const std::vector<Expr> g = gradient(f, x);
  Expr result = g[0];
  for (std::size_t k = 0; k < coordinates_.size(); ++k) result += g[1 + k] * coordinates_[k].rate;
  return result;
}

VectorExpr Configuration::total_derivative(const VectorExpr& v) const {
  return {total_derivative(v[0]), total_derivative(v[1]), total_derivative(v[2])};
}

GiNaC::exmap Configuration::zero_accelerations() const {
  GiNaC::exmap map;
  for (const auto& q : coordinates_) map[q.acceleration] = 0;
  return map;
}

}  // namespace unidyn
