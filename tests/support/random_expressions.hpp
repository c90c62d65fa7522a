// Random expressions of the book's kinds, for tests that compare two ways of doing one thing.
#pragma once

#include <random>
#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn::test {

inline const GiNaC::realsymbol q1("q1"), q2("q2"), u("u"), m("m"), L("L");

// A random expression of depth ≤ `depth` in q1, q2, u and the parameters m, L: sums, products,
// integer and half powers, sines, cosines, and an exponential and atan2 (left to GiNaC).
inline Expr random_expression(std::mt19937& rng, int depth) {
  const std::vector<Expr> leaves{q1, q2, u, m, L, Expr(2), GiNaC::numeric(1, 3)};
  std::uniform_int_distribution<int> kind(0, depth > 0 ? 8 : 0);
  const auto leaf = [&] {
    return leaves[std::uniform_int_distribution<std::size_t>(0, leaves.size() - 1)(rng)];
  };
  const auto below = [&] { return random_expression(rng, depth - 1); };
  switch (kind(rng)) {
    case 1:
      return below() + below() + below();
    case 2:
      return below() * below() * below();
    case 3:
      return GiNaC::pow(below(), 3);
    case 4:
      return GiNaC::sqrt(below());
    case 5:
      return GiNaC::sin(below());
    case 6:
      return GiNaC::cos(below() - below());
    case 7:
      return GiNaC::exp(below());
    case 8:
      return GiNaC::atan2(below(), below());
    default:
      return leaf();
  }
}

}  // namespace unidyn::test
