// The generalised impulses of an applied impulse (11.15).
#include "unidyn/equations/impulses.hpp"

namespace unidyn {

std::vector<Expr> generalized_impulses(const System& system, const AppliedImpulse& impulse) {
  std::vector<Expr> phi;
  for (const auto& q : system.coordinates()) {
    phi.push_back(dot(impulse.impulse, diff(impulse.point, q.value)));
  }
  return phi;
}

}  // namespace unidyn
