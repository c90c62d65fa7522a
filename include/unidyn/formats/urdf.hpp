// URDF (the Unified Robot Description Format of ROS) read into the model language: a robot's links
// become bodies placed by tree joints (docs/model-format.md), its joints their coordinates.
// docs/formats.md says what maps to what, and what is ignored or refused.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace unidyn::formats {

// The largest URDF file read (16 MiB) and the most links it may have.
inline constexpr std::size_t kMaxUrdfBytes = 16u << 20;
inline constexpr std::size_t kMaxUrdfLinks = 10000;

// The unidyn model equivalent to a URDF file, as YAML text, and what unidyn said while importing
// (each note "file:line:column: ..."; e.g. elements ignored, names changed, numbers computed).
struct ImportedModel {
  std::string yaml;
  std::vector<std::string> notes;
};

// What an import may add on request: `limits` (the commands' --limits) makes each joint's
// position limits (URDF <limit lower upper>, MJCF range) two unilateral contacts; without it they
// are noted and not applied.
struct ImportOptions {
  bool limits = false;
};

// Throws ModelError at file:line:column for anything refused. The same text gives the same bytes.
ImportedModel import_urdf(const std::string& text, const std::string& file,
                          const ImportOptions& options = {});

// The same from a file, read once and never past kMaxUrdfBytes (ModelError when it cannot be).
ImportedModel import_urdf_file(const std::string& path, const ImportOptions& options = {});

}  // namespace unidyn::formats
