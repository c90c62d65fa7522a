// A model loaded for Python (`unidyn.load`): the model a user names — a file, a bundled model or
// the text of one — read once, and its equations compiled on first use (native code, cached as the
// command's; parameters are inputs of that code, so one compilation serves every run and every
// parameter set). What a method computes is what the command of the same name computes: the same
// options, the same checks, the same numbers. Nothing here touches Python: the bindings
// (module.cpp) release the interpreter's lock around the work.
//
// GiNaC is not thread-safe: its expressions share nodes (the numbers 0 and 1 among them) whose
// reference counts are not atomic, so two threads that copy or free any expressions at once, of
// one model or of two, corrupt them. Every method therefore holds one process-wide lock while it
// touches expressions — a whole run included (the integrators set up from the model) — and rhs()
// only while it reads the parameters: its states are evaluated in parallel by the compiled code.
// A PythonModel is freed under the same lock.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "unidyn/commands/model_commands.hpp"
#include "unidyn/commands/model_source.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn::python {

// A run: its columns, its rows (row-major), the summary `simulate` prints, its events.
struct RunResult {
  std::vector<std::string> columns;
  std::vector<double> values;
  std::size_t rows = 0;
  std::string summary;
  std::vector<std::pair<double, std::string>> events;
  bool ok = true;
  std::string message;
};

// What a run is asked for: simulate's options (0 or "" for the model's own) and NAME=VALUE
// settings.
struct RunRequest {
  double t_end = 0, output_step = 0, rtol = 0;
  std::string method;
  std::vector<std::pair<std::string, double>> set;
  bool poses = false;
  // Asked after every step (SimulationOptions::interrupted): true ends the run there.
  std::function<bool()> interrupted;
};

class PythonModel {
 public:
  // `source`: a model file, a bundled model's name, or a model's text (a text with a newline);
  // `limits`: a URDF or MJCF file's joint limits as unilateral contacts (the commands' --limits).
  // Throws ModelError (file:line:column) or std::invalid_argument.
  explicit PythonModel(const std::string& source, bool limits = false);
  ~PythonModel();
  PythonModel(const PythonModel&) = delete;
  PythonModel& operator=(const PythonModel&) = delete;

  // (names only are read from these without the lock: no expression is copied)
  const System& system() const { return model_->system; }
  const std::string& path() const { return model_->path; }
  const std::string& text() const { return model_->text; }
  // The parameters' values in the model (before any setting).
  std::vector<std::pair<std::string, double>> parameters() const;

  // `unidyn derive MODEL --method M --format F --form FORM`.
  std::string derive(const std::string& method, const std::string& format,
                     const std::string& form) const;

  // `unidyn simulate`: every row kept, the summary's text.
  RunResult simulate(const RunRequest& request) const;

  // q̈ and λ at each of `count` states (q, q̇ rows of n values each, row-major) at time t, with the
  // settings' parameters: M q̈ = f + Aᵀλ, A q̈ + b = 0 (numeric/compiled_system.hpp).
  void rhs(const double* q, const double* qdot, std::size_t count, double t,
           const std::vector<std::pair<std::string, double>>& set, double* qddot,
           double* lambda) const;

  // `unidyn linearize|modes|equilibria MODEL --at ... --set ... [--period T] --format json`.
  std::string analysis_json(const std::string& command, const std::vector<std::string>& at,
                            const std::vector<std::pair<std::string, double>>& set,
                            std::size_t starts, const std::vector<std::string>& cyclic,
                            std::optional<double> period) const;

  // `unidyn report MODEL -o PATH`; returns what the command prints.
  std::string report(const std::string& path, const RunRequest& request) const;

  // The compiled equations (made once, on first use) and their sizes.
  std::size_t coordinate_count() const;
  std::size_t constraint_count() const;

 private:
  // The commands layer's options of a request.
  commands::ModelOptions options_of(const RunRequest& request) const;

  // the compiled equations, made under the lock on first use
  const CompiledSystem& compiled_locked() const;

  std::unique_ptr<commands::LoadedModel> model_;
  mutable std::unique_ptr<CompiledSystem> compiled_;
};

}  // namespace unidyn::python
