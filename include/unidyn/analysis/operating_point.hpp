// An operating point: the state a system is linearised about (an equilibrium or a steady motion).
//
// The user names some of its values, NAME=VALUE with NAME a coordinate q or a rate der(q) and
// VALUE a number or an expression in the parameters (`acos(-g/(R0*Omega^2))`, `v/rR`). Every other
// coordinate and rate starts at 0 and is completed from the constraints as a simulation's start is
// (integrate/initial_state.hpp): the values given are kept, the others take the least-norm
// correction that satisfies the constraints, so a value that no constraint needs stays 0. Then q̈
// and λ follow from the equations of motion. Whether the point is an equilibrium or a steady motion
// is for the linearisation to say (analysis/linearization.hpp): it knows which coordinates are
// ignorable.
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "unidyn/model/system.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {

// A value given for the operating point: "phi" or "der(phi)", and its expression.
struct GivenValue {
  std::string name;
  Expr value;
};

struct OperatingPoint {
  double t = 0.0;
  std::vector<double> parameters;
  Eigen::VectorXd q, qdot, qddot, lambda;
  std::vector<bool> q_given, qdot_given;
  // What the completion computed, "name = value" each (coordinates, then rates).
  std::vector<std::string> computed;
  // Unilateral constraints apart at the point (Ψ > 0): they exert nothing and are left out.
  std::vector<bool> active;
  // Where its values come from when not from --at: "the model's initial state" (printed).
  std::string source;
};

// A value of the state a name stands for: coordinate q ("q") or its rate ("der(q)").
struct StateValue {
  std::size_t coordinate;
  bool rate;
};
// The coordinate or rate `name` is, if it is one.
std::optional<StateValue> state_value(const System& system, const std::string& name);

// The coordinate q whose generalised momentum p = ∂T/∂q̇ `name` ("p(q)") is, if it is one (given
// for the steady motions of `unidyn equilibria --cyclic`).
std::optional<std::size_t> momentum_coordinate(const System& system, const std::string& name);

// A double as a given value's expression; a subnormal one (below 2.2e-308, which CLN refuses to
// convert) as 0.
Expr given_number(double x);

// NAME=VALUE texts (command line) as given values, VALUE parsed in the model's names. Throws
// std::invalid_argument naming the text: no '=', NAME neither a coordinate nor der(coordinate)
// (nor, with `momenta`, p(coordinate)), NAME given twice, or a VALUE that is not an expression in
// the parameters.
std::vector<GivenValue> parse_given_values(const System& system,
                                           const std::vector<std::string>& texts,
                                           bool momenta = false);

// Throws std::invalid_argument when a constraint has friction (a coefficient that is not 0 at the
// parameters' values): stick and slip are not smooth, and the analysis is of smooth equations.
void expect_smooth_contacts(const System& system, const std::vector<double>& parameters);

// The model's initial state as given values: each coordinate and rate its `initial:` gives (at the
// parameters `sets` give), the others left to the completion from the constraints, as a
// simulation's start completes them. The operating point of `linearize` and `modes` without --at.
std::vector<GivenValue> initial_values(const System& system,
                                       const std::vector<std::pair<std::string, double>>& sets);

// The operating point with the given values at the parameters' values. Throws
// std::invalid_argument (bad input) when a value is not a real number, when the constraints cannot
// be satisfied with the values given (InitialStateError: the constraint, its residual), when Euler
// angles are at gimbal lock there, or when a rough contact would need stick–slip; and
// std::runtime_error when the equations cannot be solved for q̈ there (M singular, dependent
// constraints).
OperatingPoint operating_point(const System& system, const CompiledSystem& compiled,
                               const std::vector<GivenValue>& given,
                               const std::vector<double>& parameters);

}  // namespace unidyn
