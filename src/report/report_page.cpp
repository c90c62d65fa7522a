// The report's page: its data as JSON, and the HTML around it.
#include "unidyn/report/report_page.hpp"

#include "page_data.hpp"

#include <fmt/format.h>

#include <openssl/evp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "unidyn/io/equation_report.hpp"
#include "unidyn/io/integrability_text.hpp"
#include "unidyn/io/json_text.hpp"
#include "unidyn/io/textbook_equations.hpp"
#include "unidyn/report/page_rows.hpp"
#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {

std::string page_number(double x) {
  return std::isfinite(x) ? fmt::format("{:.9g}", x) : std::string("null");
}

std::string json_names(const std::vector<std::string>& names) {
  std::string out = "[";
  for (std::size_t k = 0; k < names.size(); ++k) out += (k ? ", " : "") + unidyn::quoted(names[k]);
  return out + "]";
}

namespace {

template <class Items, class Each>
std::string json_array(const Items& items, Each each) {
  std::string out = "[";
  bool first = true;
  for (const auto& item : items) {
    out += (first ? "" : ", ") + each(item);
    first = false;
  }
  return out + "]";
}

// The most LaTeX the page renders (KaTeX, when it opens).
constexpr std::size_t kMostEquationBytes = 100'000;

// Numbers as 32-bit floats, little-endian, in base64 (RFC 4648).
std::string float32_base64(const std::vector<double>& values) {
  std::vector<unsigned char> bytes;
  bytes.reserve(4 * values.size());
  for (const double v : values) {
    const auto bits = std::bit_cast<std::uint32_t>(static_cast<float>(v));
    for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<unsigned char>(bits >> (8 * k)));
  }
  std::string text(4 * ((bytes.size() + 2) / 3) + 1, '\0');
  const int length = EVP_EncodeBlock(reinterpret_cast<unsigned char*>(text.data()), bytes.data(),
                                     static_cast<int>(bytes.size()));
  text.resize(static_cast<std::size_t>(length));
  return text;
}

// The model: name, reference, parameters and their values, coordinates.
std::string model_json(const ReportModel& model) {
  const System& system = model.system;
  std::vector<std::string> parameters, coordinates;
  for (std::size_t k = 0; k < system.parameters.size(); ++k) {
    parameters.push_back("[" + unidyn::quoted(system.parameters[k].name) + ", " +
                         json_number(model.parameters[k]) + "]");
  }
  for (const auto& q : system.coordinates()) coordinates.push_back(q.name);
  return "{\"name\": " + unidyn::quoted(system.name) +
         ", \"reference\": " + unidyn::quoted(system.reference) + ", \"parameters\": [" +
         fmt::format("{}", fmt::join(parameters, ", ")) +
         "], \"coordinates\": " + json_names(coordinates) + "}";
}

// Lagrange's equations in the book's form, in LaTeX (as `derive --format latex` writes them), their
// caption and the integrability of the velocity constraints as notes, and the Newton–Euler check.
std::string equations_json(const ReportModel& model) {
  std::ostringstream latex;
  write_textbook_lagrange(latex, model.system, model.equations, EquationFormat::latex);
  std::string block;
  std::vector<std::string> notes;
  std::istringstream lines(latex.str());
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("% ")) {
      notes.push_back(line.substr(2));
    } else {
      block += line + "\n";
    }
  }
  for (std::string& line : integrability_lines(model.system)) notes.push_back(std::move(line));
  // equations too long to read on a page (the bicycle's: 0.9 MB of LaTeX) are named, not shown
  if (block.size() > kMostEquationBytes) {
    notes.insert(notes.begin(),
                 fmt::format("the equations are {:.0f} kB of LaTeX, more than a page can show: "
                             "`unidyn derive MODEL --format latex` writes them",
                             static_cast<double>(block.size()) / 1024.0));
    block.clear();
  }
  return "{\"latex\": [" + (block.empty() ? std::string() : unidyn::quoted(block)) +
         "], \"notes\": " + json_names(notes) + ", \"check\": " + unidyn::quoted(model.check) + "}";
}

