// A body's <inertial> as its mass, inertia tensor and centre of mass.
#include <Eigen/Dense>

#include "mjcf_parts.hpp"

namespace unidyn::formats {
namespace {

using tinyxml2::XMLElement;

// The tensor on the inertial frame: diaginertia="A B C", or fullinertia="Ixx Iyy Izz Ixy Ixz
// Iyz" (MuJoCo's order), as typed.
std::vector<std::vector<Number>> typed_mjcf_tensor(const XmlSource& source,
                                                   const XMLElement& inertial) {
  const bool diagonal = inertial.Attribute("diaginertia") != nullptr;
  if (diagonal == (inertial.Attribute("fullinertia") != nullptr)) {
    source.refuse(inertial, "<inertial> needs diaginertia=\"...\" or fullinertia=\"...\" (one)");
  }
  const Number zero{"0", 0};
  if (diagonal) {
    const auto d = source.required_numbers(inertial, "diaginertia", 3);
    return {{d[0], zero, zero}, {zero, d[1], zero}, {zero, zero, d[2]}};
  }
  const auto f = source.required_numbers(inertial, "fullinertia", 6);
  return {{f[0], f[3], f[4]}, {f[3], f[1], f[5]}, {f[4], f[5], f[2]}};
}

// `inertia:` on the body frame: [A, B, C] of a diaginertia on an unturned inertial frame, else
// the tensor (turned by the inertial frame's orientation, R J Rᵀ, with a note and a comment).
void write_inertia(const MjcfContext& context, const XMLElement& inertial,
                   std::vector<std::string>& lines) {
  const auto components = typed_mjcf_tensor(context.source, inertial);
  Eigen::Matrix3d J;
  std::vector<std::vector<std::string>> rows(3, std::vector<std::string>(3));
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      J(i, k) = components[size_t(i)][size_t(k)].value;
      rows[size_t(i)][size_t(k)] = components[size_t(i)][size_t(k)].text;
    }
  }
  const char* at = inertial.Attribute("diaginertia") ? "diaginertia" : "fullinertia";
  expect_realisable(context.source, inertial, J);
  const Orientation turned = orientation(context, inertial);
  if (turned.text.empty()) {
    const bool diagonal = inertial.Attribute("diaginertia") != nullptr;
    lines.push_back("    inertia: " +
                    (diagonal ? "[" + rows[0][0] + ", " + rows[1][1] + ", " + rows[2][2] + "]"
                              : tensor_text(rows)));
    return;
  }
  const Eigen::Matrix3d R = turned.value.toRotationMatrix();
  const Eigen::Matrix3d RJRt = R * J * R.transpose();
  const Eigen::Matrix3d symmetric = 0.5 * (RJRt + RJRt.transpose());
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) rows[size_t(i)][size_t(k)] = exact_text(symmetric(i, k));
  }
  const std::string why = std::string("the ") + at +
                          " on the turned <inertial> frame turned onto the body frame: R J R^T";
  context.notes.push_back(context.source.position(inertial, at).str() + ": " + why);
  lines.push_back("    # " + why);
  lines.push_back("    inertia: " + tensor_text(rows));
}

// A primitive geom's uniform shape in the model's words and its volume (MuJoCo's sizes are radii
// and half-lengths): {"{sphere: {radius: r}}", "4/3*pi*r^3"}, ...; a capsule's shape is
// written by capsule_inertia.
std::pair<std::string, std::string> shape_and_volume(const XmlSource& source,
                                                     const XMLElement& geom,
                                                     const std::string& type) {
  const std::size_t count = type == "sphere" ? 1 : type == "cylinder" || type == "capsule" ? 2 : 3;
  const auto size = source.required_numbers(geom, "size", count);
  for (const Number& x : size) {
    if (x.value <= 0) source.refuse(geom, "size", "a geom's size must be positive");
  }
  const std::string& a = size[0].text;
  if (type == "sphere") return {"{sphere: {radius: " + a + "}}", "4/3*pi*" + a + "^3"};
  const std::string& b = size[1].text;
  if (type == "capsule") return {"", "(pi*" + a + "^2*2*" + b + " + 4/3*pi*" + a + "^3)"};
  if (type == "cylinder") {
    return {"{cylinder: {radius: " + a + ", height: 2*" + b + "}}", "pi*" + a + "^2*2*" + b};
  }
  const std::string& c = size[2].text;
  if (type == "box") {
    return {"{box: {a: 2*" + a + ", b: 2*" + b + ", c: 2*" + c + "}}",
            "8*" + a + "*" + b + "*" + c};
  }
  return {"{ellipsoid: {a: " + a + ", b: " + b + ", c: " + c + "}}",
          "4/3*pi*" + a + "*" + b + "*" + c};
}

