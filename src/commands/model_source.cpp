// Reading the model a command names, and NAME=VALUE parameters.
#include "unidyn/commands/model_source.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "unidyn/formats/mjcf.hpp"
#include "unidyn/formats/urdf.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/io/phase_timings.hpp"

#ifndef UNIDYN_MODELS_DIR
#define UNIDYN_MODELS_DIR "models"
#endif

namespace unidyn::commands {
namespace {

// The edit distance between two names (insertions, deletions, substitutions).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

// The bundled models: $UNIDYN_MODELS or the source tree's models/.
fs::path models_directory() {
  if (const char* env = std::getenv("UNIDYN_MODELS")) return env;
  // the source tree's, else an installed command's (PREFIX/bin/unidyn: PREFIX/share/unidyn/models)
  std::error_code error;
  if (fs::is_directory(UNIDYN_MODELS_DIR, error)) return UNIDYN_MODELS_DIR;
  const fs::path installed =
      fs::read_symlink("/proc/self/exe", error).parent_path().parent_path() / "share/unidyn/models";
  return !error && fs::is_directory(installed, error) ? installed : fs::path(UNIDYN_MODELS_DIR);
}

std::vector<fs::path> bundled_models() {
  std::vector<fs::path> found;
  std::error_code error;
  for (fs::recursive_directory_iterator it(models_directory(), error), end; !error && it != end;
       it.increment(error)) {
    if (it->path().extension() == ".yaml") found.push_back(it->path());
  }
  std::sort(found.begin(), found.end());
  return found;
}

// A model argument: a file, or the name of a bundled model; neither is bad input, with the
// bundled model of the nearest name when there is one close enough.
std::string resolve_model(const std::string& argument) {
  if (fs::exists(argument)) return argument;
  std::string nearest;
  std::size_t best = argument.size() / 3 + 2;
  for (const auto& path : bundled_models()) {
    if (path.stem() == argument) return path.string();
    if (const std::size_t d = edit_distance(argument, path.stem().string()); d < best) {
      best = d;
      nearest = path.stem().string();
    }
  }
  // a path (with a slash or an extension) that does not exist: load_model says it cannot open it
  if (argument.find('/') != std::string::npos || fs::path(argument).has_extension()) {
    return argument;
  }
  throw std::invalid_argument("'" + argument + "' is neither a model file nor a bundled model" +
                              (nearest.empty() ? "" : "; did you mean '" + nearest + "'?") +
                              " (`unidyn models` lists them)");
}

std::vector<std::pair<std::string, double>> parse_sets(const std::vector<std::string>& sets) {
  std::vector<std::pair<std::string, double>> overrides;
  for (const auto& s : sets) {
    const std::size_t eq = s.find('=');
    double value = 0;
    const char* begin = s.data() + (eq == std::string::npos ? 0 : eq + 1);
    const auto [ptr, ec] = std::from_chars(begin, s.data() + s.size(), value);
    if (eq == std::string::npos || ec != std::errc() || ptr != s.data() + s.size() ||
        !std::isfinite(value)) {
      throw std::invalid_argument("--set " + s + ": expected NAME=NUMBER (a finite number)");
    }
    overrides.emplace_back(s.substr(0, eq), value);
  }
  return overrides;
}

bool is_urdf(const std::string& path) {
  return fs::path(path).extension() == ".urdf";
}

bool is_imported(const std::string& path) {
  return is_urdf(path) || formats::is_mjcf_file(path);
}

formats::ImportedModel import_robot_file(const std::string& path,
                                         const formats::ImportOptions& options) {
  return is_urdf(path) ? formats::import_urdf_file(path, options)
                       : formats::import_mjcf_file(path, options);
}

// A URDF file, or an MJCF file (.xml with the root <mujoco>), is imported: the model is the YAML
// it becomes (`unidyn import` prints it).
LoadedModel load_named_model(const std::string& argument, const formats::ImportOptions& options) {
  const std::string path = resolve_model(argument);
  const bool imported = is_imported(path);
  if (options.limits && !imported) {
    throw std::invalid_argument(
        "--limits applies to URDF and MJCF files; in a unidyn model a "
        "joint's limits are unilateral constraints (docs/model-format.md)");
  }
  std::string text = imported ? import_robot_file(path, options).yaml : read_model_text(path);
  System system = parse_model(text, imported ? path + " (imported)" : path);
  end_phase("read model");
  return {std::move(system), std::move(text), path};
}

}  // namespace unidyn::commands
