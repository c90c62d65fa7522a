// The model a command names (a file, or a bundled model by name) and its NAME=VALUE settings.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "unidyn/formats/urdf.hpp"
#include "unidyn/model/system.hpp"

namespace unidyn::commands {

namespace fs = std::filesystem;

// The bundled models' directory: $UNIDYN_MODELS, else the source tree's models/, else an installed
// command's PREFIX/share/unidyn/models; its models, sorted.
fs::path models_directory();
std::vector<fs::path> bundled_models();

// A model argument: a file, or the name of a bundled model; neither is bad input
// (std::invalid_argument), with the bundled model of the nearest name when one is close enough.
std::string resolve_model(const std::string& argument);

// --set NAME=NUMBER texts; anything else is bad input (std::invalid_argument).
std::vector<std::pair<std::string, double>> parse_sets(const std::vector<std::string>& sets);

// Whether a model file is a URDF file (named *.urdf), which is imported.
bool is_urdf(const std::string& path);

// Whether a file is a URDF or MJCF file, and the model it imports as (--limits in `options`).
bool is_imported(const std::string& path);
formats::ImportedModel import_robot_file(const std::string& path,
                                         const formats::ImportOptions& options);

// The model a command names (a file, or a bundled model by name), read once, and its text (a URDF
// or MJCF file's: the YAML it is imported as, read as "PATH (imported)"). Import options given for
// a model of the model language are bad input (std::invalid_argument).
struct LoadedModel {
  System system;
  std::string text;
  std::string path;
};
LoadedModel load_named_model(const std::string& argument,
                             const formats::ImportOptions& options = {});

}  // namespace unidyn::commands
