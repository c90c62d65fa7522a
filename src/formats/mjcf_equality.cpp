// MJCF <equality> as the model's position constraints: loops closed by <connect>, joints coupled
// by <joint>. MuJoCo holds them softly (solref, solimp); unidyn holds them exactly, a multiplier
// for each row (book §3.8):
//
//   <connect body1 body2 anchor>: body1's point at `anchor` on its frame stays on the point of
//     body2 that it coincides with at the reference configuration qpos0 (MuJoCo computes that
//     point the same way), three rows dot(p1 − p2, Ei) = 0, i = 1, 2, 3, named <name>_1.._3;
//     body2 left out (or "world") is the ground;
//   <weld body1 body2 anchor relpose>: body1's point P1 stays on body2's point `anchor`, and
//     body2's frame stays turned from body1's by R0, the relative rotation R1ᵀ R2 — both from the
//     pose at qpos0 when relpose's quaternion is 0 (its default), else relpose's position (on
//     body1's frame) and quaternion. With E = R1ᵀ R2 R0ᵀ (the error, I on the constraint), six
//     rows: dot(P1 − anchor, Ei), i = 1, 2, 3, and E23, E31, E12 = dot(f1_i, R2 R0ᵀ Ej), each the
//     first-order turn about f1_1, f1_2, f1_3 (MuJoCo's are a quaternion's, with the same
//     solutions near I and the same row space);
//   <joint joint1 joint2 polycoef="a0 a1 a2 a3 a4">: q1 = a0 + a1 q2 + a2 q2² + a3 q2³ + a4 q2⁴
//     (each angle measured from its qpos0, 0, as `ref` is 0), q1 = a0 without joint2.
//
// <tendon> is refused; an inactive constraint (active="false") is left out, noted.
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

// body1 and body2 of a <connect> or <weld>: body1 required, the two different.
std::pair<std::string, std::string> two_bodies(const MjcfContext& context,
                                               const XMLElement& element) {
  context.source.required(element, "body1");
  auto bodies =
      std::pair{named_body(context, element, "body1"), named_body(context, element, "body2")};
  if (bodies.first == bodies.second) {
    context.source.refuse(element, "a <" + std::string(element.Name()) +
                                       "> joins two different bodies (one may be the world)");
  }
  return bodies;
}

// The rows NAME_1, NAME_2, ... of an equality as position constraints.
void write_rows(MjcfContext& context, const XMLElement& element, const std::string& name,
                const std::vector<std::string>& rows) {
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::string row = context.names.claim(name + "_" + std::to_string(k + 1), "constraint",
                                                context.source.position(element), context.notes);
    context.written.constraints.push_back("  - name: " + row);
    context.written.constraints.push_back("    position: " + rows[k]);
  }
}

