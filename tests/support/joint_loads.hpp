// A joint's closed-form Lagrange representation (8.23) against the f and h solved from each of its
// rows ∂Ψ/∂q alone (kinematics/constraint_gradient), at one state of the coordinates.
#pragma once

#include <gtest/gtest.h>

#include "unidyn/kinematics/constraint_gradient.hpp"
#include "unidyn/model/system.hpp"

namespace unidyn::test {

inline void expect_joint_loads_match_rows(const System& system) {
  GiNaC::exmap state = system.parameter_values();
  double value = 0.3;
  for (const auto& q : system.coordinates()) state[q.value] = value += 0.17;
  const auto number = [&](const Expr& e) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(state))).to_double();
  };
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    if (system.constraints[k].parametrisation) continue;
    ASSERT_FALSE(system.constraints[k].loads.empty()) << system.constraints[k].name;
    const ConstraintLoads closed = constraint_loads(system, k);
    const ConstraintLoads solved = solve_constraint_loads(system, constraint_row(system, k));
    for (std::size_t b = 0; b < system.bodies.size(); ++b) {
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(number(closed.body_force[b][i]), number(solved.body_force[b][i]), 1e-13)
            << system.constraints[k].name << " on " << system.bodies[b].name;
        EXPECT_NEAR(number(closed.body_moment[b][i]), number(solved.body_moment[b][i]), 1e-13)
            << system.constraints[k].name << " on " << system.bodies[b].name;
      }
    }
  }
}

}  // namespace unidyn::test
