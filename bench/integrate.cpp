// Micro benchmarks of the integrate layer: one step on a 12-dimensional linear system.
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <limits>

#include "unidyn/integrate/dormand_prince.hpp"
#include "unidyn/integrate/dormand_prince_853.hpp"
#include "unidyn/integrate/rk4.hpp"

namespace {

// Six undamped oscillators x_i'' = −i² x_i as y' = A y, y = (x, v) ∈ R¹².
Eigen::MatrixXd oscillators() {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(12, 12);
  for (int i = 0; i < 6; ++i) {
    A(i, 6 + i) = 1.0;
    A(6 + i, i) = -double((i + 1) * (i + 1));
  }
  return A;
}

unidyn::OdeFunction linear_system() {
  return [A = oscillators()](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    dydt.noalias() = A * y;
  };
}

// One accepted step of a Dormand–Prince pair (dopri5 or dop853) at rtol 1e-8, without dense output.
template <class Pair>
void BM_DormandPrinceStep(benchmark::State& state) {
  unidyn::DormandPrinceOptions options;
  options.rtol = 1e-8;
  options.atol = 1e-10;
  options.max_steps = std::numeric_limits<std::size_t>::max();
  Pair stepper(linear_system(), options);
  stepper.initialize(0.0, Eigen::VectorXd::Ones(12));
  for (auto _ : state) {
    stepper.step(1e12);
    benchmark::DoNotOptimize(stepper.y().data());
  }
  state.counters["rhs/step"] =
      double(stepper.stats().rhs_evaluations) / double(stepper.stats().accepted_steps);
}
BENCHMARK(BM_DormandPrinceStep<unidyn::DormandPrince54>);
BENCHMARK(BM_DormandPrinceStep<unidyn::DormandPrince853>);

void BM_Rk4Step(benchmark::State& state) {
  unidyn::Rk4 stepper(linear_system(), 0.01);
  stepper.initialize(0.0, Eigen::VectorXd::Ones(12));
  for (auto _ : state) {
    stepper.step(1e12);
    benchmark::DoNotOptimize(stepper.y().data());
  }
}
BENCHMARK(BM_Rk4Step);

}  // namespace

BENCHMARK_MAIN();
