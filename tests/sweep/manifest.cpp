// A sweep's plan (sweep/manifest.hpp): grid values and their order, random draws within their
// laws and the same from one seed, distinct run seeds, and the manifest read back bit for bit.
#include "unidyn/sweep/manifest.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {
namespace {

SweepManifest plan(const std::vector<std::string>& grid, const std::vector<std::string>& random,
                   std::size_t samples = 1, std::uint64_t seed = 1) {
  std::vector<GridAxis> g;
  std::vector<RandomAxis> r;
  for (const auto& text : grid) g.push_back(parse_grid_axis(text));
  for (const auto& text : random) r.push_back(parse_random_axis(text));
  return plan_sweep("/models/m.yaml", "model bytes", {2.0, 0.01, 0, ""}, g, r, samples, seed);
}

TEST(SweepManifest, GridPointsInOrderTheLastNameFastest) {
  const SweepManifest m = plan({"a=0:1:3", "b=10:20:2"}, {});
  ASSERT_EQ(m.runs.size(), 6u);
  const std::vector<std::vector<double>> expected{{0, 10},   {0, 20}, {0.5, 10},
                                                  {0.5, 20}, {1, 10}, {1, 20}};
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(m.runs[k].index, k);
    EXPECT_EQ(m.runs[k].values, expected[k]);
  }
  // both ends exactly, and a single value
  const SweepManifest v = plan({"v0=3:8:51"}, {});
  EXPECT_EQ(v.runs.front().values[0], 3.0);
  EXPECT_EQ(v.runs.back().values[0], 8.0);
  EXPECT_EQ(v.runs[25].values[0], 5.5);
  EXPECT_EQ(plan({"x=2:9:1"}, {}).runs.size(), 1u);
}

TEST(SweepManifest, RandomDrawsFollowTheirLawsFromTheSeed) {
  const SweepManifest m = plan({}, {"mu=U(0.1,0.3)", "k=N(5,2)"}, 20000, 7);
  ASSERT_EQ(m.runs.size(), 20000u);
  double sum_u = 0, sum_n = 0, square_n = 0;
  for (const auto& run : m.runs) {
    EXPECT_GE(run.values[0], 0.1);
    EXPECT_LT(run.values[0], 0.3);
    sum_u += run.values[0];
    sum_n += run.values[1];
    square_n += (run.values[1] - 5) * (run.values[1] - 5);
  }
  const double n = 20000;
  // U(0.1, 0.3): mean 0.2, standard deviation 0.2/√12 = 0.0577; N(5, 2): mean 5, sd 2 — the
  // sample means within 5 standard errors, the sample sd within 5 % (its error is 0.5 %)
  EXPECT_NEAR(sum_u / n, 0.2, 5 * 0.0577 / std::sqrt(n));
  EXPECT_NEAR(sum_n / n, 5.0, 5 * 2 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(square_n / n), 2.0, 0.1);
  // the same plan from the same seed, another from another
  EXPECT_EQ(manifest_text(plan({}, {"mu=U(0.1,0.3)"}, 50, 7)),
            manifest_text(plan({}, {"mu=U(0.1,0.3)"}, 50, 7)));
  EXPECT_NE(manifest_text(plan({}, {"mu=U(0.1,0.3)"}, 50, 7)),
            manifest_text(plan({}, {"mu=U(0.1,0.3)"}, 50, 8)));
  // each run's seed its own
  std::set<std::uint64_t> seeds;
  for (const auto& run : m.runs) seeds.insert(run.seed);
  EXPECT_EQ(seeds.size(), m.runs.size());
}

TEST(SweepManifest, GridTimesSamples) {
  const SweepManifest m = plan({"a=1:2:2"}, {"b=U(0,1)"}, 3);
  ASSERT_EQ(m.runs.size(), 6u);
  for (std::size_t k = 0; k < 6; ++k) EXPECT_EQ(m.runs[k].values[0], k < 3 ? 1.0 : 2.0);
}

TEST(SweepManifest, ReadBackBitForBit) {
  SweepManifest m = plan({"theta=0.1:1.3:7"}, {"m=N(1,0.3)"}, 5, 99);
  m.times = {0.1, 0.3, 2};
  const std::string path = testing::TempDir() + "manifest_roundtrip.yaml";
  std::ofstream(path) << manifest_text(m);
  const SweepManifest back = read_manifest(path);
  EXPECT_EQ(back.model, m.model);
  EXPECT_EQ(back.model_sha256, m.model_sha256);
  EXPECT_EQ(back.options.t_end, 2.0);
  EXPECT_EQ(back.options.output_step, 0.01);
  EXPECT_EQ(back.names, m.names);
  EXPECT_EQ(back.seed, 99u);
  EXPECT_EQ(back.times, m.times);
  ASSERT_EQ(back.runs.size(), m.runs.size());
  for (std::size_t k = 0; k < m.runs.size(); ++k) {
    EXPECT_EQ(back.runs[k].seed, m.runs[k].seed);
    EXPECT_EQ(back.runs[k].values, m.runs[k].values);  // shortest exact text: the same doubles
  }
  EXPECT_EQ(manifest_text(back), manifest_text(m));
  // a damaged row: named by file, line and column
  std::ofstream(path) << "unidyn_sweep: 1\nmodel: m\nmodel_sha256: x\noptions: {}\nseed: 1\n"
                         "names: [a]\nruns:\n  - [0, 5, 1]\n  - [1, 6]\n";
  try {
    read_manifest(path);
    ADD_FAILURE() << "a run without its value was read";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().line, 9);
    EXPECT_NE(std::string(e.what()).find("a run is [index, seed, 1 values]"), std::string::npos);
  }
  std::filesystem::remove(path);
}