// A capsule's principal moments as MuJoCo computes them: its mass m shared by the cylinder (of
// height H = 2h) and the sphere of its two caps by volume, m_s = m 4r/(4r + 3H); the cylinder's
// moments, the sphere's 2/5 m_s r², and the caps moved out to the cylinder's ends,
// m_s H (3r + 2H)/8 across the axis.
std::string capsule_inertia(const XmlSource& source, const XMLElement& geom,
                            const std::string& mass) {
  const auto size = source.required_numbers(geom, "size", 2);
  const std::string r = size[0].text, H = "(2*" + size[1].text + ")", m = "(" + mass + ")";
  const std::string ms = m + "*4*" + r + "/(4*" + r + " + 3*" + H + ")";
  const std::string mc = "(" + m + " - " + ms + ")";
  const std::string caps = "2*" + ms + "*" + r + "^2/5";
  const std::string across = mc + "*(3*" + r + "^2 + " + H + "^2)/12 + " + caps + " + " + ms + "*" +
                             H + "*(3*" + r + " + 2*" + H + ")/8";
  return "[" + across + ", " + across + ", " + mc + "*" + r + "^2/2 + " + caps + "]";
}

// The inertia MuJoCo derives from a body's one geom (inertiafromgeom auto): a uniform solid of
// its density (default 1000) or of its mass, centred at its pos, unturned.
std::vector<std::string> geom_lines(const MjcfContext& context, const XMLElement& geom,
                                    const std::string& name) {
  const XmlSource& source = context.source;
  if (const auto* second = geom.NextSiblingElement("geom")) {
    source.refuse(*second,
                  "a body's inertia from several geoms is not supported yet: give the body an "
                  "<inertial>");
  }
  for (const char* placed : {"fromto", "quat", "euler", "axisangle", "xyaxes", "zaxis"}) {
    if (geom.Attribute(placed)) {
      source.refuse(geom, placed,
                    std::string("a body's inertia from a geom placed by ") + placed +
                        " is not supported yet: give the body an <inertial>");
    }
  }
  const char* given = geom.Attribute("type");
  const std::string type = given ? given : "sphere";
  if (type != "sphere" && type != "box" && type != "cylinder" && type != "ellipsoid" &&
      type != "capsule") {
    source.refuse(
        geom, "type",
        "a body's inertia from a " + type +
            " geom is not supported yet (sphere, box, cylinder, capsule, ellipsoid): give "
            "the "
            "body an <inertial>");
  }
  const auto [shape, volume] = shape_and_volume(source, geom, type);
  std::string mass = source.numbers_or(geom, "density", {"1000"})[0].text + "*" + volume;
  if (const auto m = source.numbers(geom, "mass", 1)) {
    if ((*m)[0].value < 0) source.refuse(geom, "mass", "a mass must be positive or 0");
    if ((*m)[0].value == 0) return {"    mass: 0  # a frame: its geom has mass 0"};
    mass = (*m)[0].text;
  }
  std::vector<std::string> lines = {
      "    # the inertia of its <geom> (MuJoCo's inertiafromgeom)", "    mass: " + mass,
      "    inertia: " + (type == "capsule" ? capsule_inertia(source, geom, mass) : shape)};
  const auto center = source.numbers_or(geom, "pos", {"0", "0", "0"});
  if (center[0].value != 0 || center[1].value != 0 || center[2].value != 0) {
    lines.push_back("    center: " + name + ".frame_point(" + vector_text(center) + ")");
  }
  return lines;
}

}  // namespace

std::vector<std::string> inertial_lines(const MjcfContext& context, const XMLElement& body,
                                        const std::string& name) {
  const XmlSource& source = context.source;
  const XMLElement* geom = body.FirstChildElement("geom");
  for (const auto* g = geom; g; g = g->NextSiblingElement("geom")) {
    context.ignored.add(source, *g,
                        "not drawn and not made into contacts (read only for the inertia of a body "
                        "without <inertial>)");
  }
  const XMLElement* inertial = body.FirstChildElement("inertial");
  if (!inertial && geom && context.inertia_from_geom) return geom_lines(context, *geom, name);
  if (!inertial) return {"    mass: 0  # a frame: the body has no <inertial>"};
  ignore_others(source, *inertial, {}, context.ignored);
  if (!inertial->Attribute("mass")) source.refuse(*inertial, "<inertial> needs mass=\"...\"");
  const Number mass = (source.required_numbers(*inertial, "mass", 1))[0];
  if (mass.value < 0) source.refuse(*inertial, "mass", "a mass must be positive or 0 (a frame)");
  if (mass.value == 0) return {"    mass: 0  # a frame: its <inertial> has mass 0"};
  std::vector<std::string> lines = {"    mass: " + mass.text};
  write_inertia(context, *inertial, lines);
  const auto center = source.numbers_or(*inertial, "pos", {"0", "0", "0"});
  if (center[0].value != 0 || center[1].value != 0 || center[2].value != 0) {
    lines.push_back("    center: " + name + ".frame_point(" + vector_text(center) + ")");
  }
  return lines;
}

}  // namespace unidyn::formats
