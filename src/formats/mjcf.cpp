// An MJCF file as a unidyn model: <compiler> and <option> read, the rest of <mujoco> refused,
// ignored or noted, and the YAML of <worldbody>'s bodies.
#include "unidyn/formats/mjcf.hpp"

#include <cstring>
#include <filesystem>

#include "mjcf_parts.hpp"
#include "unidyn/symbolic/printable_text.hpp"

namespace unidyn::formats {
namespace {

using tinyxml2::XMLElement;

// Nothing is read from other files: <include> refused wherever it is.
void refuse_includes(const XmlSource& source, const XMLElement& element) {
  if (std::strcmp(element.Name(), "include") == 0) {
    source.refuse(element, "<include> is not supported: unidyn reads one file");
  }
  for (const auto* child = element.FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    refuse_includes(source, *child);
  }
}

// An attribute that must keep MuJoCo's default (its value `expected`, or absent).
void expect_value(const XmlSource& source, const XMLElement& element, const char* attribute,
                  const char* expected, const std::string& why) {
  const char* value = element.Attribute(attribute);
  if (value && std::strcmp(value, expected) != 0) source.refuse(element, attribute, why);
}

// <compiler angle eulerseq coordinate inertiafromgeom ...>: the angle unit and where inertia
// comes from; anything that would change the model otherwise refused.
void read_compiler(const XmlSource& source, const XMLElement& compiler, MjcfContext& context) {
  if (const char* angle = compiler.Attribute("angle")) {
    if (std::strcmp(angle, "radian") != 0 && std::strcmp(angle, "degree") != 0) {
      source.refuse(compiler, "angle", "angle= is \"radian\" or \"degree\"");
    }
    context.degrees = std::strcmp(angle, "degree") == 0;
  }
  context.autolimits = compiler.BoolAttribute("autolimits", false);
  expect_value(source, compiler, "eulerseq", "xyz",
               "only eulerseq=\"xyz\" (MuJoCo's default) is supported yet");
  expect_value(source, compiler, "coordinate", "local",
               "only coordinate=\"local\" (MuJoCo's default) is supported");
  if (const char* from_geom = compiler.Attribute("inertiafromgeom")) {
    if (std::strcmp(from_geom, "true") == 0) {
      source.refuse(compiler, "inertiafromgeom",
                    "inertia from geoms is not supported yet: give bodies an <inertial>");
    }
    context.inertia_from_geom = std::strcmp(from_geom, "false") != 0;
  }
  for (const char* changes : {"settotalmass", "boundmass", "boundinertia", "balanceinertia"}) {
    if (compiler.Attribute(changes)) {
      source.refuse(compiler, changes,
                    std::string(changes) + "= is not supported: it changes the bodies' inertia");
    }
  }
}

// <option gravity> and its <flag contact gravity>: the gravity force's lines, and whether
// contacts are on.
struct Options {
  std::vector<Number> gravity = {{"0", 0}, {"0", 0}, {"-9.81", -9.81}};
  bool contacts = true;
};
void read_option(const XmlSource& source, const XMLElement& option, Options& options,
                 Ignored& ignored) {
  if (auto gravity = source.numbers(option, "gravity", 3)) options.gravity = *gravity;
  ignore_others(source, option, {"flag"}, ignored);
  for (const auto* flag = option.FirstChildElement("flag"); flag;
       flag = flag->NextSiblingElement("flag")) {
    if (const char* contact = flag->Attribute("contact")) {
      options.contacts = std::strcmp(contact, "disable") != 0;
    }
    if (const char* gravity = flag->Attribute("gravity");
        gravity && std::strcmp(gravity, "disable") == 0) {
      options.gravity = {{"0", 0}, {"0", 0}, {"0", 0}};
    }
    expect_value(source, *flag, "passive", "enable",
                 "passive=\"disable\" is not supported: the joints' damping is applied");
  }
}

// Whether any geom can touch another (MuJoCo's default contype = conaffinity = 1).
bool has_contact_geoms(const XMLElement& element) {
  for (const auto* child = element.FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    if (std::strcmp(child->Name(), "geom") == 0) {
      const int type = child->IntAttribute("contype", 1);
      const int affinity = child->IntAttribute("conaffinity", 1);
      if (type != 0 || affinity != 0) return true;
    }
    if (has_contact_geoms(*child)) return true;
  }
  return false;
}

// parameters: and the gravity force of <option gravity>: -g*E3 when it is along E3.
ModelHeader header(const std::string& name, const std::string& file, const Options& options) {
  const auto& g = options.gravity;
  if (g[0].value == 0 && g[1].value == 0 && g[2].value == 0) {
    return {name, file, "MJCF", "{}", ""};
  }
  if (g[0].value == 0 && g[1].value == 0) {
    const std::string minus = g[2].text[0] == '-' ? g[2].text.substr(1) : "-" + g[2].text;
    return {name, file, "MJCF", "{g: " + minus + "}", "  - gravity: -g*E3"};
  }
  return {name, file, "MJCF", "{}",
          "  - gravity: (" + g[0].text + ")*E1 + (" + g[1].text + ")*E2 + (" + g[2].text + ")*E3"};
}

// The elements of <mujoco>: read, refused, or noted as ignored.
void read_top_level(const XmlSource& source, MjcfContext& context, Options& options) {
  const XMLElement& mujoco = source.root();
  for (const auto* e = mujoco.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (name == "compiler") read_compiler(source, *e, context);
    if (name == "option") read_option(source, *e, options, context.ignored);
    if (name == "actuator" || name == "sensor") {
      context.ignored.add(source, *e, "ignored: it does not change the passive dynamics");
    } else if (name == "contact") {
      context.ignored.add(source, *e, "ignored: contacts between geoms are not modelled");
    } else if (name == "tendon") {
      context.ignored.add(source, *e, "ignored: tendons are not modelled");
    } else if (name != "compiler" && name != "option" && name != "worldbody" && name != "default" &&
               name != "equality") {
      context.ignored.add(source, *e, "ignored");
    }
  }
}

}  // namespace

bool is_mjcf_text(const std::string& text) {
  tinyxml2::XMLDocument document;
  if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) return false;
  return document.RootElement() && std::strcmp(document.RootElement()->Name(), "mujoco") == 0;
}

