// Tapes' outputs and their forward-mode derivatives at a state.
#include "tape_derivatives.hpp"

namespace unidyn {

std::vector<double> tape_inputs_at(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                   const std::vector<double>& parameters) {
  std::vector<double> inputs{t};
  inputs.insert(inputs.end(), q.begin(), q.end());
  inputs.insert(inputs.end(), qdot.begin(), qdot.end());
  inputs.insert(inputs.end(), parameters.begin(), parameters.end());
  return inputs;
}

TapeDerivatives derivatives(const Tape& tape, const std::vector<double>& inputs, Eigen::Index first,
                            Eigen::Index count) {
  const auto outputs = static_cast<Eigen::Index>(tape.output_count());
  TapeDerivatives out{Eigen::VectorXd(outputs), Eigen::MatrixXd(outputs, count)};
  TapeWorkspace workspace(tape);
  std::vector<double> seed(inputs.size(), 0.0), value(tape.output_count()),
      tangent(tape.output_count());
  if (count == 0) tape.evaluate(inputs, value, workspace);
  for (Eigen::Index d = 0; d < count; ++d) {
    seed[static_cast<std::size_t>(first + d)] = 1.0;
    tape.evaluate_tangent(inputs, seed, value, tangent, workspace);
    seed[static_cast<std::size_t>(first + d)] = 0.0;
    out.derivative.col(d) = Eigen::Map<const Eigen::VectorXd>(tangent.data(), outputs);
  }
  out.value = Eigen::Map<const Eigen::VectorXd>(value.data(), outputs);
  return out;
}

}  // namespace unidyn
