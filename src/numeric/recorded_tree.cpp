// The articulated-body algorithm recorded as a tape (include/unidyn/numeric/recorded_tree.hpp).
#include "unidyn/numeric/recorded_tree.hpp"

#include <stdexcept>

#include "unidyn/numeric/tape_recorder.hpp"
#include "unidyn/tree/articulated_body.hpp"

namespace unidyn {

// A recorded pivot is kept for the tape's caller to check; a number is checked now (found by the
// algorithm's template through Recorded's namespace).
void require_positive_pivot(const Recorded& pivot, int coordinate) {
  if (pivot.is_constant()) {
    tree::require_positive_pivot(pivot.constant(), coordinate);
    return;
  }
  pivot.recorder()->watch(pivot);
}

Tape record_tree_accelerations(const tree::TreeModel& model, const Tape& joint_forces,
                               std::span<const double> parameters) {
  const std::size_t n = model.coordinates;
  if (joint_forces.input_count() != 1 + 2 * n + parameters.size()) {
    throw std::invalid_argument(
        "record_tree_accelerations: the forces' inputs are not [t, q, q', p]");
  }
  std::vector<std::string> names;
  for (std::size_t k = 0; k < joint_forces.input_count(); ++k) {
    names.push_back(joint_forces.input_name(k));
  }
  TapeRecorder recorder(std::move(names));
  // [t, q, q̇] recorded, the parameters as numbers
  std::vector<Recorded> inputs;
  for (std::size_t k = 0; k < 1 + 2 * n; ++k) inputs.push_back(recorder.input(k));
  for (const double p : parameters) inputs.emplace_back(p);
  using Vector = Eigen::Matrix<Recorded, Eigen::Dynamic, 1>;
  Vector q(static_cast<Eigen::Index>(n)), qdot(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    q[static_cast<Eigen::Index>(i)] = inputs[1 + i];
    qdot[static_cast<Eigen::Index>(i)] = inputs[1 + n + i];
  }
  const std::vector<Recorded> tau_values = recorder.replay(joint_forces, inputs);
  const Vector tau = Eigen::Map<const Vector>(tau_values.data(), static_cast<Eigen::Index>(n));
  Vector qddot;
  tree::BasicTreeData<Recorded> data(model);
  tree::articulated_body_accelerations<Recorded>(model, q, qdot, tau, qddot, data);
  return recorder.finish(std::vector<Recorded>(qddot.begin(), qddot.end()));
}

}  // namespace unidyn
