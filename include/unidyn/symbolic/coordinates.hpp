// Generalised coordinates as symbols, and the total time derivative (book (1.7)–(1.8)).
#pragma once

#include <string>
#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// The symbols of one generalised coordinate q: q itself, its rate der(q) and its acceleration.
// Where a name's trailing digits begin (its size when it has none, or is all digits): they are
// printed as a subscript in LaTeX, m1 as m_{1}.
std::size_t subscript_start(const std::string& name);

// A name in LaTeX: Greek names as Greek (theta → \theta), trailing digits as a subscript
// (theta1 → \theta_{1}), what follows an underscore too (mu_d → \mu_{d}), other names of several
// letters upright (\mathrm{Rw}).
std::string latex_name(const std::string& name);

struct CoordinateSymbols {
  std::string name;
  GiNaC::realsymbol value;
  GiNaC::realsymbol rate;
  GiNaC::realsymbol acceleration;

  // Symbols printed as q, q' and q'' in text and as q, \dot{q}, \ddot{q} in LaTeX.
  explicit CoordinateSymbols(const std::string& coordinate_name);
};

// The coordinates of a system and time: enough to differentiate any expression along a motion.
class Configuration {
 public:
  Configuration();

  // Adds a coordinate; returns its index.
  std::size_t add(const std::string& name);
  // The same configuration without coordinate k: same symbols, same time.
  Configuration without(std::size_t k) const;

  const std::vector<CoordinateSymbols>& coordinates() const { return coordinates_; }
  std::size_t size() const { return coordinates_.size(); }
  const GiNaC::realsymbol& time() const { return time_; }

  // (1.7)–(1.8) total time derivative along a motion q(t):
  //   ḟ = ∂f/∂t + Σ ∂f/∂q^i q̇^i + Σ ∂f/∂q̇^i q̈^i.
  Expr total_derivative(const Expr& f) const;
  VectorExpr total_derivative(const VectorExpr& v) const;

  // The part of ḟ without q̈, for f free of q̇'s rates' rates: ∂f/∂t + Σ ∂f/∂q^i q̇^i (what
  // total_derivative(f) becomes at q̈ = 0, without forming the q̈ terms).
  Expr convective_derivative(const Expr& f) const;

  // The substitution q̈ ↦ 0 for every coordinate: what is left of an expression linear in q̈.
  GiNaC::exmap zero_accelerations() const;

 private:
  std::vector<CoordinateSymbols> coordinates_;
  GiNaC::realsymbol time_;
};

}  // namespace unidyn
