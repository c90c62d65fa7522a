// CSV output of a simulation: a header row, then one row per output time, each number in the
// shortest form that reads back to the same double. Rows are flushed as they come, so a run that
// fails keeps every row before the failure.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace unidyn {

class CsvWriter {
 public:
  // Writes to `path`, or to standard output when path is "-". Throws std::runtime_error when the
  // file cannot be opened.
  explicit CsvWriter(const std::string& path);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  void header(const std::vector<std::string>& columns);
  void row(const std::vector<double>& values);

 private:
  std::FILE* file_;
  bool owned_;
};

}  // namespace unidyn
