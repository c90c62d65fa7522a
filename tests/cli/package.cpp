// The C++ package: `cmake --install` into a scratch prefix, examples/embed configured with
// find_package(unidyn) against it, built and run; its last row of the double pendulum's run is the
// `unidyn simulate` command's, bit for bit (both evaluate the tape of the same equations); its
// embed-derive, through the commands layer, prints `unidyn derive`'s bytes; the installed command
// runs. Not under the sanitizers: a program built against their libraries
// would need their run-time too.
#include <filesystem>

#include "cli/cli_support.hpp"

namespace unidyn::cli_test {
namespace {

namespace fs = std::filesystem;

// A shell command's status; its output in `log`.
int shell(const std::string& command, const std::string& log) {
  return std::system(("(" + command + ") >'" + log + "' 2>&1").c_str());
}

std::vector<double> numbers(const std::string& line, char separator) {
  std::vector<double> values;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, separator);) values.push_back(std::stod(cell));
  return values;
}

TEST(Package, EmbedBuiltAgainstTheInstalledPackage) {
#ifdef UNIDYN_SANITIZED
  GTEST_SKIP() << "the package is tested in the plain build";
#endif
  const fs::path build = fs::path(UNIDYN_EXECUTABLE).parent_path();
  const fs::path source = fs::path(UNIDYN_MODELS_DIR).parent_path();
  const fs::path work = temp_path("package");
  const std::string log = (work.string() + ".log");
  const fs::path prefix = work / "prefix";
  ASSERT_EQ(
      shell("cmake --install '" + build.string() + "' --prefix '" + prefix.string() + "'", log), 0)
      << read_file(log);
  EXPECT_TRUE(fs::exists(prefix / "lib/cmake/unidyn/unidynConfig.cmake"));
  EXPECT_TRUE(fs::exists(prefix / "include/unidyn/integrate/simulation.hpp"));
  // everything under the prefix: the Python package too (nothing written elsewhere)
  bool python_package = false;
  for (const auto& entry : fs::recursive_directory_iterator(prefix / "lib")) {
    python_package = python_package || entry.path().filename() == "__init__.py";
  }
  EXPECT_TRUE(python_package);
  ASSERT_EQ(shell("cmake -S '" + (source / "examples/embed").string() + "' -B '" +
                      (work / "build").string() + "' -G Ninja -DCMAKE_PREFIX_PATH='" +
                      prefix.string() + "' && cmake --build '" + (work / "build").string() + "'",
                  log),
            0)
      << read_file(log);

  const std::string model = (source / "models/double-pendulum.yaml").string();
  const std::string out = work.string() + ".out";
  ASSERT_EQ(shell("'" + (work / "build/embed").string() + "' '" + model + "' 1", out), 0)
      << read_file(out);
  const auto embedded = lines_of(read_file(out));
  ASSERT_EQ(embedded.size(), 2u) << read_file(out);
  const Outcome cli = run("simulate '" + model + "' --t-end 1 --evaluation tape");
  ASSERT_EQ(cli.status, 0) << cli.err;
  const auto rows = lines_of(cli.out);
  ASSERT_GE(rows.size(), 2u);
  // the same columns, and the same last row
  std::string header = embedded[0];
  for (char& c : header) c = c == '\t' ? ',' : c;
  EXPECT_EQ(header, rows.front());
  EXPECT_EQ(numbers(embedded[1], '\t'), numbers(rows.back(), ','));

  // the commands layer from C++: derive's bytes (Kane's equations of the rolling disk)
  ASSERT_EQ(shell("'" + (work / "build/embed-derive").string() + "' rolling-disk kane", out), 0)
      << read_file(out);
  const Outcome derived = run("derive rolling-disk --method kane");
  ASSERT_EQ(derived.status, 0) << derived.err;
  EXPECT_EQ(read_file(out), derived.out);

  // the installed command
  ASSERT_EQ(shell("'" + (prefix / "bin/unidyn").string() + "' models", out), 0) << read_file(out);
  EXPECT_TRUE(contains(read_file(out), "double-pendulum")) << read_file(out);
  fs::remove_all(work);
  std::remove(log.c_str());
  std::remove(out.c_str());
}

}  // namespace
}  // namespace unidyn::cli_test
