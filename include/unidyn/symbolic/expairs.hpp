// The pairs GiNaC keeps a sum or a product as, read where they are.
//
// A sum Σ c_k r_k + c₀ is kept as the pairs (r_k, c_k) and the overall coefficient c₀; a product
// c₀ Π r_k^c_k as the pairs (r_k, c_k) and c₀. GiNaC's op(k) makes the k-th term or factor anew at
// each call (c_k r_k is a new product, evaluated): a walk that only looks reads the pairs instead.
// They are protected members of GiNaC::expairseq, reached through a pointer to member formed in a
// derived class (standard C++: nothing is instantiated or cast).
#pragma once

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {
namespace detail {

struct ExpairseqMembers : GiNaC::expairseq {
  static const GiNaC::epvector& pairs(const GiNaC::expairseq& s) {
    return s.*(&ExpairseqMembers::seq);
  }
  static const Expr& overall(const GiNaC::expairseq& s) {
    return s.*(&ExpairseqMembers::overall_coeff);
  }
};

}  // namespace detail

// The pairs (rest, coefficient) of a sum or a product (GiNaC::is_a<GiNaC::expairseq>(e)).
inline const GiNaC::epvector& expairs(const Expr& e) {
  return detail::ExpairseqMembers::pairs(GiNaC::ex_to<GiNaC::expairseq>(e));
}

// Its overall coefficient: a sum's number term (0 if none), a product's number factor (1 if none).
inline const Expr& overall_coefficient(const Expr& e) {
  return detail::ExpairseqMembers::overall(GiNaC::ex_to<GiNaC::expairseq>(e));
}

}  // namespace unidyn
