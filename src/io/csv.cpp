// CSV writer.
#include "unidyn/io/csv.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace unidyn {

CsvWriter::CsvWriter(const std::string& path)
    : file_(path == "-" ? stdout : std::fopen(path.c_str(), "w")), owned_(path != "-") {
  if (!file_) throw std::runtime_error("cannot open '" + path + "' for writing");
}

CsvWriter::~CsvWriter() {
  if (owned_) std::fclose(file_);
}

void CsvWriter::header(const std::vector<std::string>& columns) {
  std::string line;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i > 0) line += ',';
    // A name with a comma or quote is quoted (RFC 4180).
    if (columns[i].find_first_of(",\"") != std::string::npos) {
      std::string quoted = "\"";
      for (char c : columns[i]) quoted += (c == '"') ? std::string("\"\"") : std::string(1, c);
      line += quoted + "\"";
    } else {
      line += columns[i];
    }
  }
  fmt::print(file_, "{}\n", line);
  std::fflush(file_);
}

void CsvWriter::row(const std::vector<double>& values) {
  std::string line;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) line += ',';
    line += fmt::format("{}", values[i]);
  }
  fmt::print(file_, "{}\n", line);
  std::fflush(file_);
}

}  // namespace unidyn
