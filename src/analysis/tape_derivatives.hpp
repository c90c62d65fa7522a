// A compiled tape's outputs and their exact derivatives at a state (forward mode,
// numeric/tape.hpp), for the analysis layer's linearisation and searches.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "unidyn/numeric/tape.hpp"

namespace unidyn {

// The inputs [t, q, q̇, p] of the system's tapes at a state.
std::vector<double> tape_inputs_at(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                   const std::vector<double>& parameters);

// The outputs and their derivatives along `count` inputs from `first`:
// derivative.col(d) = ∂outputs/∂input_{first + d}.
struct TapeDerivatives {
  Eigen::VectorXd value;
  Eigen::MatrixXd derivative;
};
TapeDerivatives derivatives(const Tape& tape, const std::vector<double>& inputs, Eigen::Index first,
                            Eigen::Index count);

}  // namespace unidyn
