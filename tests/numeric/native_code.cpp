// Native code: every tape operation compiled by the system compiler gives the tape's own value,
// bit for bit; the cache by key; a library that does not prove its key and signature is never
// called (a collision of names, a forged library, a damaged file); one compilation among
// concurrent builds; failures that leave the tape in charge.
#include "unidyn/numeric/native_code.hpp"

#include "unidyn/numeric/digest.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace unidyn {
namespace {

NativeOptions in_temporary_cache(const std::string& name) {
  NativeOptions options;
  options.cache_directory = ::testing::TempDir() + "unidyn-native-" + name;
  std::filesystem::remove_all(options.cache_directory);
  return options;
}

// Every operation of the tape, shared subexpressions, sincos, constants (π, 1/3) and an output
// that is an input.
Tape every_operation() {
  const GiNaC::realsymbol x("x"), y("y"), z("z");
  const GiNaC::ex third = GiNaC::numeric(1, 3);
  const std::vector<GiNaC::ex> outputs{
      x + y,
      x - y * third,
      x * y * z,
      x / y,
      -x,
      1 / (x + z),
      GiNaC::sqrt(GiNaC::abs(z) + 1),
      GiNaC::pow(GiNaC::abs(x) + 1, y),
      GiNaC::sin(x) * GiNaC::cos(x) + GiNaC::Pi,
      GiNaC::tan(y) + GiNaC::asin(z / 10) + GiNaC::acos(z / 10) + GiNaC::atan(x),
      GiNaC::atan2(y, x),
      GiNaC::sinh(z) + GiNaC::cosh(z) + GiNaC::tanh(z),
      GiNaC::exp(x) + GiNaC::log(GiNaC::abs(y) + 2),
      GiNaC::csgn(x) + GiNaC::step(y),
      GiNaC::pow(x, 7) + GiNaC::pow(y, -3),
      z,
  };
  return Tape::compile(outputs, std::vector<GiNaC::realsymbol>{x, y, z});
}

TEST(NativeCode, EveryOperationAgreesWithTheTapeBitForBit) {
  const Tape tape = every_operation();
  const auto library = NativeLibrary::build({{"f", &tape}}, in_temporary_cache("ops"));
  const NativeFunction f = library->function("f");
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-3, 3);
  std::vector<double> native(tape.output_count());
  std::size_t compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> in{value(random), value(random), value(random)};
    if (trial == 0) in = {0.0, 0.0, 1.0};  // sign and step at 0
    const std::vector<double> expected = tape.evaluate(in);
    f(in.data(), native.data());
    for (std::size_t k = 0; k < expected.size(); ++k) {
      if (std::isnan(expected[k])) {
        EXPECT_TRUE(std::isnan(native[k])) << k;
        continue;
      }
      EXPECT_EQ(native[k], expected[k]) << "output " << k << " trial " << trial;
      ++compared;
    }
  }
  EXPECT_GT(compared, 3000u);
}

// A long tape is compiled in parts over an array of registers (native_source.cpp); values made in
// one part and used in later ones, sincos among them, still give the tape's results bit for bit.
TEST(NativeCode, ALongTapeInPartsAgreesWithTheTapeBitForBit) {
  const GiNaC::realsymbol x("x"), y("y");
  // 700 terms sin(a_k) cos(a_k) (1 + c_k y), a_k = c_k x + y: the sum's running total and the
  // terms of the outputs below cross the parts
  std::vector<GiNaC::ex> outputs;
  GiNaC::ex sum = 0;
  for (int k = 0; k < 700; ++k) {
    const GiNaC::ex c = GiNaC::numeric(k + 1, 1000), a = c * x + y;
    const GiNaC::ex term = GiNaC::sin(a) * GiNaC::cos(a) * (1 + c * y);
    sum += term;
    if (k % 100 == 0) outputs.push_back(term);
  }
  outputs.push_back(sum);
  const Tape tape = Tape::compile(outputs, std::vector<GiNaC::realsymbol>{x, y});
  ASSERT_GT(tape.instruction_count(), 3000u);
  ASSERT_NE(tape_source(tape, "f").find("f_part1("), std::string::npos);
  const auto library = NativeLibrary::build({{"f", &tape}}, in_temporary_cache("parts"));
  const NativeFunction f = library->function("f");
  std::mt19937 random(3);
  std::uniform_real_distribution<double> value(-1, 1);
  std::vector<double> native(tape.output_count());
  for (int trial = 0; trial < 50; ++trial) {
    const std::vector<double> in{value(random), value(random)};
    const std::vector<double> expected = tape.evaluate(in);
    f(in.data(), native.data());
    EXPECT_EQ(native, expected) << "trial " << trial;
  }
}

