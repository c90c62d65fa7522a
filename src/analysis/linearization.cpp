// Linearisation about an operating point in independent coordinates and speeds.
#include "unidyn/analysis/linearization.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "reduced_system.hpp"
#include "steadiness.hpp"
#include "unidyn/numeric/number_text.hpp"

namespace unidyn {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using namespace detail;

namespace {

// The kept coordinates at rest: one that moves at the point, where the equations depend on it,
// does not stay where it is.
void expect_kept_at_rest(const ReducedSystem& at, const OperatingPoint& point,
                         const Linearization& out, const std::vector<std::string>& names) {
  const double rate_tolerance = kNegligible * (1.0 + largest(point.qdot));
  const Index s1 = at.P_q.cols();
  for (const Index k : out.kept) {
    if (k >= s1) continue;
    const Index i = at.choice.independent_q[static_cast<std::size_t>(k)];
    if (std::abs(point.qdot[i]) > rate_tolerance) {
      const std::string& name = names[static_cast<std::size_t>(i)];
      throw NotAnOperatingPoint(rate_name(name) + " = " + detail::to_short_text(point.qdot[i]) +
                                " at the point, and the equations depend on " + name +
                                " (it is not ignorable): not an equilibrium or a steady motion; "
                                "give " +
                                rate_name(name) + "=0 with --at");
    }
  }
}

// The independent rates steady: no acceleration (the forces balance), none from t either; the
// tolerance, relative to the forces at play, is returned.
double expect_balanced(const ReducedSystem& at, const OperatingPoint& point,
                       const std::vector<std::string>& names) {
  const double force_scale = (largest(at.f) + largest(at.A_all.transpose() * point.lambda)) /
                             std::max(largest(at.M.diagonal()), 1e-300);
  const double acceleration_tolerance = 1e-8 * (1.0 + force_scale);
  for (const Index i : at.choice.independent_u) {
    const std::string& name = names[static_cast<std::size_t>(i)];
    if (std::abs(point.qddot[i]) > acceleration_tolerance) {
      throw NotAnOperatingPoint("the acceleration of " + name + " is " +
                                detail::to_short_text(point.qddot[i]) +
                                " at the point: the forces do not balance there, so it is not an "
                                "equilibrium or a steady motion");
    }
    if (std::abs(at.D(i, 0)) > acceleration_tolerance) {
      throw NotAnOperatingPoint("the equations change with t at the point (the acceleration of " +
                                name + " does): it is not an equilibrium or a steady motion");
    }
  }
  return acceleration_tolerance;
}

// A unilateral contact that holds must push (λ ≥ 0, integrate/contacts.hpp): one that would pull
// is lost at once.
void expect_contacts_push(const System& system, const OperatingPoint& point, Index m) {
  for (Index k = 0; k < m; ++k) {
    const Constraint& c = system.constraints[static_cast<std::size_t>(k)];
    if (c.unilateral && point.active[static_cast<std::size_t>(k)] &&
        point.lambda[k] < -1e-9 * (1.0 + largest(point.lambda))) {
      throw NotAnOperatingPoint("the unilateral constraint '" + c.name + "' would have to pull " +
                                "there (lambda = " + detail::to_short_text(point.lambda[k]) +
                                " < 0): the contact is lost at once, so it is not an equilibrium "
                                "or a steady motion");
    }
  }
}

}  // namespace

Linearization linearize(const System& system, const CompiledSystem& compiled,
                        const OperatingPoint& point) {
  const auto n = static_cast<Index>(compiled.coordinate_count());
  const auto m = static_cast<Index>(compiled.constraint_count());
  std::vector<std::string> names;
  for (const auto& q : system.coordinates()) names.push_back(q.name);
  const ReducedSystem at = reduced_system(compiled, point, nullptr);

  // 4.–5. The state, its matrix, and the ignorable coordinates dropped: judged here and at a state
  // nearby (where an influence that vanishes only at the point, as at a bifurcation, shows); with
  // no state nearby, none is dropped.
  const std::optional<OperatingPoint> near = nearby_state(system, compiled, point, at);
  std::vector<MatrixXd> samples;
  if (near) samples = {at.F, reduced_system(compiled, *near, &at.choice).F};
  Linearization out = reduced_linearization(system, at, samples);

  // The point must stay where it is: kept coordinates at rest, independent rates steady, the
  // equations the same at the next instant, the contacts pushing.
  expect_kept_at_rest(at, point, out, names);
  const double acceleration_tolerance = expect_balanced(at, point, names);
  expect_the_same_at_other_instants(compiled, point, at, out.kept, acceleration_tolerance, names);
  expect_steady_along_the_motion(compiled, point, at, out.kept, out.dropped, names);
  expect_contacts_push(system, point, m);

  // M, C and K in all coordinates; without constraints, the equations themselves.
  out.all_coordinates =
      SecondOrderForm{at.M, at.balance.middleCols(1 + n, n), at.balance.middleCols(1, n)};
  if (m == 0) out.second_order = out.all_coordinates;
  for (Index k = 0; k < m; ++k) {
    out.velocity_constraints = out.velocity_constraints ||
                               (point.active[static_cast<std::size_t>(k)] &&
                                !compiled.is_position_constraint()[static_cast<std::size_t>(k)]);
  }
  return out;
}

}  // namespace unidyn