// The digest a manifest is read with is its file's SHA-256 (as coreutils' sha256sum gives it),
// for a range of runs as for all of them.
TEST(SweepManifest, ReadWithTheDigestOfItsBytes) {
  const SweepManifest m = plan({"theta=0.1:1.3:7"}, {}, 1, 7);
  const std::string path = testing::TempDir() + "manifest_digest.yaml";
  std::ofstream(path) << manifest_text(m);
  std::string sha256sum(64, ' ');
  std::FILE* tool = ::popen(("sha256sum '" + path + "'").c_str(), "r");
  ASSERT_NE(tool, nullptr);
  ASSERT_EQ(std::fread(sha256sum.data(), 1, 64, tool), 64u);
  ::pclose(tool);
  EXPECT_EQ(read_manifest(path).sha256, sha256sum);
  EXPECT_EQ(read_manifest(path, {2, 3}).sha256, sha256sum);
  std::filesystem::remove(path);
}

// A manifest read for some of its runs holds those runs (as a whole read has them) and counts all;
// a row out of place outside the range is still found.
TEST(SweepManifest, ReadForARangeOfRuns) {
  const SweepManifest m = plan({"theta=0.1:1.3:7"}, {"m=N(1,0.3)"}, 5, 99);
  const std::string path = testing::TempDir() + "manifest_range.yaml";
  std::ofstream(path) << manifest_text(m);
  const SweepManifest some = read_manifest(path, {10, 13});
  EXPECT_EQ(some.run_count, 35u);
  ASSERT_EQ(some.runs.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(some.runs[k].index, 10 + k);
    EXPECT_EQ(some.runs[k].seed, m.runs[10 + k].seed);
    EXPECT_EQ(some.runs[k].values, m.runs[10 + k].values);
  }
  EXPECT_TRUE(read_manifest(path, {0, 0}).runs.empty());
  std::string text = manifest_text(m);
  const std::size_t row = text.find("\n  - [20, ");
  ASSERT_NE(row, std::string::npos);
  text.replace(row + 6, 2, "21");
  std::ofstream(path) << text;
  try {
    read_manifest(path, {0, 3});
    ADD_FAILURE() << "a run out of place was read";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("run 21 where run 20 was expected"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove(path);
}

TEST(SweepManifest, BadPlansRefused) {
  for (const char* text : {"a", "a=1:2", "a=1:2:0", "=1:2:3", "a=x:2:3", "a=1:2:3.5"}) {
    EXPECT_THROW(parse_grid_axis(text), std::invalid_argument) << text;
  }
  for (const char* text : {"a=U(1,1)", "a=N(0,0)", "a=V(0,1)", "a=U(0;1)", "a=U(0,1"}) {
    EXPECT_THROW(parse_random_axis(text), std::invalid_argument) << text;
  }
  EXPECT_THROW(plan({"a=0:1:2"}, {"a=U(0,1)"}), std::invalid_argument);           // a name twice
  EXPECT_THROW(plan({"a=0:1:10000", "b=0:1:10000"}, {}), std::invalid_argument);  // 10^8 runs
}

// Rows kept at times: a row's times only (t0 + k·step, or t_end), increasing, at most 1000.
TEST(SweepManifest, KeptTimesAreRowsTimes) {
  // rows of a run from 0.5 to 2 every 0.1 (0.5 + 0.1·3 is 0.8000000000000002: within 1e-9 of a
  // step)
  EXPECT_NO_THROW(check_kept_times({0.5, 0.8, 1.3, 2.0}, 0.5, 2.0, 0.1));
  EXPECT_NO_THROW(check_kept_times({1.95}, 0.0, 1.95, 0.1));  // t_end, off the grid: its last row
  for (const std::vector<double>& bad : std::vector<std::vector<double>>{
           {0.85}, {0.4}, {2.1}, {0.8, 0.6}, {0.8, 0.8}, {0.5 + 1e-6}}) {
    EXPECT_THROW(check_kept_times(bad, 0.5, 2.0, 0.1), std::invalid_argument) << bad.front();
  }
  std::vector<double> many;
  for (int k = 0; k <= 1000; ++k) many.push_back(k * 0.001);
  EXPECT_THROW(check_kept_times(many, 0.0, 1.0, 0.001), std::invalid_argument);
  many.pop_back();
  EXPECT_NO_THROW(check_kept_times(many, 0.0, 1.0, 0.001));
}

}  // namespace
}  // namespace unidyn
