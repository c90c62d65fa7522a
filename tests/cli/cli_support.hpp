// Running the `unidyn` command as a user runs it, for the command-line tests: its exit status,
// standard output and standard error; temporary files; reading its CSV.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace unidyn::cli_test {

struct Outcome {
  int status;
  std::string out;
  std::string err;
};

// A fresh temporary path, named by process id and call (ctest may run test cases in parallel).
inline std::string temp_path(const std::string& what) {
  static int counter = 0;
  return testing::TempDir() + "unidyn_cli_" + std::to_string(getpid()) + "_" +
         std::to_string(++counter) + "_" + what;
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

// Runs `unidyn ARGS` through the shell, standard output and standard error each to a file;
// `before` comes first on the command line (a pipe into unidyn, variables of its environment).
inline Outcome run(const std::string& args, const std::string& before = "") {
  // the bundled models are those the command was built with
  unsetenv("UNIDYN_MODELS");
  const std::string out_path = temp_path("stdout.txt"), err_path = temp_path("stderr.txt");
  const std::string command =
      before + " '" + UNIDYN_EXECUTABLE + "' " + args + " >'" + out_path + "' 2>'" + err_path + "'";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    ADD_FAILURE() << "popen failed for " << command;
    return {-1, "", ""};
  }
  const int raw = pclose(pipe);
  Outcome outcome{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_file(out_path), read_file(err_path)};
  std::remove(out_path.c_str());
  std::remove(err_path.c_str());
  return outcome;
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The lines of `text` that start with `prefix`.
inline std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
  std::vector<std::string> found;
  for (const auto& line : lines_of(text)) {
    if (line.starts_with(prefix)) found.push_back(line);
  }
  return found;
}

// Expects bad input: status 2, nothing on standard output, one line on standard error.
inline void expect_bad_input(const Outcome& r, const std::string& args) {
  EXPECT_EQ(r.status, 2) << args << "\nstderr: " << r.err;
  EXPECT_EQ(r.out, "") << args;
  ASSERT_FALSE(r.err.empty()) << args;
  EXPECT_EQ(lines_of(r.err).size(), 1u) << args << "\nstderr: " << r.err;
  EXPECT_EQ(r.err.back(), '\n') << args;
}

// A CSV file: its header and its rows of numbers.
struct Csv {
  std::string header;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  std::size_t index(const std::string& name) const {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (columns[i] == name) return i;
    }
    ADD_FAILURE() << "no column " << name << " in " << header;
    return 0;
  }
  double at(std::size_t row, const std::string& name) const { return rows.at(row).at(index(name)); }
};

inline std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

// Parses CSV text; every row must have a number in every column.
inline Csv parse_csv(const std::string& text) {
  Csv csv;
  const std::vector<std::string> lines = lines_of(text);
  if (lines.empty()) {
    ADD_FAILURE() << "no CSV header";
    return csv;
  }
  csv.header = lines[0];
  csv.columns = split(lines[0]);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::vector<double> row;
    for (const std::string& field : split(lines[i])) {
      std::size_t used = 0;
      double value = NAN;
      try {
        value = std::stod(field, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      EXPECT_TRUE(used == field.size() && !field.empty()) << "row " << i << ": '" << field << "'";
      EXPECT_TRUE(std::isfinite(value)) << "row " << i << ": " << field;
      row.push_back(value);
    }
    EXPECT_EQ(row.size(), csv.columns.size()) << "row " << i << ": " << lines[i];
    csv.rows.push_back(row);
  }
  return csv;
}

// The number after `label` in `text` (e.g. the drift after "relative drift ").
inline double number_after(const std::string& text, const std::string& label) {
  const std::size_t at = text.find(label);
  if (at == std::string::npos) {
    ADD_FAILURE() << "no '" << label << "' in\n" << text;
    return NAN;
  }
  return std::stod(text.substr(at + label.size()));
}

}  // namespace unidyn::cli_test
