// MJCF (MuJoCo's XML) read into the model language: the bodies of <worldbody> placed by tree
// joints (docs/model-format.md), its joints their coordinates. docs/formats.md says what maps to
// what, and what is ignored or refused.
#pragma once

#include <cstddef>
#include <string>

#include "unidyn/formats/urdf.hpp"

namespace unidyn::formats {

// The largest MJCF file read (16 MiB) and the most bodies it may have.
inline constexpr std::size_t kMaxMjcfBytes = 16u << 20;
inline constexpr std::size_t kMaxMjcfBodies = 10000;

// Whether `text` is an MJCF file: its root element is <mujoco> (a URDF's is <robot>).
bool is_mjcf_text(const std::string& text);

// Throws ModelError at file:line:column for anything refused. The same text gives the same bytes.
ImportedModel import_mjcf(const std::string& text, const std::string& file,
                          const ImportOptions& options = {});

// The same from a file, read once and never past kMaxMjcfBytes (ModelError when it cannot be).
ImportedModel import_mjcf_file(const std::string& path, const ImportOptions& options = {});

// Whether the file at `path` ends in .xml and its root element is <mujoco> (ModelError when an
// .xml file cannot be read).
bool is_mjcf_file(const std::string& path);

}  // namespace unidyn::formats
