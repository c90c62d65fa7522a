// Micro benchmarks of the rotation layer.
#include <benchmark/benchmark.h>

#include "unidyn/rotation/euler_angles.hpp"
#include "unidyn/rotation/euler_parameters.hpp"

namespace {

void BM_EulerRotationTensor(benchmark::State& state) {
  const unidyn::EulerSet set{3, 1, 3};
  unidyn::Vec3 angles(0.3, 0.7, -1.1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(unidyn::rotation_tensor(set, angles));
    angles[0] += 1e-9;
  }
}
BENCHMARK(BM_EulerRotationTensor);

void BM_EulerAnglesFromTensor(benchmark::State& state) {
  const unidyn::EulerSet set{3, 2, 1};
  const unidyn::Tensor Q = unidyn::rotation_tensor(set, unidyn::Vec3(0.3, 0.7, -1.1));
  for (auto _ : state) benchmark::DoNotOptimize(unidyn::euler_angles(set, Q));
}
BENCHMARK(BM_EulerAnglesFromTensor);

void BM_EulerParametersFromTensor(benchmark::State& state) {
  const unidyn::Tensor Q =
      unidyn::rotation_tensor(unidyn::EulerSet{3, 2, 1}, unidyn::Vec3(0.3, 0.7, -1.1));
  for (auto _ : state) benchmark::DoNotOptimize(unidyn::euler_parameters(Q));
}
BENCHMARK(BM_EulerParametersFromTensor);

void BM_EulerAngleRates(benchmark::State& state) {
  const unidyn::EulerSet set{3, 1, 3};
  const unidyn::Vec3 angles(0.3, 0.7, -1.1), omega(0.1, -0.2, 3.0);
  for (auto _ : state) benchmark::DoNotOptimize(unidyn::euler_angle_rates(set, angles, omega));
}
BENCHMARK(BM_EulerAngleRates);

}  // namespace

BENCHMARK_MAIN();
