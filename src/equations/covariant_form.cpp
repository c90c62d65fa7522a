// The covariant form of Lagrange's equations: convective terms by Christoffel symbols.
#include "unidyn/equations/covariant_form.hpp"

#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/zero_test.hpp"

namespace unidyn {
namespace {

// T's parts linear in the rates and free of them: b_R = ∂T/∂q̇^R and T0 at q̇ = 0.
struct RateFreeParts {
  std::vector<Expr> b;
  Expr T0;
};

RateFreeParts rate_free_parts(const System& system, const Expr& T) {
  GiNaC::exmap at_rest;
  for (const auto& c : system.coordinates()) at_rest[c.rate] = 0;
  std::vector<Expr> rates;
  for (const auto& c : system.coordinates()) rates.push_back(c.rate);
  RateFreeParts parts;
  for (const Expr& p : gradient(T, rates))
    parts.b.push_back(p.subs(at_rest, GiNaC::subs_options::no_pattern));
  parts.T0 = T.subs(at_rest, GiNaC::subs_options::no_pattern);
  return parts;
}

}  // namespace

std::vector<std::optional<Expr>> covariant_convective_terms(const System& system,
                                                            const EquationsOfMotion& eq,
                                                            const ExprMatrix& M) {
  const auto& q = system.coordinates();
  const std::size_t n = q.size();
  const GiNaC::symbol& t = system.time();
  const RateFreeParts parts = rate_free_parts(system, eq.kinetic_energy);
  // ∂M_ij/∂(q^1, …, q^n, t) and ∂b_i/∂(q^1, …, q^n, t), each entry walked through once
  std::vector<Expr> x;
  for (const auto& c : q) x.push_back(c.value);
  x.push_back(t);
  std::vector<std::vector<std::vector<Expr>>> dM(n, std::vector<std::vector<Expr>>(n));
  std::vector<std::vector<Expr>> db(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) dM[i][j] = gradient(M(i, j), x);
    db[i] = gradient(parts.b[i], x);
  }
  // each row and its difference from the derived row's convective part, f_R = Φ_R − ∂U/∂q^R − c_R
  std::vector<Expr> rows_c, differences;
  for (std::size_t R = 0; R < n; ++R) {
    Expr c = 0;
    for (std::size_t K = 0; K < n; ++K) {
      // (4.25): the Christoffel symbols of the first kind, [KS, R] + [SK, R] for K < S
      const Expr diagonal = dM[R][K][K] - dM[K][K][R] / 2;  // [KK, R]
      c += diagonal * q[K].rate * q[K].rate;
      for (std::size_t S = K + 1; S < n; ++S) {
        const Expr symbol = dM[R][K][S] + dM[R][S][K] - dM[K][S][R];
        c += symbol * q[K].rate * q[S].rate;
      }
      // the rheonomic and gyroscopic terms, linear in the rates
      const Expr g = dM[R][K][n] + db[R][K] - db[K][R];
      c += g * q[K].rate;
    }
    c += db[R][n] - derivative(parts.T0, q[R].value);
    const Expr derived =
        eq.generalized_force[R] - derivative(eq.potential_energy, q[R].value) - eq.forcing[R];
    rows_c.push_back(c);
    differences.push_back(derived - c);
  }
  // the rows shown equal by exact evaluation (all at once, shared among processes)
  const std::vector<std::optional<bool>> equal = vanish_identically(differences);
  std::vector<std::optional<Expr>> rows;
  for (std::size_t R = 0; R < n; ++R) {
    rows.push_back(equal[R] == std::optional<bool>(true) ? std::optional<Expr>(rows_c[R])
                                                         : std::nullopt);
  }
  return rows;
}

std::optional<Expr> quadratic_kinetic_energy(const System& system, const EquationsOfMotion& eq,
                                             const ExprMatrix& M) {
  const auto& q = system.coordinates();
  const RateFreeParts parts = rate_free_parts(system, eq.kinetic_energy);
  Expr T = parts.T0;
  for (std::size_t K = 0; K < q.size(); ++K) {
    T += M(K, K) * q[K].rate * q[K].rate / 2 + parts.b[K] * q[K].rate;
    for (std::size_t S = K + 1; S < q.size(); ++S) T += M(K, S) * q[K].rate * q[S].rate;
  }
  if (vanishes_identically(eq.kinetic_energy - T) != std::optional<bool>(true)) return std::nullopt;
  return T;
}

}  // namespace unidyn
