// A model loaded for Python: the commands' own steps, with their results kept rather than printed.
#include "python_model.hpp"

#include <fmt/format.h>

#include <sstream>

#include "unidyn/commands/analysis_commands.hpp"
#include "unidyn/commands/report_command.hpp"
#include "unidyn/commands/run_setup.hpp"
#include "unidyn/integrate/initial_state.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/numeric/poses.hpp"

namespace unidyn::python {
namespace {

// NAME=VALUE texts of settings, each value written so that it reads back as the same double.
std::vector<std::string> setting_texts(const std::vector<std::pair<std::string, double>>& set) {
  std::vector<std::string> texts;
  for (const auto& [name, value] : set) texts.push_back(fmt::format("{}={:.17g}", name, value));
  return texts;
}

// The lock every use of GiNaC's expressions holds (python_model.hpp).
std::mutex& symbolic_lock() {
  static std::mutex lock;
  return lock;
}

}  // namespace

PythonModel::PythonModel(const std::string& source, bool limits) {
  const std::lock_guard held(symbolic_lock());
  // a text with a line break is a model's text; anything else names a file or a bundled model
  if (source.find('\n') != std::string::npos) {
    model_ = std::make_unique<commands::LoadedModel>(
        commands::LoadedModel{parse_model(source, "<string>"), source, "<string>"});
  } else {
    model_ = std::make_unique<commands::LoadedModel>(
        commands::load_named_model(source, formats::ImportOptions{limits}));
  }
}

PythonModel::~PythonModel() {
  const std::lock_guard held(symbolic_lock());
  compiled_.reset();
  model_.reset();
}

std::vector<std::pair<std::string, double>> PythonModel::parameters() const {
  const std::lock_guard held(symbolic_lock());
  const SimulationStart start = initial_state(system(), {});
  std::vector<std::pair<std::string, double>> out;
  for (std::size_t k = 0; k < system().parameters.size(); ++k) {
    out.emplace_back(system().parameters[k].name, start.parameters[k]);
  }
  return out;
}

commands::ModelOptions PythonModel::options_of(const RunRequest& request) const {
  commands::ModelOptions c;
  c.t_end = request.t_end;
  c.output_step = request.output_step;
  c.rtol = request.rtol;
  c.integrator = request.method;
  c.sets = setting_texts(request.set);
  c.poses = request.poses;
  return c;
}

const CompiledSystem& PythonModel::compiled_locked() const {
  if (!compiled_) {
    compiled_ = std::make_unique<CompiledSystem>(
        commands::command_compiled(commands::ModelOptions{}, *model_, system()));
  }
  return *compiled_;
}

std::size_t PythonModel::coordinate_count() const {
  const std::lock_guard held(symbolic_lock());
  return compiled_locked().coordinate_count();
}

std::size_t PythonModel::constraint_count() const {
  const std::lock_guard held(symbolic_lock());
  return compiled_locked().constraint_count();
}

std::string PythonModel::derive(const std::string& method, const std::string& format,
                                const std::string& form) const {
  commands::ModelOptions c;
  c.method = method;
  c.format = format;
  c.form = form;
  std::ostringstream out;
  const std::lock_guard held(symbolic_lock());
  commands::write_derivation(out, c, *model_);
  return out.str();
}

RunResult PythonModel::simulate(const RunRequest& request) const {
  const commands::ModelOptions c = options_of(request);
  const std::lock_guard held(symbolic_lock());
  const System& system = this->system();
  commands::CommandStart initial = commands::command_start(c, system, system);
  SimulationOptions options = commands::options_for(system, c);
  options.interrupted = request.interrupted;
  const CompiledSystem& code = compiled_locked();
  const std::vector<std::string> computed =
      commands::complete_command_start(initial, system, system, code);
  const SimulationStart& start = initial.start;

  RunResult result;
  result.columns = simulation_columns(system);
  std::optional<Poses> poses;
  if (request.poses) {
    poses.emplace(system);
    result.columns.insert(result.columns.end(), poses->columns().begin(), poses->columns().end());
  }
  const auto n = static_cast<Eigen::Index>(system.coordinates().size());
  std::vector<double> row_with_poses;
  const SimulationSummary s =
      unidyn::simulate(system, code, start, options, [&](const std::vector<double>& row) {
        if (!poses) {
          result.values.insert(result.values.end(), row.begin(), row.end());
          return;
        }
        row_with_poses = row;
        poses->append(row[0], Eigen::Map<const Eigen::VectorXd>(row.data() + 1, n),
                      start.parameters, row_with_poses);
        result.values.insert(result.values.end(), row_with_poses.begin(), row_with_poses.end());
      });
  result.rows = s.rows;
  result.ok = s.ok;
  result.message = s.message;
  result.summary = commands::run_headline(system, options, s);
  for (const auto& line : start.computed) {
    result.summary += "  parameter computed from set: " + line + "\n";
  }
  if (!computed.empty()) {
    result.summary += fmt::format("  initial values computed from the constraints: {}\n",
                                  fmt::join(computed, ", "));
  }
  if (s.rows > 0) result.summary += commands::run_figures(system, s);
  for (const auto& phase : s.phases) result.events.emplace_back(phase.t, phase.what);
  return result;
}

void PythonModel::rhs(const double* q, const double* qdot, std::size_t count, double t,
                      const std::vector<std::pair<std::string, double>>& set, double* qddot,
                      double* lambda) const {
  // parameters only: the states are given
  for (const auto& [name, value] : set) {
    if (!system().find_parameter(name)) {
      throw std::invalid_argument("set " + name + ": not a parameter (the states are given)");
    }
  }
  std::vector<double> parameters;
  const CompiledSystem* compiled = nullptr;
  {
    const std::lock_guard held(symbolic_lock());
    parameters = initial_state(system(), set).parameters;
    compiled = &compiled_locked();
  }
  // the compiled code alone from here: no expression is touched
  const CompiledSystem& code = *compiled;
  CompiledSystemData data = code.make_data();
  const auto n = static_cast<Eigen::Index>(code.coordinate_count());
  const auto m = static_cast<Eigen::Index>(code.constraint_count());
  Eigen::VectorXd qk(n), qdotk(n), qddotk(n), lambdak(m);
  for (std::size_t k = 0; k < count; ++k) {
    qk = Eigen::Map<const Eigen::VectorXd>(q + k * n, n);
    qdotk = Eigen::Map<const Eigen::VectorXd>(qdot + k * n, n);
    code.solve(t, qk, qdotk, parameters, qddotk, lambdak, data);
    Eigen::Map<Eigen::VectorXd>(qddot + k * n, n) = qddotk;
    if (m > 0) Eigen::Map<Eigen::VectorXd>(lambda + k * m, m) = lambdak;
  }
}

std::string PythonModel::analysis_json(const std::string& command,
                                       const std::vector<std::string>& at,
                                       const std::vector<std::pair<std::string, double>>& set,
                                       std::size_t starts, const std::vector<std::string>& cyclic,
                                       std::optional<double> period) const {
  commands::AnalysisOptions c;
  c.period = period;
  c.at = at;
  c.sets = setting_texts(set);
  c.format = "json";
  c.starts = starts;
  c.cyclic = cyclic;
  std::ostringstream out;
  const std::lock_guard held(symbolic_lock());
  commands::write_analysis(out, command, c, *model_);
  return out.str();
}

std::string PythonModel::report(const std::string& path, const RunRequest& request) const {
  commands::ModelOptions c = options_of(request);
  c.output = path;
  std::ostringstream out;
  const std::lock_guard held(symbolic_lock());
  const int status = commands::run_report(c, *model_, out);
  if (status != 0) throw std::runtime_error(out.str());
  return out.str();
}

}  // namespace unidyn::python