// Points p1 and p2 coinciding: dot(p1 − p2, Ei), i = 1, 2, 3.
std::vector<std::string> coincidence_rows(const std::string& p1, const std::string& p2) {
  std::vector<std::string> rows;
  for (int i = 1; i <= 3; ++i) {
    rows.push_back("dot(" + p1 + " - " + p2 + ", E" + std::to_string(i) + ")");
  }
  return rows;
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

// The typed texts of numbers first .. first + count − 1.
std::vector<std::string> typed_texts(const std::vector<Number>& numbers, std::size_t first,
                                     std::size_t count) {
  std::vector<std::string> texts;
  for (std::size_t i = first; i < first + count; ++i) texts.push_back(numbers[i].text);
  return texts;
}

// <connect>: body1's anchor held on body2's point that coincides with it at qpos0.
void write_connect(MjcfContext& context, const XMLElement& connect, const std::string& name) {
  const XmlSource& source = context.source;
  const auto [body1, body2] = two_bodies(context, connect);
  source.required(connect, "anchor");
  const auto anchor = source.required_numbers(connect, "anchor", 3);
  const Eigen::Vector3d on_body1(anchor[0].value, anchor[1].value, anchor[2].value);
  // body2's point: where body1's anchor is at qpos0, on body2's frame
  const Eigen::Vector3d on_body2 =
      frame_at_qpos0(context, body2).inverse() * (frame_at_qpos0(context, body1) * on_body1);
  std::vector<std::string> computed;
  for (Eigen::Index i = 0; i < 3; ++i) computed.push_back(exact_text(on_body2[i]));
  const std::string p1 = point_text(body1, typed_texts(anchor, 0, 3)),
                    p2 = point_text(body2, computed);
  context.notes.push_back(source.position(connect).str() + ": <connect> '" + name + "' holds " +
                          p1 + " on " + p2 + ", the point where it is at qpos0 (computed)");
  write_rows(context, connect, name, coincidence_rows(p1, p2));
}

// The vector X1 f1 + X2 f2 + X3 f3 on a body's frame basis as the model's text (numbers on the
// ground).
std::string frame_vector_text(const std::string& body, const Eigen::Vector3d& X) {
  std::vector<std::string> components;
  for (Eigen::Index i = 0; i < 3; ++i) components.push_back(exact_text(X[i]));
  const std::string vector = "[" + joined(components) + "]";
  return body.empty() ? vector : body + ".frame_point(" + vector + ") - " + body + ".origin";
}

// The weld's pose of body2 relative to body1: body1's point on body2's anchor and R0 = R1ᵀ R2.
struct RelativePose {
  std::vector<std::string> point_on_body1;
  Eigen::Matrix3d R0;
  bool computed = false;
};

RelativePose weld_pose(const MjcfContext& context, const XMLElement& weld, const std::string& body1,
                       const std::string& body2, const std::vector<Number>& anchor) {
  const auto relpose =
      context.source.numbers_or(weld, "relpose", {"0", "1", "0", "0", "0", "0", "0"});
  const Eigen::Quaterniond quaternion(relpose[3].value, relpose[4].value, relpose[5].value,
                                      relpose[6].value);
  RelativePose pose;
  if (quaternion.norm() != 0) {
    // relpose: body1's point and body2's turn from body1, as typed (the quaternion normalised)
    pose.point_on_body1 = typed_texts(relpose, 0, 3);
    pose.R0 = quaternion.normalized().toRotationMatrix();
    return pose;
  }
  // MuJoCo's default: the pose at qpos0
  const Eigen::Isometry3d F1 = frame_at_qpos0(context, body1), F2 = frame_at_qpos0(context, body2);
  const Eigen::Vector3d on_body2(anchor[0].value, anchor[1].value, anchor[2].value);
  const Eigen::Vector3d on_body1 = F1.inverse() * (F2 * on_body2);
  for (Eigen::Index i = 0; i < 3; ++i) pose.point_on_body1.push_back(exact_text(on_body1[i]));
  pose.R0 = F1.linear().transpose() * F2.linear();
  pose.computed = true;
  return pose;
}

// <weld>: three rows hold body1's point on body2's anchor, three hold the relative rotation.
void write_weld(MjcfContext& context, const XMLElement& weld, const std::string& name) {
  const XmlSource& source = context.source;
  const auto [body1, body2] = two_bodies(context, weld);
  const auto anchor = source.numbers_or(weld, "anchor", {"0", "0", "0"});
  const RelativePose pose = weld_pose(context, weld, body1, body2, anchor);
  const std::string p1 = point_text(body1, pose.point_on_body1);
  const std::string p2 = point_text(body2, typed_texts(anchor, 0, 3));
  context.notes.push_back(
      source.position(weld).str() + ": <weld> '" + name + "' holds " + p1 + " on " + p2 + " and " +
      (body2.empty() ? "the ground" : body2) + "'s frame turned from " +
      (body1.empty() ? "the ground" : body1) + "'s by " +
      (pose.computed ? "the rotation at qpos0 (computed)" : "relpose's rotation") +
      ": rows 4-6 are the error rotation's E23, E31, E12");
  std::vector<std::string> rows = coincidence_rows(p1, p2);
  // (i, j) of E = R1ᵀ R2 R0ᵀ: dot(f1_i, R2 R0ᵀ Ej), R0ᵀ Ej the j-th row of R0 on body2's basis
  for (const auto& [i, j] : {std::pair{1, 2}, std::pair{2, 0}, std::pair{0, 1}}) {
    const std::string f1 = body1.empty() ? "E" + std::to_string(i + 1)
                                         : frame_vector_text(body1, Eigen::Vector3d::Unit(i));
    rows.push_back("dot(" + f1 + ", " + frame_vector_text(body2, pose.R0.row(j).transpose()) + ")");
  }
  write_rows(context, weld, name, rows);
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
    if (kind != "connect" && kind != "weld" && kind != "joint") {
      source.refuse(*e, "<" + printable(kind) +
                            "> equality constraints are not supported yet (<connect>, <weld> "
                            "and <joint> are)");
    }
    if (!e->BoolAttribute("active", true)) {
      ++context.equalities;
      context.ignored.add(source, *e, "with active=\"false\": left out, as MuJoCo leaves it off");
      continue;
    }
    const std::string name = equality_name(context, *e);
    // the soft constraint's settings
    std::string soft;
    for (const char* setting : {"solref", "solimp", "torquescale"}) {
      if (e->Attribute(setting)) soft += (soft.empty() ? "" : " and ") + std::string(setting);
    }
    if (!soft.empty()) {
      context.notes.push_back(source.position(*e).str() + ": " + soft +
                              " not applied: unidyn holds the constraint exactly");
    }
    if (kind == "connect") write_connect(context, *e, name);
    if (kind == "weld") write_weld(context, *e, name);
    if (kind == "joint") write_joint_coupling(context, *e, name);
  }
}

}  // namespace unidyn::formats
