// `unidyn report` opened in a real browser (Debian's headless Chromium): for a particle model, the
// heavy top and the rolling disk the page checks itself (#selftest: no errors, every plot and phase
// portrait drawn, the 3-D view drawn and different at the run's first and last instants, each
// body turned as its Euler parameters say, the equations rendered as MathML), and two screenshots
// at two instants differ; the screenshots are
// kept in build/tests/artefacts. A 10 s run of a bundled model makes a page under 2 MB.
#include <filesystem>
#include <iostream>
#include <string>

#include "cli/cli_support.hpp"

namespace unidyn::cli_test {
namespace {

// A command's standard output (through the shell), and whether it exited with 0.
std::pair<bool, std::string> shell(const std::string& command) {
  const std::string out = temp_path("shell.txt");
  const int status = std::system((command + " >'" + out + "' 2>/dev/null").c_str());
  std::string text = read_file(out);
  std::remove(out.c_str());
  return {status == 0, text};
}

// Headless Chromium as the machine runs it here: no sandbox (root), no network of its own, a
// fresh profile, WebGL in software.
std::string chromium(const std::string& profile) {
  return "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic "
         "--no-first-run --disable-background-networking --disable-component-update "
         "--disable-sync --enable-unsafe-swiftshader --virtual-time-budget=4000 "
         "--window-size=1000,1400 --user-data-dir='" +
         profile + "'";
}

// The number after "name": in the self-test's JSON (−1 when it is not there).
double value(const std::string& json, const std::string& name) {
  const std::size_t at = json.find("\"" + name + "\":");
  return at == std::string::npos ? -1 : std::stod(json.substr(at + name.size() + 3));
}
int count(const std::string& json, const std::string& name) {
  return static_cast<int>(value(json, name));
}

// The page opened in headless Chromium with #selftest: the document as drawn, and the self-test's
// result (its JSON; "" when the page did not finish it).
struct SelfTest {
  std::string dom, result;
};
SelfTest self_test(const std::string& page, const std::string& profile) {
  const auto [loaded, dom] =
      shell(chromium(profile) + " --dump-dom 'file://" + page + "#selftest'");
  const std::size_t at = dom.find("<pre id=\"selftest\">");
  if (!loaded || at == std::string::npos) return {dom, ""};
  return {dom, dom.substr(at, dom.find("</pre>", at) - at)};
}

class Report : public testing::TestWithParam<std::string> {};

TEST_P(Report, DrawsItselfInChromium) {
#ifdef UNIDYN_SANITIZED
  // the page is the same bytes in both builds; Chromium's 25 s a page are spent in the plain one
  GTEST_SKIP() << "the page is drawn in Chromium in the plain build";
#endif
  ASSERT_TRUE(shell("command -v chromium").first)
      << "chromium is not installed: scripts/setup.sh test installs it";
  const std::string model = GetParam();
  const std::string page = temp_path(model + ".html");
  // the driven pendulum about its inverted position: a periodic motion (Floquet multipliers)
  const std::string point = model == "driven-pendulum" ? " --at phi=0" : "";
  const Outcome made = run("report " + model + point + " --t-end 2 -o '" + page + "'");
  ASSERT_EQ(made.status, 0) << made.out << made.err;
  EXPECT_TRUE(contains(made.out, "written to " + page)) << made.out;
  const std::string profile = temp_path("chromium-profile");

  const auto [dom, result] = self_test(page, profile);
  ASSERT_FALSE(result.empty()) << "the page did not finish its self-test: " << dom;
  EXPECT_TRUE(contains(result, "\"errors\":[]")) << result;
  EXPECT_GT(count(result, "plots"), 0) << result;
  EXPECT_EQ(count(result, "plots_drawn"), count(result, "plots")) << result;
  EXPECT_GT(count(result, "portraits"), 0) << result;
  EXPECT_EQ(count(result, "portraits_drawn"), count(result, "portraits")) << result;
  EXPECT_TRUE(contains(result, "\"scene_drawn\":true")) << result;
  EXPECT_TRUE(contains(result, "\"scene_moves\":true")) << result;
  EXPECT_GE(count(result, "math"), 1) << result;
  EXPECT_EQ(count(result, "math_errors"), 0) << result;
  EXPECT_GE(count(result, "actors"), 1) << result;
  // the rolling disk's equilibria (upright or not, at rest) listed
  if (model == "rolling-disk") {
    EXPECT_GE(count(result, "equilibria"), 1) << result;
  }
  // the constraint force on the pendulum's particle and on the disk as arrows (the top has no
  // constraints), the pendulum's sphere |r| = L drawn (report/constraint_surfaces.hpp)
  EXPECT_EQ(count(result, "arrows"), model == "heavy-top" || model == "driven-pendulum" ? 0 : 1)
      << result;
  EXPECT_EQ(count(result, "surfaces"), model == "spherical-pendulum-cartesian" ? 1 : 0) << result;
  // the modes of an operating point: the disk's first equilibrium (upright at rest: θ, ψ̇, θ̇,
  // φ̇, four eigenvalues, one of each complex pair listed); the top's Euler angles are singular
  // at its equilibria and its initial state moves: none
  if (model == "rolling-disk") {
    EXPECT_GE(count(result, "modes"), 3) << result;
  }
  if (model == "heavy-top") {
    EXPECT_EQ(count(result, "modes"), -1) << result;
  }
  // the driven pendulum's two multipliers in place of modes
  if (model == "driven-pendulum") {
    EXPECT_EQ(count(result, "modes"), 2) << result;
  }
  // each body turned as its Euler parameters say (to float precision: the page's data is float32)
  EXPECT_GE(value(result, "orientation_error"), 0.0) << result;
  EXPECT_LT(value(result, "orientation_error"), 1e-5) << result;
  // shown within a second (the test prints how long it took)
  std::cout << model << ": the first picture after " << value(result, "ready_ms") << " ms\n";

  // two instants, two different pictures, kept as artefacts
  std::filesystem::create_directories("artefacts");
  std::string shots[2];
  const char* instants[2] = {"0.3", "1.7"};
  for (int k = 0; k < 2; ++k) {
    const std::string png = "artefacts/report-" + model + "-t" + instants[k] + ".png";
    ASSERT_TRUE(shell(chromium(profile) + " --screenshot='" + png + "' 'file://" + page +
                      "#t=" + instants[k] + "'")
                    .first);
    shots[k] = read_file(png);
    EXPECT_GT(shots[k].size(), 10000u) << png;
  }
  EXPECT_NE(shots[0], shots[1]);
  std::filesystem::remove_all(profile);
  std::remove(page.c_str());
}

INSTANTIATE_TEST_SUITE_P(Bundled, Report,
                         testing::Values("spherical-pendulum-cartesian", "heavy-top",
                                         "rolling-disk", "driven-pendulum"),
                         [](const auto& parameter) {
                           std::string name = parameter.param;
                           for (char& c : name) c = c == '-' ? '_' : c;
                           return name;
                         });

// A long run (2·10^5 rows): the page carries its envelope, at most 20 000 rows, says so, and draws
// every plot and portrait without an error (past ~150 000 rows the page used to throw a RangeError
// and 10^6 rows made 68 MB). A value past the float's range is a gap the plot names.
TEST(Report, ALongRunIsThinnedAndDrawn) {
#ifdef UNIDYN_SANITIZED
  GTEST_SKIP() << "the page is drawn in Chromium in the plain build";
#endif
  ASSERT_TRUE(shell("command -v chromium").first)
      << "chromium is not installed: scripts/setup.sh test installs it";
  const std::string model = temp_path("long.yaml"), page = temp_path("long.html");
  // a particle on a line, x = e^t: past t = 88.7 x is beyond the float's range (3.4e38)
  write_file(model,
             "unidyn: 1\nparameters: {m: 1}\ncoordinates: [x]\nparticles:\n"
             "  P: {mass: m, position: [x, 0, 0]}\nforces:\n"
             "  - force: {at: P, value: \"[m*x, 0, 0]\"}\ninitial: {x: 1, der(x): 1}\n");
  const Outcome made =
      run("report '" + model + "' --t-end 100 --output-step 5e-4 -o '" + page + "'");
  ASSERT_EQ(made.status, 0) << made.out << made.err;
  const std::string html = read_file(page);
  EXPECT_TRUE(contains(html, "\"rows\": 200001, \"rows_shown\": ")) << html.size();
  EXPECT_LT(html.size(), 3'000'000u);
  const std::string profile = temp_path("chromium-profile");
  const auto [dom, result] = self_test(page, profile);
  ASSERT_FALSE(result.empty()) << "the page did not finish its self-test: " << dom;
  EXPECT_TRUE(contains(result, "\"errors\":[]")) << result;
  EXPECT_EQ(count(result, "plots_drawn"), count(result, "plots")) << result;
  EXPECT_EQ(count(result, "portraits_drawn"), count(result, "portraits")) << result;
  EXPECT_TRUE(contains(dom, "This page shows ")) << dom.substr(0, 2000);
  EXPECT_TRUE(contains(dom, "not finite, so not drawn: x at ")) << dom.substr(0, 2000);
  std::filesystem::remove_all(profile);
  std::remove(page.c_str());
  std::remove(model.c_str());
  // docs/commands.md's example
  const Outcome kepler = run("report kepler --t-end 2000 --output-step 0.01 -o '" + page + "'");
  ASSERT_EQ(kepler.status, 0) << kepler.out << kepler.err;
  EXPECT_TRUE(contains(read_file(page), "\"rows\": 200001, \"rows_shown\": 4432,"));
  EXPECT_LT(std::filesystem::file_size(page), 1'300'000u);
  std::remove(page.c_str());
}

// The size a user gets for a 10 s run (the bicycle: four bodies, 1001 rows).
TEST(Report, TenSecondsUnderTwoMegabytes) {
#ifdef UNIDYN_SANITIZED
  // the page is the same bytes in both builds (25 s of the bicycle under the sanitizers)
  GTEST_SKIP() << "the page's size is measured in the plain build";
#endif
  const std::string page = temp_path("bicycle.html");
  const Outcome made = run("report bicycle --t-end 10 -o '" + page + "'");
  ASSERT_EQ(made.status, 0) << made.out << made.err;
  EXPECT_LT(std::filesystem::file_size(page), 2'000'000u);
  std::remove(page.c_str());
}

// The bead on the hoop: its four equilibria and their verdicts in the page's data; a model with
// friction says why none were sought.
TEST(Report, EquilibriaInThePage) {
  const std::string page = temp_path("hoop.html");
  ASSERT_EQ(run("report rotating-hoop --t-end 1 -o '" + page + "'").status, 0);
  const std::string html = read_file(page);
  // the page's equilibria, up to the operating point after them
  const std::size_t from = html.find("\"equilibria\": ");
  const std::string hoop = html.substr(from, html.find("\n\"operating_point\"", from) - from);
  EXPECT_TRUE(hoop.starts_with("\"equilibria\": {\"starts\": 100")) << hoop;
  std::size_t stable = 0;
  for (std::size_t at = hoop.find("\"stability\": \"linearly stable\""); at != std::string::npos;
       at = hoop.find("\"stability\": \"linearly stable\"", at + 1)) {
    ++stable;
  }
  EXPECT_EQ(stable, 2u);  // ±acos(−g/(R0 Ω²)); the top and bottom are unstable
  // their eigenvalues ±iω, ω² = Ω² − g²/(R0² Ω²) = 29.43 (Ω² = 2 g/R0 here): ω = 5.42494
  std::size_t oscillating = 0;
  for (std::size_t at = hoop.find("\"eigenvalues\": [\"0\u00b15.42494i\"]");
       at != std::string::npos; at = hoop.find("\"eigenvalues\": [\"0\u00b15.42494i\"]", at + 1)) {
    ++oscillating;
  }
  EXPECT_EQ(oscillating, 2u);
  ASSERT_EQ(run("report block-incline --t-end 1 -o '" + page + "'").status, 0);
  EXPECT_TRUE(contains(read_file(page),
                       "\"equilibria\": {\"not_sought\": \"constraint 'plane' has friction"));
  std::remove(page.c_str());
}

// The linearisation the page shows: about the point given with --at, else the initial state when
// it is an equilibrium, else the first equilibrium found; the bead on the hoop, φ from the top,
// φ'' = (Ω² cos φ + g/R0) sin φ with Ω² = 2 g/R0: at the top λ² = Ω² + g/R0 = 3 g/R0 = 58.86, at
// the bottom λ² = Ω² − g/R0 = g/R0 = 19.62, both unstable.
TEST(Report, ModesOfAnOperatingPoint) {
  const std::string page = temp_path("hoop-modes.html");
  const auto operating_point = [&](const std::string& options) {
    const Outcome made = run("report rotating-hoop --t-end 0.1 -o '" + page + "' " + options);
    EXPECT_EQ(made.status, 0) << made.err;
    const std::string html = read_file(page);
    const std::size_t at = html.find("\"operating_point\": ");
    return at == std::string::npos ? std::string()
                                   : html.substr(at, html.find("\n\"scene\"", at) - at);
  };
  const std::string top = operating_point("--at phi=0");
  EXPECT_TRUE(contains(top, "\"label\": \"the operating point given: phi=0\"")) << top;
  EXPECT_TRUE(contains(top, "\"eigenvalue\": \"7.67203\"")) << top;
  EXPECT_TRUE(contains(top, "\"eigenvalue\": \"-7.67203\"")) << top;
  EXPECT_TRUE(contains(top, "\"stability\": \"unstable\"")) << top;
  // A in the LaTeX (JSON doubles its backslashes)
  EXPECT_TRUE(contains(top, R"(\\begin{bmatrix} 0 & 1 \\\\ 58.86 & 0 \\end{bmatrix})")) << top;
  const std::string bottom = operating_point("--set phi0=3.141592653589793");
  EXPECT_TRUE(contains(bottom, "\"label\": \"the initial state\"")) << bottom;
  EXPECT_TRUE(contains(bottom, "\"eigenvalue\": \"4.42945\"")) << bottom;
  // released at φ0 = 2.5 it moves: the first equilibrium's (the table's first row)
  EXPECT_TRUE(contains(operating_point(""), "\"label\": \"the first equilibrium found\""));
  // the top's initial state moves and its equilibria are at gimbal lock: why there is none
  const Outcome top_page = run("report heavy-top --t-end 0.1 -o '" + page + "'");
  ASSERT_EQ(top_page.status, 0);
  EXPECT_TRUE(contains(read_file(page),
                       "\"operating_point\": {\"none\": \"the initial state "
                       "is not one: the acceleration of theta is"));
  // a point that is not one, or not a coordinate: bad input
  EXPECT_EQ(run("report rotating-hoop --at phi=1 -o '" + page + "'").status, 2);
  EXPECT_EQ(run("report rotating-hoop --at psi=1 -o '" + page + "'").status, 2);
  std::remove(page.c_str());
}

// Equal input, the same bytes.
TEST(Report, SamePageOnEveryRun) {
  const std::string first = temp_path("first.html"), again = temp_path("again.html");
  ASSERT_EQ(run("report double-pendulum --t-end 1 -o '" + first + "'").status, 0);
  ASSERT_EQ(
      run("report double-pendulum --t-end 1 -o '" + again + "'", "UNIDYN_RANDOM_LAYOUT=1").status,
      0);
  EXPECT_EQ(read_file(first), read_file(again));
  std::remove(first.c_str());
  std::remove(again.c_str());
}

// Names are data: a model name and an output name holding "<!--<script>" and "</script>" cannot
// end the page's data element or put the HTML parser in its double-escaped script state (a blank
// page): the page has its two <script> elements and no "<!--" at all.
TEST(Report, NamesCannotEndTheScriptElement) {
  const std::string model = temp_path("script-names.yaml"), page = temp_path("script-names.html");
  write_file(model,
             "unidyn: 1\nname: \"x <!--<script> </script> y\"\nparameters: {m: 1, g: 9.81}\n"
             "coordinates: [z]\nparticles:\n  P: {mass: m, position: [0, 0, z]}\n"
             "forces:\n  - gravity: -g*E3\noutputs:\n  \"<!--<script>\": z\n"
             "simulate: {t_end: 0.1, output_step: 0.01}\n");
  const Outcome r = run("report '" + model + "' -o '" + page + "'");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const std::string html = read_file(page);
  std::size_t scripts = 0;
  for (std::size_t at = html.find("<script"); at != std::string::npos;
       at = html.find("<script", at + 1)) {
    ++scripts;
  }
  EXPECT_EQ(scripts, 2u);
  EXPECT_EQ(html.find("<!--"), std::string::npos);
  EXPECT_NE(html.find("x \\u003c!--\\u003cscript> \\u003c/script> y"), std::string::npos);
  std::remove(page.c_str());
}

// The page is written whole at the end: a report killed on its way (here while it simulates: a
// run of 1000 s took 0.58 s in all, and a kill at 0.5 s landed anywhere) leaves the previous page
// as it was (it used to be truncated to 0 bytes at the start), and no temporary file. A kill
// while the page is written: io/atomic_file.
TEST(Report, AKilledReportLeavesThePreviousPage) {
  const std::string directory = temp_path("killed-report");
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  const std::string page = directory + "/page.html";
  write_file(page, "the previous page\n");
  const Outcome r = run("report double-pendulum --t-end 1e5 --output-step 10 -o '" + page + "'",
                        "timeout -s TERM 0.5");
  EXPECT_NE(r.status, 0) << "the report ended before it was killed";
  EXPECT_EQ(read_file(page), "the previous page\n");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(directory)) ++files;
  EXPECT_EQ(files, 1u);
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace unidyn::cli_test
