// CSV writer: one write(2) per line, every error checked, the file cut back to its last complete
// line when a write fails.
#include "unidyn/io/csv.hpp"

#include <fcntl.h>
#include <fmt/compile.h>
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
  if (fd_ < 0) return;
  // an error here is lost (close() reports it)
  try {
    flush();
  } catch (const CsvWriteError&) {
  }
  if (owned_ && fd_ >= 0) ::close(fd_);
}

bool CsvWriter::write_bytes(std::size_t from, std::size_t to) {
  while (from < to) {
    const ssize_t n = ::write(fd_, block_.data() + from, to - from);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;
      return false;
    }
    from += static_cast<std::size_t>(n);
  }
  return true;
}

void CsvWriter::flush() {
  if (fd_ < 0) throw CsvWriteError("cannot write '" + path_ + "': it is closed");
  written_ = std::chrono::steady_clock::now();
  const std::size_t lines = line_ends_.size();
  const std::size_t rows = header_pending_ ? lines - 1 : lines;
  if (write_bytes(0, block_.size())) {
    complete_ += static_cast<long long>(block_.size());
    rows_written_ += rows;
    block_.clear();
    line_ends_.clear();
    header_pending_ = false;
    return;
  }
  std::string why = std::strerror(errno);
  // a part of the block may be in the file: it ends again after the last complete line, and
  // the block's lines go again one by one, as far as they fit (a pipe cannot be cut back)
  std::string kept;
  if (regular_ && ::ftruncate(fd_, complete_) == 0 && ::lseek(fd_, complete_, SEEK_SET) >= 0) {
    std::size_t start = 0;
    for (std::size_t k = 0; k < lines; ++k) {
      if (!write_bytes(start, line_ends_[k])) {
        why = std::strerror(errno);
        if (::ftruncate(fd_, complete_) == 0) ::lseek(fd_, complete_, SEEK_SET);
        break;
      }
      complete_ += static_cast<long long>(line_ends_[k] - start);
      if (k > 0 || !header_pending_) ++rows_written_;
      start = line_ends_[k];
    }
    kept = " (the file ends with the last complete row)";
  }
  block_.clear();
  line_ends_.clear();
  header_pending_ = false;
  throw CsvWriteError("cannot write '" + path_ + "': " + why + kept);
}

void CsvWriter::maybe_flush() {
  constexpr std::size_t block_bytes = 64 * 1024;
  constexpr std::chrono::milliseconds patience(200);
  if (block_.size() >= block_bytes || std::chrono::steady_clock::now() - written_ >= patience) {
    flush();
  }
}

void CsvWriter::header(const std::vector<std::string>& columns) {
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i > 0) block_ += ',';
    block_ += csv_field(columns[i]);
  }
  block_ += '\n';
  line_ends_.push_back(block_.size());
  header_pending_ = true;
  flush();
}

void CsvWriter::row(const std::vector<double>& values) {
  if (fd_ < 0) throw CsvWriteError("cannot write '" + path_ + "': it is closed");
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) block_ += ',';
    // the shortest text that reads back to the same double
    char text[32];  // at most 24 characters
    block_.append(text, fmt::format_to(text, FMT_COMPILE("{}"), values[i]));
  }
  block_ += '\n';
  line_ends_.push_back(block_.size());
  maybe_flush();
}

void CsvWriter::close() {
  if (fd_ < 0) return;
  flush();
  if (!owned_) return;
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) {
    throw CsvWriteError("cannot write '" + path_ + "': " + std::strerror(errno));
  }
}

}  // namespace unidyn
