// Virtual work, Gauss's constraint and Hamilton's action on a compiled system.
#include "unidyn/analysis/variational.hpp"

#include <stdexcept>

namespace unidyn {

double virtual_work(const CompiledSystem& compiled, std::span<const double> parameters, double t,
                    const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                    const Eigen::VectorXd& qddot, const Eigen::VectorXd& d) {
  CompiledSystemData data = compiled.make_data();
  compiled.mass_and_forcing(t, q, qdot, parameters, data);
  // (4.36) Σ (F_K − m_K r̈_K) · d_K in the coordinates
  return d.dot(data.forcing - data.mass_matrix * qddot);
}

double gauss_constraint(const CompiledSystem& compiled, std::span<const double> parameters,
                        double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                        const Eigen::VectorXd& qddot) {
  CompiledSystemData data = compiled.make_data();
  compiled.mass_and_forcing(t, q, qdot, parameters, data);
  // ½ (q̈ − M⁻¹f)ᵀ M (q̈ − M⁻¹f) = ½ q̈ᵀ M q̈ − q̈ᵀ f + ½ fᵀ M⁻¹ f
  const Eigen::VectorXd free = data.mass_matrix.ldlt().solve(data.forcing);
  const Eigen::VectorXd away = qddot - free;
  return 0.5 * away.dot(data.mass_matrix * away);
}

namespace {

// L = T − U with the given registers: T and U are the first two observations, which do not
// depend on q̈ or λ.
double lagrangian_with(const CompiledSystem& compiled, std::span<const double> parameters, double t,
                       const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                       CompiledSystemData& data) {
  std::vector<double> observed(compiled.observation_count());
  const Eigen::VectorXd qddot = Eigen::VectorXd::Zero(q.size());
  const Eigen::VectorXd lambda =
      Eigen::VectorXd::Zero(static_cast<Eigen::Index>(compiled.constraint_count()));
  compiled.observe(t, q, qdot, qddot, lambda, parameters, observed, data);
  return observed[0] - observed[1];
}

}  // namespace

double lagrangian(const CompiledSystem& compiled, std::span<const double> parameters, double t,
                  const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
  CompiledSystemData data = compiled.make_data();
  return lagrangian_with(compiled, parameters, t, q, qdot, data);
}

double action_integral(const CompiledSystem& compiled, std::span<const double> parameters,
                       const SampledPath& path) {
  const std::size_t samples = path.q.size();
  if (samples < 3 || samples % 2 == 0 || path.qdot.size() != samples) {
    throw std::invalid_argument("the action needs an odd number (at least 3) of samples of q, q'");
  }
  // Simpson's rule: h/3 (L0 + 4 L1 + 2 L2 + … + 4 L_{2N−1} + L_2N)
  CompiledSystemData data = compiled.make_data();
  double sum = 0;
  for (std::size_t k = 0; k < samples; ++k) {
    const double weight = (k == 0 || k + 1 == samples) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    const double t = path.t0 + double(k) * path.step;
    sum += weight * lagrangian_with(compiled, parameters, t, path.q[k], path.qdot[k], data);
  }
  return sum * path.step / 3;
}

}  // namespace unidyn
