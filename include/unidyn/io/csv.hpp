// CSV output of a simulation (RFC 4180): a header row, then one row per output time, each number
// in the shortest form that reads back to the same double. The header is written at once; rows
// are gathered and written in blocks (64 KiB, or whatever has come within 0.2 s, so a slow run
// still shows its rows as they come; close() writes the rest): a run that fails keeps every row
// before the failure. A block that cannot be written (a full disk, a file size limit, a closed
// pipe) is written again row by row, as far as it goes: the file ends with the last row that fit,
// rows_written() counts them, and CsvWriteError says why the next one did not.
#pragma once

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

namespace unidyn {

class CsvWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A header field: quoted when it holds a comma, a quote or a line break (quotes doubled).
std::string csv_field(const std::string& text);

class CsvWriter {
 public:
  // Writes to `path`, or to standard output when path is "-". Throws std::runtime_error when the
  // file cannot be opened.
  explicit CsvWriter(const std::string& path);
  // Closes the file; an error there is lost: call close() to see it.
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  void header(const std::vector<std::string>& columns);
  void row(const std::vector<double>& values);
  // Writes the rows gathered so far (CsvWriteError when they cannot be written).
  void flush();
  // The rows in the file (or on standard output) so far, not counting the header.
  std::size_t rows_written() const { return rows_written_; }
  // Writes the rest and closes the file (not standard output). Throws CsvWriteError when the
  // system reports that what was written may not be kept.
  void close();

 private:
  // Writes the block when it is full or has waited long enough.
  void maybe_flush();
  // Writes bytes [from, to) of the block; false (errno set) when the system refused some.
  bool write_bytes(std::size_t from, std::size_t to);

  std::string path_;
  int fd_ = -1;
  bool owned_ = false;
  bool regular_ = false;                // a regular file: it can be cut back after a failed write
  long long complete_ = 0;              // the file's size after the last complete line
  std::string block_;                   // complete lines not written yet
  std::vector<std::size_t> line_ends_;  // where each of them ends in block_
  std::size_t rows_written_ = 0;
  bool header_pending_ = false;  // the block's first line is the header
  std::chrono::steady_clock::time_point written_ = std::chrono::steady_clock::now();
};

}  // namespace unidyn
