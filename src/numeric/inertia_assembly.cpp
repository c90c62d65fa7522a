// M = Σ Jᵀ W J and c = Σ Jᵀ h from the partial velocities.
#include "unidyn/numeric/inertia_assembly.hpp"

#include <algorithm>

namespace unidyn {

InertiaAssembly::InertiaAssembly(const std::vector<PartialVelocityTerm>& terms,
                                 std::size_t coordinates)
    : n_(coordinates) {
  for (const PartialVelocityTerm& t : terms) {
    Term term;
    term.rotation = t.inertia.has_value();
    term.first_column = columns_.size();
    term.columns = t.columns.size();
    columns_.insert(columns_.end(), t.columns.begin(), t.columns.end());
    term.contiguous = t.columns.back() - t.columns.front() + 1 == t.columns.size();
    term.offset = outputs_.size();
    // W: m, or J0 row by row
    if (term.rotation) {
      for (unsigned i = 0; i < 3; ++i) {
        for (unsigned j = 0; j < 3; ++j) outputs_.push_back((*t.inertia)(i, j));
      }
      scratch_ = std::max(scratch_, 3 * term.columns);
    } else {
      outputs_.push_back(t.mass);
    }
    // J's rows: a rotation's W mixes them, so all three; a point's rows of zeros are left out
    for (int r = 0; r < 3; ++r) {
      const bool zero = std::all_of(t.partial_velocity.begin(), t.partial_velocity.end(),
                                    [r](const VectorExpr& v) { return v[r].is_zero(); });
      if (zero && !term.rotation) continue;
      term.rows.push_back(r);
      for (const VectorExpr& v : t.partial_velocity) outputs_.push_back(v[r]);
    }
    for (int r = 0; r < 3; ++r) outputs_.push_back(t.inertia_force[r]);
    terms_.push_back(std::move(term));
  }
}

namespace {

// Row a of the upper triangle: M_ab += Σ_r s_r K_r[b] for b ≥ a over the R rows of K, one pass;
// with contiguous columns the row of M is contiguous and the loop vectorises.
template <int R>
void add_row(double* M_row, const std::size_t* columns, bool contiguous, std::size_t a,
             std::size_t k, const double* s, const double* const* K) {
  if (contiguous) {
    double* out = M_row + columns[0];
    for (std::size_t b = a; b < k; ++b) {
      double sum = s[0] * K[0][b];
      for (int r = 1; r < R; ++r) sum += s[r] * K[r][b];
      out[b] += sum;
    }
    return;
  }
  for (std::size_t b = a; b < k; ++b) {
    double sum = s[0] * K[0][b];
    for (int r = 1; r < R; ++r) sum += s[r] * K[r][b];
    M_row[columns[b]] += sum;
  }
}

// One term with R rows of J (and of K = W J, or J itself for a point, whose m is in `weight`):
// M += Jᵀ K over the upper triangle, c += Jᵀ h.
template <int R>
void add_term(double* M, double* c, std::size_t n, const std::size_t* columns, bool contiguous,
              std::size_t k, const double* const* J, const double* const* K, const double* h,
              double weight) {
  for (std::size_t a = 0; a < k; ++a) {
    double s[R];
    double ca = 0.0;
    for (int r = 0; r < R; ++r) {
      s[r] = weight * J[r][a];
      ca += J[r][a] * h[r];
    }
    add_row<R>(M + columns[a] * n, columns, contiguous, a, k, s, K);
    c[columns[a]] += ca;
  }
}

}  // namespace

void InertiaAssembly::assemble(const double* values, double* M, double* c,
                               std::span<double> scratch) const {
  std::fill(M, M + n_ * n_, 0.0);
  std::fill(c, c + n_, 0.0);
  for (const Term& term : terms_) {
    const std::size_t k = term.columns;
    const std::size_t* columns = columns_.data() + term.first_column;
    const double* v = values + term.offset;
    const double* W = v;
    v += term.rotation ? 9 : 1;
    // J's rows evaluated (a point's rows of zeros left out), then h's three components
    const double* J[3] = {nullptr, nullptr, nullptr};
    const std::size_t R = term.rows.size();
    for (std::size_t i = 0; i < R; ++i) {
      J[i] = v;
      v += k;
    }
    double h[3] = {0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < R; ++i) h[i] = v[term.rows[i]];
    const double* K[3] = {J[0], J[1], J[2]};
    double weight = W[0];
    if (term.rotation) {
      // K = J0 J, three rows
      for (std::size_t i = 0; i < 3; ++i) {
        double* K_i = scratch.data() + i * k;
        for (std::size_t b = 0; b < k; ++b) {
          K_i[b] = W[3 * i] * J[0][b] + W[3 * i + 1] * J[1][b] + W[3 * i + 2] * J[2][b];
        }
        K[i] = K_i;
      }
      weight = 1.0;
    }
    switch (R) {
      case 1:
        add_term<1>(M, c, n_, columns, term.contiguous, k, J, K, h, weight);
        break;
      case 2:
        add_term<2>(M, c, n_, columns, term.contiguous, k, J, K, h, weight);
        break;
      default:
        add_term<3>(M, c, n_, columns, term.contiguous, k, J, K, h, weight);
        break;
    }
  }
  // the lower triangle from the upper
  for (std::size_t i = 0; i < n_; ++i) {
    for (std::size_t j = 0; j < i; ++j) M[i * n_ + j] = M[j * n_ + i];
  }
}

}  // namespace unidyn
