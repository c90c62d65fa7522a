// Whether an operating point stays what it is: an equilibrium or a steady motion keeps the same
// linearised equations as time goes on. Two ways it may not, which the values at the point alone
// do not show (analysis/linearization.hpp checks them before it answers):
//   - the equations change with t (a driven support: cos Ωt, whose ∂/∂t is 0 at t = 0);
//   - a coordinate the equations depend on moves with the point: a crank turned at a constant rate
//     by the constraint ψ − Ωt = 0 (ψ is then a dependent coordinate, not among the state's, and
//     the equations have no t in them at all).
#pragma once

#include <string>
#include <vector>

#include "reduced_system.hpp"

namespace unidyn::detail {

// q̈ and F over the kept states (those not ignorable: the ignorable coordinates' own rows may turn
// with the motion) compared at three more instants (apart by amounts no period divides them all
// by), at the same q and q̇. Throws NotAnOperatingPoint when they differ.
void expect_the_same_at_other_instants(const CompiledSystem& compiled, const OperatingPoint& point,
                                       const ReducedSystem& at,
                                       const std::vector<Eigen::Index>& kept,
                                       double acceleration_tolerance,
                                       const std::vector<std::string>& names);

// When something moves at the point other than the ignorable coordinates (`dropped` states, on
// which F does not depend: moving them changes nothing the linearisation sees — the kept ones are
// at rest, checked before): the motion followed for the time its fastest coordinate takes to move
// by 1 (a radian, a metre), and F along it compared with F at the point (to 1e-6 of its largest
// entry: the integration's error is far below, a moving crank's change far above), over the kept
// states. Throws NotAnOperatingPoint when it changes.
void expect_steady_along_the_motion(const CompiledSystem& compiled, const OperatingPoint& point,
                                    const ReducedSystem& at, const std::vector<Eigen::Index>& kept,
                                    const std::vector<Eigen::Index>& dropped,
                                    const std::vector<std::string>& names);

}  // namespace unidyn::detail