ImportedModel import_mjcf(const std::string& text, const std::string& file,
                          const ImportOptions& options) {
  if (text.size() > kMaxMjcfBytes) {
    throw ModelError({file, 0, 0}, "an MJCF file larger than 16 MiB is refused");
  }
  XmlSource source(text, file);
  const XMLElement& mujoco = source.root();
  if (std::string(mujoco.Name()) != "mujoco") {
    source.refuse(mujoco, std::string("expected <mujoco>, found <") + mujoco.Name() + ">");
  }
  const char* model_name = mujoco.Attribute("model");
  const std::string name = model_name ? model_name : "MuJoCo Model";
  if (const std::string why = unprintable_name_reason(name, false); !why.empty()) {
    source.refuse(mujoco, "model", "the model's name " + why);
  }
  refuse_includes(source, mujoco);
  apply_default_classes(source);
  ImportedModel model;
  Ignored ignored;
  Names names;
  Written written;
  MjcfContext context{source, model.notes, ignored, names, written};
  context.limits = options.limits;
  Options top;
  read_top_level(source, context, top);
  if (top.contacts && has_contact_geoms(mujoco)) {
    model.notes.push_back(source.position(mujoco).str() +
                          ": contacts between geoms are not modelled (the file's geoms collide "
                          "in MuJoCo: contype and conaffinity are on)");
  }
  for (const auto* world = mujoco.FirstChildElement("worldbody"); world;
       world = world->NextSiblingElement("worldbody")) {
    ignore_others(source, *world, {"body"}, ignored);
    write_child_bodies(context, *world, "");
  }
  // the loops and couplings, once every body and joint is known
  for (const auto* equality = mujoco.FirstChildElement("equality"); equality;
       equality = equality->NextSiblingElement("equality")) {
    write_equalities(context, *equality);
  }
  model.yaml = model_yaml(header(name, file, top), written);
  for (auto& note : ignored.notes()) model.notes.push_back(std::move(note));
  return model;
}

ImportedModel import_mjcf_file(const std::string& path, const ImportOptions& options) {
  return import_mjcf(read_bounded_file(path, kMaxMjcfBytes, "MJCF file"), path, options);
}

bool is_mjcf_file(const std::string& path) {
  if (std::filesystem::path(path).extension() != ".xml") return false;
  return is_mjcf_text(read_bounded_file(path, kMaxMjcfBytes, "MJCF file"));
}

}  // namespace unidyn::formats
