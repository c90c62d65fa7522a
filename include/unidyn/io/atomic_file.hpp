// Files written whole or not at all: a temporary file beside the target, synced, renamed into
// place (rename(2) replaces the old file atomically), and the directory synced. A reader sees the
// old file or the new one, never a part; a failure leaves the old one and no temporary.
#pragma once

#include <filesystem>
#include <string>

namespace unidyn {

// Writes `text` as the file `path`. Throws std::runtime_error when it cannot.
void write_atomically(const std::filesystem::path& path, const std::string& text);

// Removes the temporary files of the writes under way, for a signal that ends the process: it
// leaves the old files and nothing beside them. Async-signal-safe.
void remove_unfinished_files() noexcept;

// Throws std::invalid_argument when `path` cannot be written that way (its directory is not
// writable, or it is a directory): checked before a long computation whose result goes there.
void expect_writable(const std::filesystem::path& path);

}  // namespace unidyn
