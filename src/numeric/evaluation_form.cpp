// Small entries of the equations simplified for evaluation.
#include "unidyn/numeric/evaluation_form.hpp"

#include <vector>

#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

// Whether e has at most `budget` nodes, counted over GiNaC's operands; stops as soon as it has
// more (a long chain's forcing has millions).
bool has_at_most_nodes(const Expr& e, std::size_t& budget) {
  if (budget == 0) return false;
  --budget;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    if (!has_at_most_nodes(e.op(i), budget)) return false;
  }
  return true;
}

// e, or its simplification when e is small and that is smaller.
Expr evaluation_entry(const Expr& e) {
  std::size_t budget = kEvaluationSimplifyNodes;
  if (!has_at_most_nodes(e, budget) || expanded_terms_bound(e) > kEvaluationSimplifyTerms) {
    return e;
  }
  const Expr simplified = simplify(e);
  return expression_size(simplified) < expression_size(e) ? simplified : e;
}

void simplify_entries(std::vector<Expr>& entries) {
  for (Expr& e : entries) e = evaluation_entry(e);
}

}  // namespace

EquationsOfMotion evaluation_form(const EquationsOfMotion& eq) {
  EquationsOfMotion form = eq;
  for (std::vector<Expr>* entries :
       {&form.mass_matrix.data, &form.forcing, &form.constraint_matrix.data,
        &form.constraint_velocity_term, &form.constraint_bias, &form.constraint_position}) {
    simplify_entries(*entries);
  }
  return form;
}

}  // namespace unidyn
