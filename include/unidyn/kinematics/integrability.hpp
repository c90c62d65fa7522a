// Whether velocity constraints are integrable (book §1.7, (1.19)–(1.21); §8.4, (8.11)–(8.18)).
//
// A constraint a(q, t) · q̇ + e(q, t) = 0 is the Pfaffian form Σ_J W_J dU^J = 0 on U = (q^1..q^n,
// t), W = (a_1, .., a_n, e). With S_LK = ∂W_L/∂U^K − ∂W_K/∂U^L it is integrable (some k(U) W = ∇Ψ)
// iff
//   I_JKL = W_J S_LK + W_K S_JL + W_L S_KJ = 0   for all J < K < L          (1.21), (8.11)–(8.13)
// (Jacobi's test (1.19) f · rot f = 0 when n = 3 and e = 0). A set of R constraints W_A is
// integrable as a whole iff (Frobenius, Theorem 2 of §8.4)
//   aᵀ S^A b = 0   for A = 1..R and all a, b in ker W                       (8.18)
// — it can be although none of its members is ((1.23)). Position constraints are integrable.
#pragma once

#include <string>
#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

struct Integrability {
  bool integrable = true;
  // For a non-integrable constraint or set: one non-zero I_JKL or aᵀ S^A b, and what it is.
  std::string witness;
  Expr value = 0;
};

// (1.21) for constraint k of the system.
Integrability constraint_integrability(const System& system, std::size_t k);

// (8.18) for the constraints ks taken together (they must be independent: else, or when their
// rows hold more than kLargestSetIntegrabilityTest nodes, std::invalid_argument says why not).
inline constexpr std::size_t kLargestSetIntegrabilityTest = 1500;
Integrability set_integrability(const System& system, const std::vector<std::size_t>& ks);

}  // namespace unidyn
