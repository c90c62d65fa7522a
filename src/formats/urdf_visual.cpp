// A link's <visual>: a box, cylinder or sphere at the centre of mass, and its colour.
#include "urdf_visual.hpp"

#include <cmath>
#include <cstdio>

#include "unidyn/symbolic/printable_text.hpp"

namespace unidyn::formats {
namespace {

using tinyxml2::XMLElement;

bool positive(const std::vector<Number>& numbers) {
  for (const Number& x : numbers) {
    if (x.value <= 0) return false;
  }
  return true;
}

// The shape of <geometry> in the model's words ({box: {a, b, c}}, ...), or "" with the reason.
std::string shape_text(const XmlSource& source, const XMLElement& geometry, std::string& reason) {
  if (const auto* box = geometry.FirstChildElement("box")) {
    const auto size = source.required_numbers(*box, "size", 3);
    if (positive(size)) {
      return "{box: {a: " + size[0].text + ", b: " + size[1].text + ", c: " + size[2].text + "}";
    }
  } else if (const auto* cylinder = geometry.FirstChildElement("cylinder")) {
    // URDF's cylinder is along z, the model's along e3: the same axis
    const Number r = (source.required_numbers(*cylinder, "radius", 1))[0];
    const Number h = (source.required_numbers(*cylinder, "length", 1))[0];
    if (positive({r, h})) return "{cylinder: {radius: " + r.text + ", height: " + h.text + "}";
  } else if (const auto* sphere = geometry.FirstChildElement("sphere")) {
    const Number r = (source.required_numbers(*sphere, "radius", 1))[0];
    if (positive({r})) return "{sphere: {radius: " + r.text + "}";
  } else if (const auto* mesh = geometry.FirstChildElement("mesh")) {
    const char* file = mesh->Attribute("filename");
    reason = "a mesh (" + printable(file ? file : "") + ")";
    return "";
  } else {
    reason = "no box, cylinder, sphere or mesh";
    return "";
  }
  reason = "a dimension that is not positive";
  return "";
}

// "#rrggbb" of <color rgba="r g b a"> (components 0 to 1; alpha dropped).
std::string color_text(const XmlSource& source, const XMLElement& color) {
  const auto rgba = source.numbers(color, "rgba", 4);
  if (!rgba) return "";
  char text[8];
  int channel[3];
  for (int i = 0; i < 3; ++i) {
    const double c = (*rgba)[static_cast<std::size_t>(i)].value;
    if (c < 0 || c > 1) source.refuse(color, "rgba", "a colour's components are from 0 to 1");
    channel[i] = static_cast<int>(std::lround(255 * c));
  }
  std::snprintf(text, sizeof text, "#%02x%02x%02x", channel[0], channel[1], channel[2]);
  return text;
}

// The colour of a <visual>'s <material>: its own <color>, or that of <robot>'s material of its
// name.
std::string visual_color(const LinkContext& context, const XMLElement& visual) {
  const XMLElement* material = visual.FirstChildElement("material");
  if (!material) return "";
  if (const auto* color = material->FirstChildElement("color")) {
    return color_text(context.source, *color);
  }
  const char* name = material->Attribute("name");
  const auto named = name ? context.materials.find(name) : context.materials.end();
  if (named == context.materials.end()) return "";
  const auto* color = named->second->FirstChildElement("color");
  return color ? color_text(context.source, *color) : "";
}

// Whether a <visual>'s <origin> is the centre of mass without rotation.
bool at_center(const XmlSource& source, const XMLElement& visual,
               const std::vector<Number>& center) {
  const XMLElement* origin = visual.FirstChildElement("origin");
  if (!origin) return center[0].value == 0 && center[1].value == 0 && center[2].value == 0;
  const auto xyz = source.numbers_or(*origin, "xyz", {"0", "0", "0"});
  const auto rpy = source.numbers_or(*origin, "rpy", {"0", "0", "0"});
  for (std::size_t i = 0; i < 3; ++i) {
    if (xyz[i].value != center[i].value || rpy[i].value != 0) return false;
  }
  return true;
}

void note(const LinkContext& context, const XMLElement& visual, const std::string& text) {
  context.notes.push_back(context.source.position(visual).str() + ": " + text);
}

}  // namespace

std::vector<std::string> visual_lines(const LinkContext& context, const XMLElement& link,
                                      const std::vector<Number>& center) {
  std::vector<std::string> lines;
  const XmlSource& source = context.source;
  for (const auto* visual = link.FirstChildElement("visual"); visual;
       visual = visual->NextSiblingElement("visual")) {
    ignore_others(source, *visual, {"origin", "geometry", "material"}, context.ignored);
    std::string reason = "another <visual> of the link is drawn";
    const XMLElement* geometry = visual->FirstChildElement("geometry");
    std::string shape = geometry ? shape_text(source, *geometry, reason) : "";
    if (!geometry) reason = "no <geometry>";
    if (!shape.empty() && !at_center(source, *visual, center)) {
      reason = "not centred on the centre of mass without rotation";
      shape.clear();
    }
    if (!shape.empty() && lines.empty()) {
      const std::string color = visual_color(context, *visual);
      lines.push_back("    visual: " + shape + (color.empty() ? "" : ", color: \"" + color + "\"") +
                      "}");
      continue;
    }
    if (!shape.empty()) reason = "another <visual> of the link is drawn";
    note(context, *visual,
         "<visual> not drawn: " + reason +
             (lines.empty() ? "; the link is drawn as its ellipsoid of inertia" : ""));
  }
  return lines;
}

void frame_visuals(const LinkContext& context, const XMLElement& link) {
  for (const auto* visual = link.FirstChildElement("visual"); visual;
       visual = visual->NextSiblingElement("visual")) {
    note(context, *visual, "<visual> not drawn: the link has no mass (a frame)");
  }
}

}  // namespace unidyn::formats