// The second build of the same source loads the cached library; another source compiles anew.
TEST(NativeCode, CachedByTheHashOfItsSource) {
  const NativeOptions options = in_temporary_cache("cache");
  const Tape tape = every_operation();
  const auto first = NativeLibrary::build({{"f", &tape}}, options);
  EXPECT_FALSE(first->cached());
  EXPECT_GT(first->compile_seconds(), 0.0);
  EXPECT_GT(first->source_bytes(), 500u);
  const auto second = NativeLibrary::build({{"f", &tape}}, options);
  EXPECT_TRUE(second->cached());
  EXPECT_EQ(second->path(), first->path());
  const auto renamed = NativeLibrary::build({{"g", &tape}}, options);
  EXPECT_FALSE(renamed->cached());
  EXPECT_NE(renamed->path(), first->path());
  EXPECT_THROW((void)renamed->function("f"), NativeCodeError);
}

// No compiler, or a compiler that fails: NativeCodeError that says which command and why.
TEST(NativeCode, FailuresSayWhy) {
  const Tape tape = every_operation();
  NativeOptions missing = in_temporary_cache("missing");
  missing.compiler = "/nonexistent/c++";
  try {
    (void)NativeLibrary::build({{"f", &tape}}, missing);
    ADD_FAILURE() << "no error";
  } catch (const NativeCodeError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/c++"), std::string::npos)
        << error.what();
  }
  NativeOptions bad_flag = in_temporary_cache("bad-flag");
  bad_flag.flags += " --no-such-flag";
  try {
    (void)NativeLibrary::build({{"f", &tape}}, bad_flag);
    ADD_FAILURE() << "no error";
  } catch (const NativeCodeError& error) {
    EXPECT_NE(std::string(error.what()).find("no-such-flag"), std::string::npos) << error.what();
  }
  // nothing half-made is left in the cache (only the entry's lock)
  for (const auto& entry : std::filesystem::directory_iterator(bad_flag.cache_directory)) {
    if (entry.path().extension() != ".lock") ADD_FAILURE() << entry.path();
  }
}

// A small tape of other sizes than every_operation(): 1 input, 2 outputs.
Tape small_tape() {
  const GiNaC::realsymbol x("x");
  return Tape::compile({x * x + 1, GiNaC::sin(x)}, std::vector<GiNaC::realsymbol>{x});
}

