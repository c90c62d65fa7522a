// Lagrange–Dirichlet and Routh: the Hessian of the (amended) potential on the constraints.
#include "energy_minimum.hpp"

#include "eigen_decomposition.hpp"

#include <algorithm>

namespace unidyn {

using Eigen::Index;
using Eigen::MatrixXd;

std::optional<bool> energy_minimum(const Linearization& L, const OperatingPoint& point,
                                   const std::vector<Index>& cyclic, const MatrixXd& momentum_q) {
  const auto n = static_cast<Index>(point.q.size());
  const auto is_cyclic = [&](Index i) {
    return std::find(cyclic.begin(), cyclic.end(), i) != cyclic.end();
  };
  if (L.velocity_constraints) return std::nullopt;
  for (Index i = 0; i < n; ++i) {
    if (point.qdot[i] != 0.0 && !is_cyclic(i)) return std::nullopt;
    if (is_cyclic(i) &&
        std::find(L.ignorable.begin(), L.ignorable.end(),
                  L.coordinates[static_cast<std::size_t>(i)]) == L.ignorable.end()) {
      return std::nullopt;
    }
  }
  // δq = P ξ over the independent coordinates kept (the cyclic ones are dropped as ignorable)
  std::vector<Index> kept_positions;
  for (std::size_t j = 0; j < L.kept.size(); ++j) {
    if (!L.state[j].starts_with("der(")) kept_positions.push_back(L.kept[j]);
  }
  const MatrixXd P = L.to_coordinates.topRows(n)(Eigen::all, kept_positions);
  MatrixXd K = L.all_coordinates.K;
  // (Routh) the rates of the cyclic coordinates change with r so as to keep their momenta
  if (!cyclic.empty()) {
    const MatrixXd M_ss = L.all_coordinates.M(cyclic, cyclic);
    const MatrixXd rates_q = -M_ss.ldlt().solve(momentum_q);
    K += L.all_coordinates.C(Eigen::all, cyclic) * rates_q;
  }
  const MatrixXd H = P.transpose() * K * P;
  const double size = H.size() ? H.cwiseAbs().maxCoeff() : 0.0;
  if (H.size() == 0 || (H - H.transpose()).cwiseAbs().maxCoeff() > 1e-9 * size) {
    return std::nullopt;
  }
  return symmetric_eigenvalues(0.5 * (H + H.transpose())).minCoeff() > 1e-9 * size;
}

}  // namespace unidyn
