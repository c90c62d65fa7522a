// A sweep's manifest: the plan of its runs, written and read back (sweep/manifest.hpp).
#include "unidyn/sweep/manifest.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>

#include "unidyn/io/json_text.hpp"
#include "unidyn/numeric/digest.hpp"
#include "unidyn/symbolic/expression.hpp"

namespace unidyn {
namespace {

constexpr std::size_t kMostRuns = 10'000'000;

// A finite number, all of `text`.
std::optional<double> finite_number(std::string_view text) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return {};
  return value;
}

// A uniform double in [0, 1) from the top 53 bits of a 64-bit draw (the same on every platform).
double unit(std::mt19937_64& random) {
  return static_cast<double>(random() >> 11) * 0x1.0p-53;
}

// A standard normal draw by Box–Muller (one of the pair; the same on every platform).
double standard_normal(std::mt19937_64& random) {
  const double u = 1.0 - unit(random);  // (0, 1]
  const double v = unit(random);
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

// A number of the manifest in its shortest exact form.
std::string number(double x) {
  return fmt::format("{}", x);
}

}  // namespace

std::uint64_t run_seed(std::uint64_t seed, std::size_t index) {
  // SplitMix64 (Steele, Lea & Flood 2014) of the seed advanced by the index
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (static_cast<std::uint64_t>(index) + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

void check_kept_times(const std::vector<double>& times, double t0, double t_end,
                      double output_step) {
  if (times.size() > kMostKeptTimes) {
    throw std::invalid_argument(
        fmt::format("--times: {} times, more than {} (keep every row with "
                    "`unidyn simulate` of the runs wanted)",
                    times.size(), kMostKeptTimes));
  }
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    if (k > 0 && !(t > times[k - 1])) {
      throw std::invalid_argument(
          fmt::format("--times: {} after {}: give increasing times", t, times[k - 1]));
    }
    // a row's time, as the integrator's output grid makes them (nothing is interpolated)
    const double steps = (t - t0) / output_step;
    const bool on_grid = std::abs(steps - std::round(steps)) <= 1e-9 * std::max(1.0, steps);
    if (!(t >= t0 && t <= t_end) || !(on_grid || t == t_end)) {
      throw std::invalid_argument(fmt::format(
          "--times: t = {} is not the time of a row (rows are at {} + k·{} up to {}, and at "
          "events): give times on that grid",
          t, t0, output_step, t_end));
    }
  }
}

GridAxis parse_grid_axis(const std::string& text) {
  const std::size_t eq = text.find('='), c1 = text.find(':', eq), c2 = text.find(':', c1 + 1);
  const auto bad = [&] {
    return std::invalid_argument(text +
                                 ": expected NAME=FROM:TO:COUNT (numbers, COUNT an integer "
                                 "from 1 to 1000000)");
  };
  if (eq == 0 || eq == std::string::npos || c1 == std::string::npos || c2 == std::string::npos) {
    throw bad();
  }
  const auto from = finite_number(std::string_view(text).substr(eq + 1, c1 - eq - 1));
  const auto to = finite_number(std::string_view(text).substr(c1 + 1, c2 - c1 - 1));
  std::size_t count = 0;
  const std::string_view tail = std::string_view(text).substr(c2 + 1);
  const auto [end, error] = std::from_chars(tail.data(), tail.data() + tail.size(), count);
  if (!from || !to || error != std::errc() || end != tail.data() + tail.size() || count < 1 ||
      count > 1'000'000) {
    throw bad();
  }
  return {text.substr(0, eq), *from, *to, count};
}

RandomAxis parse_random_axis(const std::string& text) {
  const std::size_t eq = text.find('=');
  const auto bad = [&] {
    return std::invalid_argument(text +
                                 ": expected NAME=U(A,B) (uniform, A < B) or NAME=N(MEAN,SD) "
                                 "(normal, SD > 0)");
  };
  if (eq == 0 || eq == std::string::npos || text.size() < eq + 6 || text.back() != ')' ||
      text[eq + 2] != '(' || (text[eq + 1] != 'U' && text[eq + 1] != 'N')) {
    throw bad();
  }
  const std::string_view inside = std::string_view(text).substr(eq + 3, text.size() - eq - 4);
  const std::size_t comma = inside.find(',');
  if (comma == std::string_view::npos) throw bad();
  const auto a = finite_number(inside.substr(0, comma));
  const auto b = finite_number(inside.substr(comma + 1));
  const bool normal = text[eq + 1] == 'N';
  if (!a || !b || (normal ? !(*b > 0) : !(*a < *b))) throw bad();
  return {text.substr(0, eq), normal, *a, *b};
}

SweepManifest plan_sweep(const std::string& model_path, const std::string& model_bytes,
                         const SweepOptions& options, const std::vector<GridAxis>& grid,
                         const std::vector<RandomAxis>& random, std::size_t samples,
                         std::uint64_t seed) {
  SweepManifest m;
  m.model = model_path;
  m.model_sha256 = sha256_hex(model_bytes);
  m.options = options;
  m.seed = seed;
  std::set<std::string> seen;
  for (const auto& axis : grid) m.names.push_back(axis.name);
  for (const auto& axis : random) m.names.push_back(axis.name);
  for (const auto& name : m.names) {
    if (!seen.insert(name).second) throw std::invalid_argument(name + " is swept twice");
  }
  if (random.empty()) samples = 1;
  if (samples == 0) throw std::invalid_argument("--samples must be at least 1");
  double count = static_cast<double>(samples);
  for (const auto& axis : grid) count *= static_cast<double>(axis.count);
  if (count > static_cast<double>(kMostRuns)) {
    throw std::invalid_argument(
        fmt::format("the plan has {:.0f} runs, more than {}", count, kMostRuns));
  }
  // every grid point (the last axis fastest), each with its samples, drawn in the runs' order
  std::mt19937_64 draws(seed);
  const auto points = static_cast<std::size_t>(count) / samples;
  for (std::size_t point = 0; point < points; ++point) {
    std::vector<double> at(grid.size());
    std::size_t rest = point;
    for (std::size_t k = grid.size(); k-- > 0;) {
      const GridAxis& axis = grid[k];
      const std::size_t i = rest % axis.count;
      rest /= axis.count;
      at[k] = axis.count == 1 ? axis.from
                              : axis.from + (axis.to - axis.from) * static_cast<double>(i) /
                                                static_cast<double>(axis.count - 1);
    }
    for (std::size_t s = 0; s < samples; ++s) {
      SweepRun run;
      run.index = m.runs.size();
      run.seed = run_seed(seed, run.index);
      run.values = at;
      for (const auto& axis : random) {
        run.values.push_back(axis.normal ? axis.a + axis.b * standard_normal(draws)
                                         : axis.a + (axis.b - axis.a) * unit(draws));
      }
      m.runs.push_back(std::move(run));
    }
  }
  m.run_count = m.runs.size();
  return m;
}

std::string manifest_text(const SweepManifest& m) {
  std::string out = "# unidyn sweep plan: one row per run, [index, seed, " +
                    fmt::format("{}", fmt::join(m.names, ", ")) + "]\n";
  out += "unidyn_sweep: 1\nmodel: " + unidyn::quoted(m.model) +
         "\nmodel_sha256: " + unidyn::quoted(m.model_sha256) + "\noptions: {";
  std::vector<std::string> options;
  if (m.options.t_end > 0) options.push_back("t_end: " + number(m.options.t_end));
  if (m.options.output_step > 0) options.push_back("output_step: " + number(m.options.output_step));
  if (!m.options.method.empty()) options.push_back("method: " + unidyn::quoted(m.options.method));
  if (m.options.rtol > 0) options.push_back("rtol: " + number(m.options.rtol));
  out += fmt::format("{}", fmt::join(options, ", ")) + "}\nseed: " + std::to_string(m.seed) +
         "\nnames: [";
  for (std::size_t k = 0; k < m.names.size(); ++k) {
    out += (k ? ", " : "") + unidyn::quoted(m.names[k]);
  }
  out += "]\n";
  if (!m.modes_at.empty()) {
    out += "modes_at: [";
    for (std::size_t k = 0; k < m.modes_at.size(); ++k) {
      out += (k ? ", " : "") + unidyn::quoted(m.modes_at[k]);
    }
    out += "]\n";
  }
  if (!m.times.empty()) {
    std::vector<std::string> times;
    for (const double t : m.times) times.push_back(number(t));
    out += fmt::format("times: [{}]\n", fmt::join(times, ", "));
  }
  out += "runs:\n";
  for (const SweepRun& run : m.runs) {
    out += "  - [" + std::to_string(run.index) + ", " + std::to_string(run.seed);
    for (const double v : run.values) out += ", " + number(v);
    out += "]\n";
  }
  return out;
}

namespace {

// The header's fields (everything before `runs:`), read as YAML.
void read_header(const std::string& path, const std::string& header, SweepManifest& m) {
  const auto fail = [&](const YAML::Mark& mark, const std::string& what) {
    return ModelError({path, mark.line + 1, mark.column + 1}, what);
  };
  YAML::Node root;
  try {
    root = YAML::Load(header);
  } catch (const YAML::Exception& e) {
    throw fail(e.mark, "not a sweep manifest: " + e.msg);
  }
  if (!root.IsMap() || !root["unidyn_sweep"] || root["unidyn_sweep"].Scalar() != "1") {
    throw ModelError({path, 1, 1}, "not a sweep manifest (unidyn_sweep: 1 expected)");
  }
  try {
    m.model = root["model"].as<std::string>();
    m.model_sha256 = root["model_sha256"].as<std::string>();
    const YAML::Node options = root["options"];
    if (options["t_end"]) m.options.t_end = options["t_end"].as<double>();
    if (options["output_step"]) m.options.output_step = options["output_step"].as<double>();
    if (options["method"]) m.options.method = options["method"].as<std::string>();
    if (options["rtol"]) m.options.rtol = options["rtol"].as<double>();
    m.seed = root["seed"].as<std::uint64_t>();
    m.names = root["names"].as<std::vector<std::string>>();
    if (root["modes_at"]) m.modes_at = root["modes_at"].as<std::vector<std::string>>();
    if (root["times"]) {
      m.times = root["times"].as<std::vector<double>>();
      for (std::size_t k = 0; k < m.times.size(); ++k) {
        if (!std::isfinite(m.times[k]) || (k > 0 && !(m.times[k] > m.times[k - 1])) ||
            m.times.size() > kMostKeptTimes) {
          throw fail(root["times"].Mark(), fmt::format("not a sweep manifest: times are at most "
                                                       "{} increasing finite numbers",
                                                       kMostKeptTimes));
        }
      }
    }
  } catch (const YAML::Exception& e) {
    throw fail(e.mark, "not a sweep manifest: " + e.msg);
  }
}

// The fields of a run's line `  - [index, seed, v1, ...]` (as manifest_text writes it), or
// nothing. Only the index when `all` is false.
std::optional<std::vector<std::string_view>> run_fields(std::string_view line, bool all) {
  constexpr std::string_view open = "  - [";
  if (line.substr(0, open.size()) != open || line.empty() || line.back() != ']') return {};
  line = line.substr(open.size(), line.size() - open.size() - 1);
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    std::string_view field = line.substr(start, comma - start);
    while (!field.empty() && field.front() == ' ') field.remove_prefix(1);
    fields.push_back(field);
    if (comma == std::string_view::npos || !all) break;
    start = comma + 1;
  }
  return fields;
}

template <typename Integer>
std::optional<Integer> whole_number(std::string_view text) {
  Integer value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return {};
  return value;
}

// The lines of an open file, one at a time without its '\n' (getline(3): any length).
class LineReader {
 public:
  explicit LineReader(std::FILE* file) : file_(file) {}
  ~LineReader() { std::free(buffer_); }
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;
  bool next(std::string& line) {
    const ssize_t length = ::getline(&buffer_, &capacity_, file_);
    if (length < 0) return false;
    line.assign(buffer_, static_cast<std::size_t>(length));
    if (!line.empty() && line.back() == '\n') line.pop_back();
    return true;
  }

 private:
  std::FILE* file_;
  char* buffer_ = nullptr;
  std::size_t capacity_ = 0;
};

// One run from its line's fields, or nothing when a field is not a number.
std::optional<SweepRun> run_of(const std::vector<std::string_view>& fields) {
  SweepRun run;
  const auto index = whole_number<std::size_t>(fields[0]);
  const auto seed = whole_number<std::uint64_t>(fields[1]);
  if (!index || !seed) return {};
  run.index = *index;
  run.seed = *seed;
  for (std::size_t k = 2; k < fields.size(); ++k) {
    const auto value = finite_number(fields[k]);
    if (!value) return {};
    run.values.push_back(*value);
  }
  return run;
}

}  // namespace

SweepManifest read_manifest(const std::string& path, RunRange keep) {
  // digested, then read from the start, through one open file (a manifest replaced meanwhile is
  // another file)
  std::FILE* file = std::fopen(path.c_str(), "rbe");
  if (file == nullptr) throw std::invalid_argument("cannot read the manifest " + path);
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> closing(file, &std::fclose);
  SweepManifest m;
  m.sha256 = sha256_of_descriptor(::fileno(file)).sha256;
  if (::lseek(::fileno(file), 0, SEEK_SET) != 0) {
    throw std::invalid_argument("cannot read the manifest " + path);
  }
  LineReader in(file);
  std::string header, line;
  int number = 0;
  bool runs = false;
  while (!runs && in.next(line)) {
    ++number;
    runs = line == "runs:";
    if (!runs) header += line + "\n";
  }
  read_header(path, header, m);
  if (!runs) throw ModelError({path, number, 1}, "not a sweep manifest (runs: expected)");
  // the runs one line each, streamed: only those kept are held (a task of a 10^7-run manifest)
  const std::string expected = fmt::format("a run is [index, seed, {} values]", m.names.size());
  while (in.next(line)) {
    ++number;
    const bool kept = m.run_count >= keep.first && m.run_count < keep.last;
    const auto fields = run_fields(line, kept);
    if (!fields) throw ModelError({path, number, 1}, expected + " on a line of its own");
    if (kept && fields->size() != m.names.size() + 2) throw ModelError({path, number, 3}, expected);
    const auto index = whole_number<std::size_t>(fields->front());
    if (index != m.run_count) {
      throw ModelError({path, number, 3}, fmt::format("run {} where run {} was expected",
                                                      fields->front(), m.run_count));
    }
    ++m.run_count;
    if (!kept) continue;
    auto run = run_of(*fields);
    if (!run) throw ModelError({path, number, 3}, expected + ", each a finite number");
    m.runs.push_back(std::move(*run));
  }
  return m;
}

}  // namespace unidyn
