// M, C and K in closed form at an exact operating point.
#include "unidyn/analysis/exact_linearization.hpp"

#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {

bool has_float(const Expr& e) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) return !e.info(GiNaC::info_flags::crational);
  for (std::size_t k = 0; k < e.nops(); ++k) {
    if (has_float(e.op(k))) return true;
  }
  return false;
}

std::optional<ExactSecondOrder> exact_second_order(const System& system,
                                                   const EquationsOfMotion& equations,
                                                   const std::vector<GivenValue>& given) {
  if (!system.constraints.empty()) return std::nullopt;
  // the point: the values given, every other coordinate and rate 0
  GiNaC::exmap point;
  for (const auto& q : system.coordinates()) {
    point[q.value] = 0;
    point[q.rate] = 0;
  }
  for (const GivenValue& g : given) {
    if (has_float(g.value)) return std::nullopt;
    const auto [i, rate] = *state_value(system, g.name);
    point[rate ? system.coordinates()[i].rate : system.coordinates()[i].value] = g.value;
  }
  const auto& q = system.coordinates();
  const std::size_t n = q.size();
  ExactSecondOrder out{ExprMatrix(n, n), ExprMatrix(n, n), ExprMatrix(n, n)};
  // C = −∂F/∂q̇ and K = −∂F/∂q, each row in one walk through F_i (rates first, then values)
  std::vector<Expr> directions;
  for (const auto& c : q) directions.push_back(c.rate);
  for (const auto& c : q) directions.push_back(c.value);
  std::vector<Expr> entries;
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<Expr> dF = gradient(equations.forcing[i], directions);
    for (std::size_t j = 0; j < n; ++j) {
      entries.push_back(equations.mass_matrix(i, j).subs(point));
      entries.push_back(-dF[j].subs(point));
      entries.push_back(-dF[n + j].subs(point));
    }
  }
  const std::vector<Expr> simplified = simplify_all(entries);
  for (std::size_t i = 0, k = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j, k += 3) {
      out.M(i, j) = simplified[k];
      out.C(i, j) = simplified[k + 1];
      out.K(i, j) = simplified[k + 2];
    }
  }
  return out;
}

}  // namespace unidyn