// Every output of `f` equals the tape's at a few inputs.
void expect_tape_results(const Tape& tape, NativeFunction f) {
  std::vector<double> in(tape.input_count(), 0.25), out(tape.output_count());
  in[0] = 0.5;
  f(in.data(), out.data());
  const std::vector<double> expected = tape.evaluate(in);
  for (std::size_t k = 0; k < expected.size(); ++k) {
    if (!std::isnan(expected[k])) {
      EXPECT_EQ(out[k], expected[k]) << k;
    }
  }
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::string every_name_collides(std::string_view) {
  return "collision";
}

// Two keys that share a file, as a collision of the hash would make them: the second build finds
// the first's library, which says another key, so it is refused before any of its functions is
// looked up, removed and compiled again. (The small tape's library would write 2 outputs where
// every_operation() has 16, and read 1 input of 3.)
TEST(NativeCode, ALibraryOfAnotherKeyIsNeverCalled) {
  NativeOptions options = in_temporary_cache("collision");
  options.entry_name = &every_name_collides;
  const Tape small = small_tape(), big = every_operation();
  {
    const auto first = NativeLibrary::build({{"f", &small}}, options);
    EXPECT_FALSE(first->cached());
    expect_tape_results(small, first->function("f"));
  }
  auto second = NativeLibrary::build({{"f", &big}}, options);
  EXPECT_FALSE(second->cached());
  EXPECT_TRUE(contains(second->notes(), "refused (its key is")) << second->notes();
  expect_tape_results(big, second->function("f"));
  // While the big tape's library is loaded, dlopen would give it again for that file name: the
  // small tape gets no library rather than the wrong one.
  EXPECT_THROW((void)NativeLibrary::build({{"f", &small}}, options), NativeCodeError);
  // once it is unloaded, the small tape refuses the big one's library in turn
  const std::string path = second->path();
  second.reset();
  const auto third = NativeLibrary::build({{"f", &small}}, options);
  EXPECT_EQ(third->path(), path);
  EXPECT_TRUE(contains(third->notes(), "refused (its key is")) << third->notes();
  expect_tape_results(small, third->function("f"));
}

// A library that carries the right key but another signature (a forgery, or a bug in the key) is
// refused: its function, which would trap, is never called.
TEST(NativeCode, ALibraryWithAnotherSignatureIsNeverCalled) {
  const NativeOptions options = in_temporary_cache("forged");
  const Tape tape = every_operation();
  std::string path, key;
  {
    const auto genuine = NativeLibrary::build({{"f", &tape}}, options);
    path = genuine->path();
    key = std::filesystem::path(path).stem().string();
  }
  const std::string source = options.cache_directory + "/forged.cpp";
  std::ofstream(source) << "extern \"C\" const char unidyn_library_key[] = \"" << key << "\";\n"
                        << "extern \"C\" const char unidyn_library_source[] = \"\";\n"
                        << "extern \"C\" const char unidyn_library_signature[] = \"f 3 2\\n\";\n"
                        << "extern \"C\" void f(const double*, double*) { __builtin_trap(); }\n";
  const std::string command = "c++ -shared -fPIC -o '" + path + ".new' '" + source + "' && mv '" +
                              path + ".new' '" + path + "'";
  ASSERT_EQ(std::system(command.c_str()), 0);
  // its checksum made to match, so that only the library's own word can refuse it
  std::FILE* library = std::fopen(path.c_str(), "rb");
  ASSERT_NE(library, nullptr);
  const FileDigest digest = sha256_of_descriptor(fileno(library));
  std::fclose(library);
  std::ofstream(options.cache_directory + "/" + key + ".sum", std::ios::trunc)
      << "sha256 " << digest.sha256 << " size " << digest.size << "\n";
  const auto rebuilt = NativeLibrary::build({{"f", &tape}}, options);
  EXPECT_FALSE(rebuilt->cached());
  EXPECT_TRUE(contains(rebuilt->notes(), "its signature differs")) << rebuilt->notes();
  expect_tape_results(tape, rebuilt->function("f"));
}

// A library cut short (a crash while copying, a full disk) does not match its checksum: it is
// never handed to dlopen (which would die of SIGBUS), but removed and compiled again.
TEST(NativeCode, ADamagedLibraryIsRebuiltNotLoaded) {
  const NativeOptions options = in_temporary_cache("damaged");
  const Tape tape = every_operation();
  std::string path;
  {
    const auto first = NativeLibrary::build({{"f", &tape}}, options);
    path = first->path();
  }
  std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
  const auto second = NativeLibrary::build({{"f", &tape}}, options);
  EXPECT_FALSE(second->cached());
  EXPECT_TRUE(contains(second->notes(), "refused")) << second->notes();
  expect_tape_results(tape, second->function("f"));
  // a checksum file removed: the library alone is not trusted either
  std::filesystem::remove(std::filesystem::path(path).replace_extension(".sum"));
  const auto third = NativeLibrary::build({{"f", &tape}}, options);
  EXPECT_TRUE(contains(third->notes(), "checksum is missing")) << third->notes();
  const auto fourth = NativeLibrary::build({{"f", &tape}}, options);
  EXPECT_TRUE(fourth->cached());
  EXPECT_EQ(fourth->notes(), "");
}

// An entry that is a symbolic link (to a library elsewhere) is not followed: it is removed (the
// link, not its target) and the library compiled in its place.
TEST(NativeCode, ASymbolicLinkInTheCacheIsNotFollowed) {
  const NativeOptions options = in_temporary_cache("symlink");
  const Tape tape = every_operation();
  std::string path;
  {
    const auto first = NativeLibrary::build({{"f", &tape}}, options);
    path = first->path();
  }
  const std::string elsewhere = options.cache_directory + "/elsewhere.so";
  std::filesystem::rename(path, elsewhere);
  std::filesystem::create_symlink(elsewhere, path);
  const auto second = NativeLibrary::build({{"f", &tape}}, options);
  EXPECT_FALSE(second->cached());
  EXPECT_TRUE(contains(second->notes(), "refused")) << second->notes();
  EXPECT_FALSE(std::filesystem::is_symlink(path));
  EXPECT_TRUE(std::filesystem::exists(elsewhere));
  expect_tape_results(tape, second->function("f"));
}

// Concurrent builds of one new library: one compiles it, the others wait and load it.
TEST(NativeCode, ConcurrentBuildsCompileOnce) {
  const NativeOptions options = in_temporary_cache("concurrent");
  const Tape tape = every_operation();
  std::vector<std::shared_ptr<const NativeLibrary>> libraries(3);
  std::vector<std::thread> threads;
  for (auto& library : libraries) {
    threads.emplace_back([&] { library = NativeLibrary::build({{"f", &tape}}, options); });
  }
  for (auto& thread : threads) thread.join();
  int compiled = 0;
  for (const auto& library : libraries) {
    ASSERT_TRUE(library);
    compiled += library->cached() ? 0 : 1;
    expect_tape_results(tape, library->function("f"));
  }
  EXPECT_EQ(compiled, 1);
}

// Whatever the umask, the cache directory (and those created above it) is 0700 and its files 0600.
TEST(NativeCode, PrivateUnderAPermissiveUmask) {
  NativeOptions options = in_temporary_cache("umask");
  options.cache_directory += "/a/b";
  const Tape tape = small_tape();
  const mode_t previous = ::umask(0);
  const auto library = NativeLibrary::build({{"f", &tape}}, options);
  ::umask(previous);
  const auto mode = [](const std::filesystem::path& p) {
    struct stat s {};
    EXPECT_EQ(::stat(p.c_str(), &s), 0) << p;
    return s.st_mode & 07777;
  };
  EXPECT_EQ(mode(options.cache_directory), 0700u);
  EXPECT_EQ(mode(std::filesystem::path(options.cache_directory).parent_path()), 0700u);
  for (const auto& entry : std::filesystem::directory_iterator(options.cache_directory)) {
    EXPECT_EQ(mode(entry.path()), 0600u) << entry.path();
  }
}

}  // namespace
}  // namespace unidyn
