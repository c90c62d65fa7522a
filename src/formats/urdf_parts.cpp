// What an import ignores, numbers as the model's text, and the model's YAML.
#include "urdf_parts.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "unidyn/symbolic/printable_text.hpp"
#include "urdf_tree.hpp"

namespace unidyn::formats {

void Ignored::add(const XmlSource& source, const tinyxml2::XMLElement& element,
                  const std::string& why) {
  const std::string name = element.Name();
  auto [kind, first] = kinds_.try_emplace(name, Kind{source.position(element), why, 0});
  if (first) order_.push_back(name);
  ++kind->second.count;
}

// "file:line:column: <collision> ignored (3 in the file, the first here)"
std::vector<std::string> Ignored::notes() const {
  std::vector<std::string> notes;
  for (const auto& name : order_) {
    const Kind& kind = kinds_.at(name);
    notes.push_back(kind.first.str() + ": <" + name + "> " + kind.why +
                    (kind.count > 1
                         ? " (" + std::to_string(kind.count) + " in the file, the first here)"
                         : ""));
  }
  return notes;
}

void ignore_others(const XmlSource& source, const tinyxml2::XMLElement& element,
                   std::initializer_list<const char*> known, Ignored& ignored) {
  for (const auto* child = element.FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    bool is_known = false;
    for (const char* name : known) is_known = is_known || std::strcmp(child->Name(), name) == 0;
    if (!is_known) ignored.add(source, *child, "ignored");
  }
}

std::string vector_text(const std::vector<Number>& numbers) {
  std::string text = "[";
  for (const Number& x : numbers) text += (text.size() > 1 ? ", " : "") + x.text;
  return text + "]";
}

std::string exact_text(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string tensor_text(const std::vector<std::vector<std::string>>& rows) {
  std::string text = "{tensor: [";
  for (std::size_t i = 0; i < 3; ++i) {
    text += (i ? "], [" : "[") + rows[i][0] + ", " + rows[i][1] + ", " + rows[i][2];
  }
  return text + "]]}";
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : printable(text)) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

void expect_realisable(const XmlSource& source, const tinyxml2::XMLElement& element,
                       const Eigen::Matrix3d& J) {
  const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(J).eigenvalues();
  const double tolerance = 1e-12 * std::max(1.0, moments.cwiseAbs().maxCoeff());
  const std::string text = "the principal moments are " + exact_text(moments[0]) + ", " +
                           exact_text(moments[1]) + ", " + exact_text(moments[2]);
  if (moments.minCoeff() < -tolerance) {
    source.refuse(element, "an inertia tensor must be positive semi-definite: " + text);
  }
  for (int i = 0; i < 3; ++i) {
    if (moments[i] > moments[(i + 1) % 3] + moments[(i + 2) % 3] + tolerance) {
      source.refuse(element,
                    "no body has this inertia: a principal moment exceeds the sum of the other "
                    "two (" +
                        text + ")");
    }
  }
}

std::string damper_line(bool slides, const std::string& coordinate,
                        const std::string& coefficient) {
  return std::string(slides ? "  - slide_damper: {displacement: "
                            : "  - torsion_damper: {angle: ") +
         coordinate + ", coefficient: " + coefficient + "}";
}

void write_limits(const std::string& coordinate, const std::string& lower, const std::string& upper,
                  const SourcePosition& where, Names& names, std::vector<std::string>& notes,
                  Written& written) {
  const std::string on_lower = names.claim(coordinate + "_lower", "constraint", where, notes);
  const std::string on_upper = names.claim(coordinate + "_upper", "constraint", where, notes);
  for (const auto& line :
       {"  - name: " + on_lower, "    position: " + coordinate + " - (" + lower + ")",
        std::string("    unilateral: true"), "  - name: " + on_upper,
        "    position: (" + upper + ") - " + coordinate, std::string("    unilateral: true")}) {
    written.constraints.push_back(line);
  }
}

std::string model_yaml(const ModelHeader& header, const Written& w) {
  const std::string article = header.format == "MJCF" ? "an " : "a ";
  std::string yaml = "# Written by `unidyn import` from " + article + header.format +
                     " file; docs/formats.md says what maps to what.\n";
  yaml += "unidyn: 1\nname: " + quoted(header.name) + "\n";
  yaml += "description: " +
          quoted("Imported by unidyn from " + header.file + " (" + header.format + ")") + "\n";
  yaml += "parameters: " + header.parameters + "\n";
  yaml += "coordinates: [" + joined(w.coordinates) + "]\n\nbodies:\n";
  for (const auto& line : w.bodies) yaml += line + "\n";
  if (!header.gravity.empty() || !w.dampers.empty()) yaml += "\nforces:\n";
  if (!header.gravity.empty()) yaml += header.gravity + "\n";
  for (const auto& line : w.dampers) yaml += line + "\n";
  if (!w.constraints.empty()) yaml += "\nconstraints:\n";
  for (const auto& line : w.constraints) yaml += line + "\n";
  yaml += "\ninitial: {" + joined(w.initial) + "}\n";
  yaml += "simulate: {t_end: 5, output_step: 0.01}\n";
  return yaml;
}

std::string read_bounded_file(const std::string& path, std::size_t max_bytes,
                              const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ModelError({path, 0, 0}, "cannot open the " + what);
  std::string text;
  std::vector<char> block(1 << 16);
  for (std::streamsize got; (got = in.rdbuf()->sgetn(block.data(), 1 << 16)) > 0;) {
    text.append(block.data(), static_cast<std::size_t>(got));
    if (text.size() > max_bytes) break;
  }
  return text;
}

}  // namespace unidyn::formats