// The plots: coordinates, rates, energy (and its change), multipliers, outputs, conserved
// quantities and each constraint force, each group of the columns there are.
std::string groups_json(const System& system, const std::vector<std::string>& columns,
                        const std::vector<std::string>& force_owners) {
  const auto has = [&](const std::string& name) {
    return std::find(columns.begin(), columns.end(), name) != columns.end();
  };
  std::vector<std::pair<std::string, std::vector<std::string>>> groups{
      {"coordinates", {}},         {"rates", {}},       {"energy", {}},
      {"energy - E(0)", {}},       {"multipliers", {}}, {"outputs", {}},
      {"conserved quantities", {}}};
  for (const auto& q : system.coordinates()) {
    groups[0].second.push_back(q.name);
    groups[1].second.push_back("der(" + q.name + ")");
  }
  if (has("energy")) {
    groups[2].second.push_back("energy");
    groups[3].second.push_back("energy - E(0)");
  }
  for (const auto& c : system.constraints) groups[4].second.push_back("lambda(" + c.name + ")");
  for (const auto& o : system.outputs) groups[5].second.push_back(o.name);
  for (const auto& o : system.conserved) groups[6].second.push_back(o.name);
  for (const auto& owner : force_owners) {
    groups.push_back(
        {"constraint force on " + owner, {owner + ".Fc.x", owner + ".Fc.y", owner + ".Fc.z"}});
  }
  std::string out = "[";
  bool first = true;
  for (const auto& [title, names] : groups) {
    if (names.empty()) continue;
    out += (first ? "" : ", ") + std::string("{\"title\": ") + unidyn::quoted(title) +
           ", \"columns\": " + json_names(names) + "}";
    first = false;
  }
  return out + "]";
}

// The run column by column (with E − E(0) after the energy), its summary and events.
std::string run_json(const System& system, const ReportRun& run) {
  std::vector<std::string> columns = run.columns;
  std::vector<std::vector<double>> values(columns.size());
  // the rows the page keeps: all, or a long run's envelope (report/page_rows.hpp)
  const std::vector<std::size_t> kept = page_rows(run);
  for (const std::size_t r : kept) {
    for (std::size_t c = 0; c < columns.size(); ++c) values[c].push_back(run.rows[r][c]);
  }
  const auto energy = std::find(columns.begin(), columns.end(), "energy");
  if (energy != columns.end() && !run.rows.empty()) {
    const auto& E = values[static_cast<std::size_t>(energy - columns.begin())];
    std::vector<double> change;
    for (const double e : E) change.push_back(e - E.front());
    columns.push_back("energy - E(0)");
    values.push_back(std::move(change));
  }
  // each column as little-endian 32-bit floats in base64: 7 digits, a third of the text
  std::string out = "{\"columns\": {";
  for (std::size_t c = 0; c < columns.size(); ++c) {
    out += (c ? ", " : "") + unidyn::quoted(columns[c]) + ": \"" + float32_base64(values[c]) + "\"";
  }
  out += "}, \"rows\": " + std::to_string(run.rows.size()) +
         ", \"rows_shown\": " + std::to_string(kept.size()) +
         ", \"summary\": " + unidyn::quoted(run.summary) + ", \"events\": " +
         json_array(run.events,
                    [](const std::pair<double, std::string>& e) {
                      return "{\"t\": " + page_number(e.first) +
                             ", \"what\": " + unidyn::quoted(e.second) + "}";
                    }) +
         ", \"groups\": " + groups_json(system, columns, run.force_owners) + "}";
  return out;
}

// s with every "</" of a closing tag inside a <script> written "<\/" (the same text to JSON and
// JavaScript strings).
std::string script_safe(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s[k] == '<' && k + 1 < s.size() && s[k + 1] == '/') {
      out += "<\\";
    } else {
      out += s[k];
    }
  }
  return out;
}

// JSON inside a <script>: every '<' written \u003c (JSON has '<' only inside strings, where
// JSON.parse gives it back), so that no "</script", "<script" or "<!--" of a name or an output
// ends the element or puts the HTML parser in its double-escaped state (a blank page).
std::string json_script_safe(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    if (c == '<') {
      out += "\\u003c";
    } else {
      out += c;
    }
  }
  return out;
}

// Text for HTML: &, < and > escaped.
std::string html_text(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '&') {
      out += "&amp;";
    } else if (c == '<') {
      out += "&lt;";
    } else if (c == '>') {
      out += "&gt;";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

std::string report_page(const ReportModel& model, const ReportRun& run, const WebAssets& assets) {
  const std::string data = "{\"model\": " + model_json(model) +
                           ",\n\"equations\": " + equations_json(model) +
                           ",\n\"run\": " + run_json(model.system, run) +
                           ",\n\"equilibria\": " + equilibria_json(model) +
                           ",\n\"operating_point\": " + operating_point_json(model) +
                           ",\n\"scene\": " + scene_json(model, run) + "}";
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"generator\" content=\"unidyn report\">\n<title>" +
         html_text(model.system.name) + " - unidyn report</title>\n<style>\n" +
         std::string(assets.style) + "\n</style>\n</head>\n<body>\n<div id=\"app\"></div>\n" +
         "<script type=\"application/json\" id=\"unidyn-data\">\n" + json_script_safe(data) +
         "\n</script>\n<script>\n" + script_safe(assets.script) + "\n</script>\n</body>\n</html>\n";
}

}  // namespace unidyn
