// Micro benchmarks of the instruction tape: the mass matrix and forcing of a 5-link planar
// pendulum, evaluated by the tape and by GiNaC's subs + evalf.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "unidyn/numeric/tape.hpp"

namespace {

using GiNaC::ex;
using GiNaC::symbol;

constexpr std::size_t kLinks = 5;

// Lagrange's equations M q̈ = f of a planar chain of point masses m_i on massless links l_i, angles
// θ_i from the downward vertical: T = ½ Σ m v·v, U = Σ m g y,
// M_ij = ∂²T/∂θ̇_i∂θ̇_j, f_i = ∂T/∂θ_i − ∂U/∂θ_i − Σ_j ∂²T/∂θ̇_i∂θ_j θ̇_j.
struct PlanarPendulum {
  std::vector<symbol> theta, rate, mass, length;
  symbol g{"g"};
  std::vector<ex> outputs;

  PlanarPendulum() {
    for (std::size_t i = 0; i < kLinks; ++i) {
      const std::string k = std::to_string(i + 1);
      theta.emplace_back("theta" + k);
      rate.emplace_back("dtheta" + k);
      mass.emplace_back("m" + k);
      length.emplace_back("l" + k);
    }
    derive();
  }

  std::vector<symbol> inputs() const {
    std::vector<symbol> in;
    for (const auto* group : {&theta, &rate, &mass, &length})
      in.insert(in.end(), group->begin(), group->end());
    in.push_back(g);
    return in;
  }

  // Energies from the positions of the masses, then the equations.
  void derive() {
    ex x = 0, y = 0, T = 0, U = 0;
    for (std::size_t i = 0; i < kLinks; ++i) {
      x += length[i] * sin(theta[i]);
      y -= length[i] * cos(theta[i]);
      ex vx = 0, vy = 0;
      for (std::size_t j = 0; j <= i; ++j) {
        vx += x.diff(theta[j]) * rate[j];
        vy += y.diff(theta[j]) * rate[j];
      }
      T += mass[i] * (vx * vx + vy * vy) / 2;
      U += mass[i] * g * y;
    }
    for (std::size_t i = 0; i < kLinks; ++i)
      for (std::size_t j = 0; j < kLinks; ++j) outputs.push_back(T.diff(rate[i]).diff(rate[j]));
    for (std::size_t i = 0; i < kLinks; ++i) {
      ex f = T.diff(theta[i]) - U.diff(theta[i]);
      for (std::size_t j = 0; j < kLinks; ++j) f -= T.diff(rate[i]).diff(theta[j]) * rate[j];
      outputs.push_back(f);
    }
  }

  // A state and parameters in the order of inputs().
  std::vector<double> point() const {
    std::vector<double> p;
    for (std::size_t i = 0; i < 4 * kLinks; ++i) p.push_back(0.3 + 0.1 * std::sin(double(i)));
    p.push_back(9.81);
    return p;
  }
};

const PlanarPendulum& pendulum() {
  static const PlanarPendulum p;
  return p;
}

// Compilation, once per model.
void BM_TapeCompile(benchmark::State& state) {
  const PlanarPendulum& p = pendulum();
  for (auto _ : state) benchmark::DoNotOptimize(unidyn::Tape::compile(p.outputs, p.inputs()));
}
BENCHMARK(BM_TapeCompile)->Unit(benchmark::kMillisecond);

// One evaluation of all 30 outputs with a sized workspace.
void BM_TapeEvaluate(benchmark::State& state) {
  const PlanarPendulum& p = pendulum();
  const unidyn::Tape tape = unidyn::Tape::compile(p.outputs, p.inputs());
  unidyn::TapeWorkspace workspace(tape);
  std::vector<double> in = p.point(), out(tape.output_count());
  for (auto _ : state) {
    tape.evaluate(in, out, workspace);
    benchmark::DoNotOptimize(out.data());
    in[0] += 1e-9;
  }
  state.counters["instructions"] = double(tape.instruction_count());
  state.counters["registers"] = double(tape.register_count());
}
BENCHMARK(BM_TapeEvaluate);

// The same with GiNaC: substitute the numbers, evaluate numerically, convert to double.
void BM_GinacSubsEvalf(benchmark::State& state) {
  const PlanarPendulum& p = pendulum();
  const std::vector<symbol> inputs = p.inputs();
  const std::vector<double> in = p.point();
  GiNaC::lst outputs;
  for (const ex& e : p.outputs) outputs.append(e);
  std::vector<double> out(p.outputs.size());
  for (auto _ : state) {
    GiNaC::exmap point;
    for (std::size_t i = 0; i < inputs.size(); ++i) point[inputs[i]] = in[i];
    const ex values = outputs.subs(point).evalf();
    for (std::size_t k = 0; k < out.size(); ++k)
      out[k] = GiNaC::ex_to<GiNaC::numeric>(values.op(k)).to_double();
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_GinacSubsEvalf)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
