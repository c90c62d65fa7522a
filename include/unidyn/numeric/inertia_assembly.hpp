// Kane's mass matrix and convective terms assembled numerically from the partial velocities
// (equations/lagrange.hpp PartialVelocityTerm, book (10.16)):
//
//   M = Σ Jᵀ W J,   c = Σ Jᵀ h      (f = Φ − ∂U/∂q − c)
//
// over the particles (W = m I) and the bodies' rotations (W = J0). The tape evaluates each
// term's numbers — m or J0, the rows of J, h — and the sums here cost 3 k² multiply-adds for a
// term with k columns. For a chain of n links the symbolic M has O(n⁴) terms in relative angles;
// the partial velocities O(n³), and their products here O(n³) multiply-adds that vectorise.
#pragma once

#include <span>
#include <vector>

#include "unidyn/equations/lagrange.hpp"

namespace unidyn {

class InertiaAssembly {
 public:
  InertiaAssembly(const std::vector<PartialVelocityTerm>& terms, std::size_t coordinates);

  // The expressions the tape evaluates, in the order assemble() reads their values: per term,
  // m (a point) or J0 row by row (a rotation), then J row by row over the term's columns (a
  // point's rows of zeros left out), then h.
  const std::vector<Expr>& outputs() const { return outputs_; }
  // The scratch assemble() needs (a rotation's W J).
  std::size_t scratch_size() const { return scratch_; }

  // M (n × n, row-major, both triangles) and c (n) from the values of outputs().
  void assemble(const double* values, double* M, double* c, std::span<double> scratch) const;

 private:
  struct Term {
    bool rotation = false;
    std::size_t first_column = 0, columns = 0;  // into columns_
    bool contiguous = false;                    // columns j0, j0 + 1, …
    std::vector<int> rows;                      // the components of J evaluated
    std::size_t offset = 0;                     // of its first value
  };
  std::size_t n_;
  std::vector<Expr> outputs_;
  std::vector<std::size_t> columns_;
  std::vector<Term> terms_;
  std::size_t scratch_ = 0;
};

}  // namespace unidyn
