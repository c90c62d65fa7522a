// The YAML model reader.
//
// Sections, in the order they may refer to each other: parameters → coordinates → particles →
// forces → constraints → impulses → initial → simulate → outputs → conserved.
#include "unidyn/io/model_file.hpp"

#include <fstream>
#include <sstream>

#include "model_reader.hpp"
#include "unidyn/equations/potential_check.hpp"

namespace unidyn {
namespace model_reading {

// YAML puts tags, anchors, quotes or a block header before a scalar's value, and folds and
// unindents values over several lines, so the value's characters are not where the node's mark
// is. The file from the mark on is matched against the value (a run of whitespace matching a run
// of whitespace); when it matches, that slice of the file is what the parser reads: the same
// tokens, at their own lines and columns. When it does not (escape sequences), the value is read
// as if it started right after the quote.
ModelReader::ScalarText ModelReader::scalar_text(const YAML::Node& node,
                                                 const std::string& what) const {
  std::string value = scalar(node, what);
  const YAML::Mark mark = node.Mark();
  const std::string_view src = source_;
  if (mark.pos < 0 || static_cast<std::size_t>(mark.pos) > src.size()) return {value, at(node)};
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  const auto flow = [](char c) { return c == ',' || c == '[' || c == ']' || c == '{' || c == '}'; };
  const auto start = static_cast<std::size_t>(mark.pos);
  std::size_t i = start;
  while (i < src.size() && (src[i] == '!' || src[i] == '&')) {  // tags and anchors
    while (i < src.size() && !space(src[i]) && !flow(src[i])) ++i;
    while (i < src.size() && space(src[i])) ++i;
  }
  if (i < src.size() && (src[i] == '"' || src[i] == '\'')) {
    ++i;
  } else if (i < src.size() && (src[i] == '|' || src[i] == '>')) {
    while (i < src.size() && src[i] != '\n') ++i;  // the block header
  }
  if (!value.empty() && !space(value[0])) {
    while (i < src.size() && space(src[i])) ++i;
  }
  const std::size_t begin = i;
  bool same = true;
  for (std::size_t k = 0; same && k < value.size(); ++k) {
    if (space(value[k])) {
      same = i < src.size() && space(src[i]);
      while (k + 1 < value.size() && space(value[k + 1])) ++k;
      while (i < src.size() && space(src[i])) ++i;
    } else {
      same = i < src.size() && src[i] == value[k];
      ++i;
    }
  }
  // where `begin` is; columns count characters, as the parser's do
  int line = mark.line + 1, column = mark.column + 1;
  for (std::size_t k = start; k < begin; ++k) {
    if (src[k] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(src[k]) & 0xC0) != 0x80) {
      ++column;
    }
  }
  if (same && i - begin <= ExpressionLimits::max_length) value = src.substr(begin, i - begin);
  return {std::move(value), {file_, line, column}};
}

System ModelReader::read(const YAML::Node& root) {
  if (!root.IsDefined() || root.IsNull())
    throw ModelError({file_, 1, 1}, "the model file is empty");
  expect_map(root, "a model file");
  expect_keys(root,
              {"unidyn", "name", "description", "reference", "parameters", "coordinates",
               "particles", "bodies", "forces", "constraints", "initial", "simulate", "outputs",
               "conserved", "stop_when", "definitions", "impulses"},
              "the model");
  if (!root["unidyn"]) throw ModelError(at(root), "missing 'unidyn: 1' (the model format version)");
  if (scalar(root["unidyn"], "unidyn") != "1")
    fail(root["unidyn"], "unsupported format version: expected 'unidyn: 1'");

  System system;
  system.source = file_;
  system.name = root["name"] ? printable_name(root["name"], "the model's name", false)
                             : printable(file_);  // shown: no raw control characters
  if (root["description"]) {
    system.description = printable_name(root["description"], "the model's description", false);
  }
  if (root["reference"]) {
    system.reference = printable_name(root["reference"], "the model's reference", false);
  }
  if (root["parameters"]) read_parameters(root["parameters"], system);
  if (!root["coordinates"]) throw ModelError(at(root), "missing 'coordinates:' (a list of names)");
  read_coordinates(root["coordinates"], system);
  if (root["particles"]) read_particles(root["particles"], system);
  if (root["bodies"]) read_bodies(root["bodies"], system);
  if (system.particles.empty() && system.bodies.empty()) {
    throw ModelError(at(root), "the model has no particles and no bodies");
  }
  expect_every_coordinate_moves(system);
  if (root["definitions"]) read_definitions(root["definitions"], system);
  if (root["forces"]) read_forces(root["forces"], system);
  if (root["constraints"]) read_constraints(root["constraints"], system);
  if (root["impulses"]) read_impulses(root["impulses"], system);
  system.initial_values.assign(system.coordinates().size(), 0);
  system.initial_rates.assign(system.coordinates().size(), 0);
  system.initial_value_given.assign(system.coordinates().size(), false);
  system.initial_rate_given.assign(system.coordinates().size(), false);
  if (root["initial"]) read_initial(root["initial"], system);
  if (root["simulate"]) read_simulate(root["simulate"], system);
  columns_ = {"t", "energy"};
  for (const auto& q : system.coordinates()) columns_.insert({q.name, "der(" + q.name + ")"});
  for (const auto& c : system.constraints) columns_.insert("lambda(" + c.name + ")");
  if (root["outputs"]) system.outputs = read_outputs(root["outputs"], system, "outputs");
  if (root["conserved"]) system.conserved = read_outputs(root["conserved"], system, "conserved");
  // stop_when: at the top or under simulate:, not both
  const bool under_simulate = root["simulate"] && root["simulate"]["stop_when"];
  if (root["stop_when"] && under_simulate) {
    fail(root["simulate"]["stop_when"],
         "stop_when is given twice (at the top and under simulate:)");
  }
  if (root["stop_when"]) read_stop_when(root["stop_when"], system);
  if (under_simulate) read_stop_when(root["simulate"]["stop_when"], system);
  system.largest_expression = largest_at_;
  system.largest_expression_terms = largest_terms_;
  return system;
}

}  // namespace model_reading

