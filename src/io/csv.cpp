// CSV writer: one write(2) per line, every error checked, the file cut back to its last complete
// line when a write fails.
#include "unidyn/io/csv.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace unidyn {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

CsvWriter::CsvWriter(const std::string& path)
    : path_(path == "-" ? "standard output" : path), owned_(path != "-") {
  fd_ =
      owned_ ? ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666) : STDOUT_FILENO;
  if (fd_ < 0) {
    throw std::runtime_error("cannot open '" + path + "' for writing: " + std::strerror(errno));
  }
  struct stat s {};
  regular_ = ::fstat(fd_, &s) == 0 && S_ISREG(s.st_mode);
  // standard output may be a file opened for appending: its lines start where it ends now
  if (regular_) complete_ = owned_ ? 0 : static_cast<long long>(::lseek(fd_, 0, SEEK_END));
}

CsvWriter::~CsvWriter() {
  if (owned_ && fd_ >= 0) ::close(fd_);
}

void CsvWriter::write_line(const std::string& line) {
  if (fd_ < 0) throw CsvWriteError("cannot write '" + path_ + "': it is closed");
  for (std::size_t done = 0; done < line.size();) {
    const ssize_t n = ::write(fd_, line.data() + done, line.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = n < 0 ? std::strerror(errno) : "nothing written";
      // a part of the line may be in the file: it ends again after the last complete line
      std::string kept;
      if (regular_ && ::ftruncate(fd_, complete_) == 0) {
        ::lseek(fd_, complete_, SEEK_SET);
        kept = " (the file ends with the last complete row)";
      }
      throw CsvWriteError("cannot write '" + path_ + "': " + why + kept);
    }
    done += static_cast<std::size_t>(n);
  }
  complete_ += static_cast<long long>(line.size());
}

void CsvWriter::header(const std::vector<std::string>& columns) {
  std::string line;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i > 0) line += ',';
    line += csv_field(columns[i]);
  }
  write_line(line + "\n");
}

void CsvWriter::row(const std::vector<double>& values) {
  std::string line;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) line += ',';
    fmt::format_to(std::back_inserter(line), "{}", values[i]);
  }
  write_line(line + "\n");
}

void CsvWriter::close() {
  if (!owned_ || fd_ < 0) return;
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) {
    throw CsvWriteError("cannot write '" + path_ + "': " + std::strerror(errno));
  }
}

}  // namespace unidyn
