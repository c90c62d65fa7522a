// CSV output of a simulation (RFC 4180): a header row, then one row per output time, each number
// in the shortest form that reads back to the same double. Each row is written as it comes, so a
// run that fails keeps every row before the failure; a row that cannot be written (a full disk,
// a file size limit, a closed pipe) throws CsvWriteError, and a file is then cut back to its last
// complete row.
#pragma once

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
  // Closes the file (not standard output). Throws CsvWriteError when the system reports that
  // what was written may not be kept.
  void close();

 private:
  void write_line(const std::string& line);

  std::string path_;
  int fd_ = -1;
  bool owned_ = false;
  bool regular_ = false;    // a regular file: it can be cut back after a failed write
  long long complete_ = 0;  // the file's size after the last complete line
};

}  // namespace unidyn