namespace {

// A model past kMaxModelBytes, refused before it is parsed.
ModelError too_large(const std::string& file) {
  return ModelError({file, 0, 0}, "the model is larger than " + std::to_string(kMaxModelBytes) +
                                      " bytes (4 MiB; a model is a few kilobytes): not read");
}

}  // namespace

System parse_model(const std::string& text, const std::string& file) {
  using model_reading::ModelReader;
  if (text.size() > kMaxModelBytes) throw too_large(file);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ModelError({file, e.mark.line + 1, e.mark.column + 1}, "YAML syntax: " + e.msg);
  }
  try {
    // yaml-cpp's marks do not count a byte-order mark
    std::string_view source = text;
    if (source.starts_with("\xEF\xBB\xBF")) source.remove_prefix(3);
    System system = ModelReader(file, source).read(root);
    // what unidyn proves conservative counts as such everywhere (said by derive and simulate)
    adopt_proven_potentials(system);
    return system;
  } catch (const YAML::Exception& e) {
    throw ModelError({file, e.mark.line + 1, e.mark.column + 1}, e.msg);
  }
}

namespace {

// A deep copy of a YAML node with every collection in block style: one layout for one content.
YAML::Node in_block_style(const YAML::Node& node) {
  if (node.IsMap()) {
    YAML::Node copy(YAML::NodeType::Map);
    for (const auto& item : node) copy[in_block_style(item.first)] = in_block_style(item.second);
    copy.SetStyle(YAML::EmitterStyle::Block);
    return copy;
  }
  if (node.IsSequence()) {
    YAML::Node copy(YAML::NodeType::Sequence);
    for (const auto& element : node) copy.push_back(in_block_style(element));
    copy.SetStyle(YAML::EmitterStyle::Block);
    return copy;
  }
  return YAML::Clone(node);
}

}  // namespace

std::string model_code_text(const std::string& text, const std::string& file) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ModelError({file, e.mark.line + 1, e.mark.column + 1}, "YAML syntax: " + e.msg);
  }
  if (!root.IsMap()) return YAML::Dump(root);
  YAML::Node code(YAML::NodeType::Map);
  for (const auto& item : root) {
    const std::string key = item.first.IsScalar() ? item.first.Scalar() : "";
    if (key == "name" || key == "description" || key == "reference" || key == "initial") continue;
    if (key == "simulate") {
      if (item.second.IsMap() && item.second["stop_when"]) {
        code["simulate.stop_when"] = in_block_style(item.second["stop_when"]);
      }
      continue;
    }
    code[in_block_style(item.first)] = in_block_style(item.second);
  }
  return YAML::Dump(code);
}

std::string read_model_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ModelError({path, 0, 0}, "cannot open the model file");
  // read in blocks, never past the bound (/dev/zero, a log file named by mistake)
  std::string text;
  char block[65536];
  while (in.read(block, sizeof block) || in.gcount() > 0) {
    text.append(block, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxModelBytes) throw too_large(path);
  }
  if (in.bad()) throw ModelError({path, 0, 0}, "cannot read the model file");
  return text;
}

System load_model(const std::string& path) {
  return parse_model(read_model_text(path), path);
}

}  // namespace unidyn
