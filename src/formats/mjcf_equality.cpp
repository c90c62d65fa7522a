// MJCF <equality> as the model's position constraints: loops closed by <connect>, joints coupled
// by <joint>. MuJoCo holds them softly (solref, solimp); unidyn holds them exactly, a multiplier
// for each row (book §3.8):
//
//   <connect body1 body2 anchor>: body1's point at `anchor` on its frame stays on the point of
//     body2 that it coincides with at the reference configuration qpos0 (MuJoCo computes that
//     point the same way), three rows dot(p1 − p2, Ei) = 0, i = 1, 2, 3, named <name>_1.._3;
//     body2 left out (or "world") is the ground;
//   <joint joint1 joint2 polycoef="a0 a1 a2 a3 a4">: q1 = a0 + a1 q2 + a2 q2² + a3 q2³ + a4 q2⁴
//     (each angle measured from its qpos0, 0, as `ref` is 0), q1 = a0 without joint2.
//
// <weld> and <tendon> are refused; an inactive constraint (active="false") is left out, noted.
#include <cstring>

#include "mjcf_parts.hpp"
#include "unidyn/symbolic/printable_text.hpp"

namespace unidyn::formats {
namespace {

using tinyxml2::XMLElement;

// The constraint's name in the file, or equalityN after its MuJoCo id (with a note).
std::string equality_name(MjcfContext& context, const XMLElement& element) {
  const int id = context.equalities++;
  const char* given = element.Attribute("name");
  if (given) return given;
  const std::string name = "equality" + std::to_string(id);
  context.notes.push_back(context.source.position(element).str() + ": an unnamed <" +
                          element.Name() + "> is named " + name + " (its MuJoCo id)");
  return name;
}

// The model name of the body named by the attribute ("" for the ground: left out, or "world").
std::string named_body(const MjcfContext& context, const XMLElement& element,
                       const char* attribute) {
  const char* name = element.Attribute(attribute);
  if (!name || std::strcmp(name, "world") == 0) return "";
  const auto found = context.named_bodies.find(name);
  if (found == context.named_bodies.end()) {
    context.source.refuse(element, attribute,
                          "no body named '" + printable(name) + "' in <worldbody>");
  }
  return found->second;
}

// The point X on a body's frame as the model's text (its numbers on the ground for the ground).
std::string point_text(const std::string& body, const std::vector<std::string>& X) {
  const std::string vector = "[" + joined(X) + "]";
  return body.empty() ? vector : body + ".frame_point(" + vector + ")";
}

// A body's frame at qpos0 (the ground's for "").
Eigen::Isometry3d frame_at_qpos0(const MjcfContext& context, const std::string& body) {
  return body.empty() ? Eigen::Isometry3d::Identity() : context.frames.at(body);
}

// <connect>: body1's anchor held on body2's point that coincides with it at qpos0.
void write_connect(MjcfContext& context, const XMLElement& connect, const std::string& name) {
  const XmlSource& source = context.source;
  source.required(connect, "body1");
  const std::string body1 = named_body(context, connect, "body1");
  const std::string body2 = named_body(context, connect, "body2");
  if (body1 == body2) {
    source.refuse(connect, "a <connect> joins two different bodies (one may be the world)");
  }
  source.required(connect, "anchor");
  const auto anchor = *source.numbers(connect, "anchor", 3);
  std::vector<std::string> typed;
  Eigen::Vector3d on_body1;
  for (std::size_t i = 0; i < 3; ++i) {
    typed.push_back(anchor[i].text);
    on_body1[static_cast<Eigen::Index>(i)] = anchor[i].value;
  }
  // body2's point: where body1's anchor is at qpos0, on body2's frame
  const Eigen::Vector3d on_body2 =
      frame_at_qpos0(context, body2).inverse() * (frame_at_qpos0(context, body1) * on_body1);
  std::vector<std::string> computed;
  for (Eigen::Index i = 0; i < 3; ++i) computed.push_back(exact_text(on_body2[i]));
  const std::string p1 = point_text(body1, typed), p2 = point_text(body2, computed);
  context.notes.push_back(source.position(connect).str() + ": <connect> '" + name + "' holds " +
                          p1 + " on " + p2 + ", the point where it is at qpos0 (computed)");
  for (int i = 1; i <= 3; ++i) {
    const std::string row = context.names.claim(name + "_" + std::to_string(i), "constraint",
                                                source.position(connect), context.notes);
    context.written.constraints.push_back("  - name: " + row);
    context.written.constraints.push_back("    position: dot(" + p1 + " - " + p2 + ", E" +
                                          std::to_string(i) + ")");
  }
}

// A named hinge or slide joint's coordinate.
std::string scalar_joint(const MjcfContext& context, const XMLElement& element,
                         const char* attribute) {
  const std::string name = context.source.required(element, attribute);
  const auto found = context.named_joints.find(name);
  if (found == context.named_joints.end()) {
    context.source.refuse(element, attribute, "no joint named '" + printable(name) + "'");
  }
  if (found->second.type != "hinge" && found->second.type != "slide") {
    context.source.refuse(element, attribute,
                          "a <joint> equality couples hinge and slide joints (this one is " +
                              found->second.type + ")");
  }
  return found->second.coordinates[0];
}

// <joint>: q1 − (a0 + a1 q2 + ... + a4 q2⁴), the terms with a zero coefficient left out.
void write_joint_coupling(MjcfContext& context, const XMLElement& coupling,
                          const std::string& name) {
  const std::string q1 = scalar_joint(context, coupling, "joint1");
  const bool coupled = coupling.Attribute("joint2") != nullptr;
  const std::string q2 = coupled ? scalar_joint(context, coupling, "joint2") : "";
  const auto a = context.source.numbers_or(coupling, "polycoef", {"0", "1", "0", "0", "0"});
  std::vector<std::string> terms;
  for (std::size_t k = 0; k < (coupled ? a.size() : 1); ++k) {
    if (a[k].value == 0) continue;
    const std::string coefficient = a[k].value < 0 ? "(" + a[k].text + ")" : a[k].text;
    const std::string power = k == 0 ? "" : k == 1 ? "*" + q2 : "*" + q2 + "^" + std::to_string(k);
    terms.push_back(coefficient + power);
  }
  std::string polynomial;
  for (const auto& term : terms) polynomial += (polynomial.empty() ? "" : " + ") + term;
  const std::string row =
      context.names.claim(name, "constraint", context.source.position(coupling), context.notes);
  context.written.constraints.push_back("  - name: " + row);
  context.written.constraints.push_back("    position: " + q1 +
                                        (terms.empty() ? "" : " - (" + polynomial + ")"));
}

}  // namespace

void write_equalities(MjcfContext& context, const XMLElement& equality) {
  const XmlSource& source = context.source;
  for (const auto* e = equality.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string kind = e->Name();
    if (kind != "connect" && kind != "joint") {
      source.refuse(*e, "<" + printable(kind) +
                            "> equality constraints are not supported yet (<connect> and "
                            "<joint> are)");
    }
    if (!e->BoolAttribute("active", true)) {
      ++context.equalities;
      context.ignored.add(source, *e, "with active=\"false\": left out, as MuJoCo leaves it off");
      continue;
    }
    const std::string name = equality_name(context, *e);
    if (e->Attribute("solref") || e->Attribute("solimp")) {
      context.notes.push_back(source.position(*e).str() +
                              ": solref and solimp not applied: unidyn holds the constraint "
                              "exactly");
    }
    if (kind == "connect") write_connect(context, *e, name);
    if (kind == "joint") write_joint_coupling(context, *e, name);
  }
}

}  // namespace unidyn::formats
