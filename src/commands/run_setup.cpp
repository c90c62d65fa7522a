// What `simulate` and `report` share.
#include "unidyn/commands/run_setup.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <iterator>

#include "unidyn/commands/model_source.hpp"
#include "unidyn/equations/kane.hpp"
#include "unidyn/equations/reduction.hpp"
#include "unidyn/integrate/initial_state.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/io/phase_timings.hpp"
#include "unidyn/symbolic/printable_text.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn::commands {

System command_system(const ModelOptions& c, const System& loaded) {
  if (!c.reduced) return loaded;
  Reduction reduction = eliminate_constraints(loaded);
  for (const auto& note : reduction.notes) fmt::print(stderr, "approach II: {}\n", note);
  return std::move(reduction.system);
}

CommandStart command_start(const ModelOptions& c, const System& full, const System& system) {
  const auto sets = parse_sets(c.sets);
  if (c.reduced) {
    SimulationStart full_start = initial_state(full, sets);
    if (gives_eliminated_values(full, full_start, system)) {
      if (c.project) {
        throw std::invalid_argument(
            "--project cannot keep a value given for a coordinate that --reduced eliminates: "
            "drop one of them");
      }
      SimulationStart start = restricted_start(full, full_start, system);
      return {std::move(start), std::move(full_start)};
    }
  }
  return {initial_state(system, sets), std::nullopt};
}

std::vector<std::string> complete_command_start(CommandStart& s, const System& full,
                                                const System& system,
                                                const CompiledSystem& compiled) {
  std::vector<std::string> computed;
  if (s.full) {
    const CompiledSystem full_compiled(full, kane_equations(full));
    computed = complete_initial_state(full, full_compiled, *s.full);
    s.start = restricted_start(full, *s.full, system);
  }
  for (auto& line : complete_initial_state(system, compiled, s.start)) {
    computed.push_back(std::move(line));
  }
  return computed;
}

CompiledSystem command_compiled(const ModelOptions& c, const LoadedModel& model,
                                const System& system, bool background) {
  CompileOptions compile_options;
  compile_options.native = c.evaluation == "native";
  compile_options.background = background;
  // the cache of native code is keyed by what determines the code in the bytes that were parsed
  // (not their comments, initial: or simulate:), and how they were reduced
  compile_options.native_options.key =
      std::string(c.reduced ? "reduced\n" : "full\n") + model_code_text(model.text, model.path);
  // the numerics take M and f through partial velocities (Kane's equations: the same as
  // Lagrange's, tested on every bundled model, derived faster and with fewer operations), or a
  // large kinematic tree's q̈ from the articulated-body algorithm, with no equations derived
  compile_options.phase_ended = end_phase;
  CompiledSystem compiled(system, compile_options);
  end_phase("build the evaluation");
  return compiled;
}

SimulationOptions options_for(const System& system, const ModelOptions& c) {
  return simulation_options(system.simulate, {c.t_end, c.output_step, c.rtol, c.integrator});
}

std::string run_headline(const System& system, const SimulationOptions& options,
                         const SimulationSummary& s) {
  return fmt::format(
      "{}: {} from t = 0 to {} ({}), {} rows\n", system.name,
      s.ok ? (s.stopped ? "simulated until stop_when" : "simulated")
           : "FAILED at t = " + fmt::format("{:.10g}", s.failure_time) + ": " + s.message,
      options.t_end, options.method, s.rows);
}

std::string run_figures(const System& system, const SimulationSummary& s) {
  fmt::memory_buffer buffer;
  const auto out = std::back_inserter(buffer);
  // the potentials unidyn found for forces given without one, in the energy E = T + U
  for (const ForceElement& f : system.forces) {
    if (!f.potential_proven) continue;
    fmt::format_to(out, "  U of {} (line {}) found by unidyn (its curl is 0): {}\n", f.label,
                   f.where.line, printable(to_text(f.potential)));
  }
  if (s.has_energy && s.energy_not_conserved.empty()) {
    fmt::format_to(out, "  energy: initial {:.12g}, relative drift {:.3g}\n", s.energy_initial,
                   s.energy_relative_drift);
  } else if (s.has_energy) {
    fmt::format_to(
        out, "  energy not conserved ({}): E(0) = {:.12g}, E({:.6g}) = {:.12g}, change {:.6g}\n",
        s.energy_not_conserved, s.energy_initial, s.last_row_time, s.energy_final,
        s.energy_final - s.energy_initial);
  }
  if (!system.constraints.empty()) {
    fmt::format_to(out, "  constraint residuals: max |Psi| {:.3g}, max |A q' + e| {:.3g}\n",
                   s.max_position_residual, s.max_velocity_residual);
    if (s.initial_projection > 1e-10) {
      fmt::format_to(out, "  note: the initial state was moved by {:.3g} onto the constraints\n",
                     s.initial_projection);
    }
    if (!s.dependent_constraints.empty()) {
      fmt::format_to(out,
                     "  note: {} depend{} on the other constraints at the start (a redundant "
                     "row, or a singular position): the accelerations are unique, the multipliers "
                     "are not; they are given as the minimum-norm ones\n",
                     fmt::format("'{}'", fmt::join(s.dependent_constraints, "', '")),
                     s.dependent_constraints.size() > 1 ? "" : "s");
    } else if (s.dependent_solves > 0) {
      fmt::format_to(out,
                     "  note: the constraints' rows were dependent at {} evaluations of the "
                     "equations (singular positions passed): the multipliers there are the "
                     "minimum-norm ones\n",
                     s.dependent_solves);
    }
    if (!s.hand_over.empty()) {
      fmt::format_to(
          out,
          "  note: {}; alf (the index-3 augmented Lagrangian method, which holds the "
          "positions themselves) took the run on from t = {:.6g}{}{}\n",
          s.hand_over, s.hand_over_time,
          s.hand_overs > 1 ? fmt::format(" (and at {} more such)", s.hand_overs - 1) : "",
          s.handed_back ? ", dopri5 taking it back past each" : " to the end");
    }
    for (const auto& m : s.multipliers) {
      if (m.held)
        fmt::format_to(out, "  lambda({}): from {:.6g} to {:.6g}\n", m.name, m.min, m.max);
    }
  }
  for (const Body& body : system.bodies) {
    if (body.chart) {
      fmt::format_to(out,
                     "  Euler angles: closest to gimbal lock |[g1,g2,g3]| = {:.3g} at t = {:.6g}\n",
                     s.closest_gimbal_lock, s.closest_gimbal_lock_time);
      break;
    }
  }
  for (const auto& d : s.conserved_drift) {
    fmt::format_to(out, "  conserved {}: initial {:.12g}, max change {:.3g}", d.name, d.initial,
                   d.max_change);
    if (d.initial != 0.0)
      fmt::format_to(out, " (relative {:.3g})", d.max_change / std::abs(d.initial));
    fmt::format_to(out, "\n");
  }
  return fmt::to_string(buffer);
}

}  // namespace unidyn::commands
