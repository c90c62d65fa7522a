// The symbols expressions hold, found in one walk.
#include "unidyn/symbolic/symbols_in.hpp"

#include "unidyn/symbolic/expairs.hpp"

namespace unidyn {

void SymbolsIn::walk(const Expr& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    symbols_.insert(e);
    return;
  }
  if (e.nops() == 0 || !seen_.insert(&GiNaC::ex_to<GiNaC::basic>(e)).second) return;
  held_.push_back(e);  // (op() may make a node anew: held, its address is not reused)
  // a sum's terms and a product's factors as GiNaC keeps them (their coefficients are numbers)
  if (GiNaC::is_exactly_a<GiNaC::add>(e) || GiNaC::is_exactly_a<GiNaC::mul>(e)) {
    for (const GiNaC::expair& part : expairs(e)) walk(part.rest);
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) walk(e.op(i));
}

}  // namespace unidyn
