// The CSV writer: RFC 4180 header quoting, numbers that read back exactly, and write failures that
// throw and leave the file ending with its last complete row.
#include "unidyn/io/csv.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace unidyn {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string temp_file(const std::string& name) {
  return ::testing::TempDir() + "unidyn-csv-" + std::to_string(::getpid()) + "-" + name;
}

TEST(Csv, HeaderQuotingAndExactNumbers) {
  EXPECT_EQ(csv_field("x"), "x");
  EXPECT_EQ(csv_field("der(x)"), "der(x)");
  EXPECT_EQ(csv_field("a, b"), "\"a, b\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
  const std::string path = temp_file("exact.csv");
  {
    CsvWriter csv(path);
    csv.header({"t", "a, b"});
    csv.row({0.1, 1.0 / 3.0});
    csv.close();
  }
  EXPECT_EQ(read_file(path), "t,\"a, b\"\n0.1,0.3333333333333333\n");
}

TEST(Csv, AFullDeviceIsAnError) {
  CsvWriter csv("/dev/full");
  EXPECT_THROW(csv.header({"t"}), CsvWriteError);
}

// A file size limit (as a full disk would): the block that crosses it throws, is written again
// row by row as far as it fits, and the file ends with the last complete row, not in the middle of
// a number — every row that fits is kept, and rows_written() counts them.
TEST(Csv, AFailedWriteKeepsTheCompleteRows) {
  const std::string path = temp_file("limit.csv");
  rlimit previous{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &previous), 0);
  const auto old_handler = ::signal(SIGXFSZ, SIG_IGN);
  rlimit limited = previous;
  limited.rlim_cur = 1000;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limited), 0);
  std::size_t rows_written = 0;
  std::string error;
  {
    CsvWriter csv(path);
    try {
      csv.header({"t", "x", "y"});
      for (std::size_t rows = 0; rows < 1000; ++rows) {
        const auto r = static_cast<double>(rows);
        csv.row({r * 0.1, r / 3.0, -2.0 / 7.0});
      }
      csv.close();
    } catch (const CsvWriteError& e) {
      error = e.what();
    }
    rows_written = csv.rows_written();
  }
  ::setrlimit(RLIMIT_FSIZE, &previous);
  ::signal(SIGXFSZ, old_handler);
  EXPECT_NE(error.find("the file ends with the last complete row"), std::string::npos) << error;
  const std::string text = read_file(path);
  ASSERT_FALSE(text.empty());
  EXPECT_LE(text.size(), 1000u);
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')), rows_written + 1);
  // as many rows as fit: the next one would have crossed the limit
  const auto r = static_cast<double>(rows_written);
  const std::string next = fmt::format("{},{},{}\n", r * 0.1, r / 3.0, -2.0 / 7.0);
  EXPECT_GT(text.size() + next.size(), 1000u) << text.size() << " + " << next;
  std::filesystem::remove(path);
}

// Rows wait in a block and reach the file at close(), all of them, counted.
TEST(Csv, RowsReachTheFileAtTheLatestOnClose) {
  const std::string path = temp_file("block.csv");
  CsvWriter csv(path);
  csv.header({"t"});
  EXPECT_EQ(read_file(path), "t\n");  // the header at once
  for (int k = 0; k < 10; ++k) csv.row({k * 0.25});
  csv.close();
  EXPECT_EQ(csv.rows_written(), 10u);
  EXPECT_EQ(read_file(path), "t\n0\n0.25\n0.5\n0.75\n1\n1.25\n1.5\n1.75\n2\n2.25\n");
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace unidyn
