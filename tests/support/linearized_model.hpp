// A bundled model linearised about an operating point, for the analysis layer's tests.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "support/eigen_solvers.hpp"
#include "support/model_run.hpp"
#include "unidyn/analysis/linearization.hpp"
#include "unidyn/analysis/modes.hpp"

namespace unidyn::test {

struct LinearizedModel {
  System system;
  CompiledSystem compiled;
  OperatingPoint point;
  Linearization linearization;

  // The model at the operating point given by NAME=VALUE texts (as `--at`), with parameters
  // changed by `parameters` (as `--set`).
  LinearizedModel(const std::string& model, const std::vector<std::string>& at,
                  const std::vector<std::pair<std::string, double>>& parameters = {})
      : system(load_model(model_path(model))),
        compiled(system, lagrange_equations(system)),
        point(operating_point(system, compiled, parse_given_values(system, at),
                              initial_state(system, parameters).parameters)),
        linearization(linearize(system, compiled, point)) {}

  std::size_t coordinate(const std::string& name) const { return *system.find_coordinate(name); }
};

// The eigenvalues of A, sorted by real part, then imaginary part.
inline std::vector<std::complex<double>> sorted_eigenvalues(const Eigen::MatrixXd& A) {
  const Eigen::VectorXcd lambda = eigenvalues(A);
  std::vector<std::complex<double>> out(lambda.begin(), lambda.end());
  std::sort(out.begin(), out.end(), [](auto a, auto b) {
    return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
  });
  return out;
}

}  // namespace unidyn::test
