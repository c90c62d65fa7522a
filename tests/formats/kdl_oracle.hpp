// Orocos KDL 1.5 as an oracle for URDF trees (tests/formats/urdf_against_kdl.cpp): the file read
// here into a KDL::Tree — by this test's own reading of the URDF elements, not unidyn's — and
// KDL's recursive Newton–Euler inverse dynamics (TreeIdSolver_RNE) give M column by column
// (τ(q, 0, e_i) without gravity) and f = −τ(q, q̇, 0) with gravity; q̈ = M⁻¹ f. KDL keeps full
// inertia tensors as they are written (MuJoCo diagonalises them, ~1e-7 off with two or more
// products of inertia), and a link on a fixed joint as a segment of its own.
//
// The URDF → KDL map (URDF's and KDL's documented conventions): a joint's origin T = (p, R(rpy)),
// rpy the fixed-axis x-y-z angles; its axis a on the joint frame; the child's frame = T ·
// motion(q). A KDL segment's joint is given on the parent's frame (origin p, axis R a) and its tip
// T; a link's inertia, about its centre of mass c on the link frame, is R_i I R_iᵀ (R_i of the
// inertial rpy).
#pragma once

#include <tinyxml2.h>

#include <Eigen/Dense>
#include <functional>
#include <kdl/jntarray.hpp>
#include <kdl/joint.hpp>
#include <kdl/rigidbodyinertia.hpp>
#include <kdl/rotationalinertia.hpp>
#include <kdl/segment.hpp>
#include <kdl/tree.hpp>
#include <kdl/treeidsolver_recursive_newton_euler.hpp>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine_oracle.hpp"

namespace unidyn::kdl_oracle {
namespace {

using engine_oracle::Dynamics;
using engine_oracle::Paths;

// "x y z" of an attribute, or its default.
KDL::Vector triple(const tinyxml2::XMLElement* element, const char* attribute,
                   KDL::Vector fallback) {
  if (element == nullptr || element->Attribute(attribute) == nullptr) return fallback;
  std::istringstream text(element->Attribute(attribute));
  double x = 0, y = 0, z = 0;
  text >> x >> y >> z;
  return KDL::Vector(x, y, z);
}

// An <origin xyz rpy> as a frame (identity when absent).
KDL::Frame origin_frame(const tinyxml2::XMLElement* parent) {
  const tinyxml2::XMLElement* origin = parent ? parent->FirstChildElement("origin") : nullptr;
  const KDL::Vector rpy = triple(origin, "rpy", KDL::Vector::Zero());
  return KDL::Frame(KDL::Rotation::RPY(rpy.x(), rpy.y(), rpy.z()),
                    triple(origin, "xyz", KDL::Vector::Zero()));
}

double number(const tinyxml2::XMLElement* element, const char* attribute) {
  return element ? element->DoubleAttribute(attribute, 0.0) : 0.0;
}

// A link's <inertial> on the link frame: mass, centre of mass, the tensor about it turned by R_i.
KDL::RigidBodyInertia link_inertia(const tinyxml2::XMLElement* link) {
  const tinyxml2::XMLElement* inertial = link->FirstChildElement("inertial");
  if (inertial == nullptr) return KDL::RigidBodyInertia::Zero();
  const KDL::Frame frame = origin_frame(inertial);
  const tinyxml2::XMLElement* i = inertial->FirstChildElement("inertia");
  Eigen::Matrix3d I;
  I << number(i, "ixx"), number(i, "ixy"), number(i, "ixz"), number(i, "ixy"), number(i, "iyy"),
      number(i, "iyz"), number(i, "ixz"), number(i, "iyz"), number(i, "izz");
  Eigen::Matrix3d R;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) R(r, c) = frame.M(r, c);
  }
  const Eigen::Matrix3d turned = R * I * R.transpose();
  return KDL::RigidBodyInertia(number(inertial->FirstChildElement("mass"), "value"), frame.p,
                               KDL::RotationalInertia(turned(0, 0), turned(1, 1), turned(2, 2),
                                                      turned(0, 1), turned(0, 2), turned(1, 2)));
}

// A URDF joint as KDL's: revolute and continuous turn, prismatic slides, fixed holds.
KDL::Joint kdl_joint(const tinyxml2::XMLElement* joint) {
  const std::string name = joint->Attribute("name");
  const std::string type = joint->Attribute("type");
  if (type == "fixed") return KDL::Joint(name, KDL::Joint::Fixed);
  const KDL::Frame T = origin_frame(joint);
  KDL::Vector axis = triple(joint->FirstChildElement("axis"), "xyz", KDL::Vector(1, 0, 0));
  axis.Normalize();
  if (type == "revolute" || type == "continuous") {
    return KDL::Joint(name, T.p, T.M * axis, KDL::Joint::RotAxis);
  }
  if (type == "prismatic") return KDL::Joint(name, T.p, T.M * axis, KDL::Joint::TransAxis);
  throw std::runtime_error("the KDL oracle takes no " + type + " joint ('" + name + "')");
}

// The URDF file as a KDL tree, its segments added depth first in the file's order of joints (so
// that KDL numbers the moving joints as unidyn orders its coordinates); the joints' names by q_nr.
struct KdlTree {
  KDL::Tree tree;
  std::vector<std::string> joint_names;
  std::vector<bool> prismatic;
};

KdlTree read_kdl_tree(const std::string& path) {
  tinyxml2::XMLDocument document;
  if (document.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) {
    throw std::runtime_error("cannot read " + path);
  }
  const tinyxml2::XMLElement* robot = document.FirstChildElement("robot");
  std::map<std::string, const tinyxml2::XMLElement*> links;
  std::multimap<std::string, const tinyxml2::XMLElement*> joints_by_parent;  // in file order
  std::map<std::string, bool> is_child;
  for (auto* e = robot->FirstChildElement("link"); e; e = e->NextSiblingElement("link")) {
    links[e->Attribute("name")] = e;
  }
  for (auto* e = robot->FirstChildElement("joint"); e; e = e->NextSiblingElement("joint")) {
    joints_by_parent.emplace(e->FirstChildElement("parent")->Attribute("link"), e);
    is_child[e->FirstChildElement("child")->Attribute("link")] = true;
  }
  std::string root;
  for (const auto& [name, link] : links) {
    if (!is_child.count(name)) root = name;
  }
  KdlTree result{KDL::Tree(root), {}, {}};
  std::function<void(const std::string&)> add_children = [&](const std::string& parent) {
    const auto [first, last] = joints_by_parent.equal_range(parent);
    for (auto it = first; it != last; ++it) {
      const tinyxml2::XMLElement* joint = it->second;
      const std::string child = joint->FirstChildElement("child")->Attribute("link");
      const KDL::Joint kdl = kdl_joint(joint);
      result.tree.addSegment(
          KDL::Segment(child, kdl, origin_frame(joint), link_inertia(links.at(child))), parent);
      if (kdl.getType() != KDL::Joint::Fixed) {
        result.joint_names.push_back(kdl.getName());
        result.prismatic.push_back(kdl.getType() == KDL::Joint::TransAxis);
      }
      add_children(child);
    }
  };
  add_children(root);
  // the numbering KDL gave: q_nr of each moving joint's segment
  for (const auto& [name, element] : result.tree.getSegments()) {
    const KDL::Joint& joint = GetTreeElementSegment(element).getJoint();
    if (joint.getType() == KDL::Joint::Fixed) continue;
    if (result.joint_names.at(GetTreeElementQNr(element)) != joint.getName()) {
      throw std::runtime_error("KDL numbered joint " + joint.getName() + " out of order");
    }
  }
  return result;
}

// τ = M q̈ + C(q, q̇) q̇ + G(q) by KDL's recursive Newton–Euler algorithm, no external wrench.
Eigen::VectorXd kdl_torques(const KdlTree& kdl, const KDL::Vector& gravity,
                            const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                            const Eigen::VectorXd& qddot) {
  KDL::TreeIdSolver_RNE solver(kdl.tree, gravity);
  const auto n = static_cast<unsigned>(q.size());
  KDL::JntArray Q(n), Qd(n), Qdd(n), torques(n);
  Q.data = q;
  Qd.data = qdot;
  Qdd.data = qddot;
  KDL::WrenchMap external;
  if (solver.CartToJnt(Q, Qd, Qdd, external, torques) < 0) {
    throw std::runtime_error("KDL's inverse dynamics failed");
  }
  return torques.data;
}

// KDL's M (columns τ(q, 0, e_i) without gravity), f = −τ(q, q̇, 0) with gravity −9.81 E3, q̈.
Dynamics kdl_dynamics(const KdlTree& kdl, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
  const auto n = q.size();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  Eigen::MatrixXd M(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    M.col(i) = kdl_torques(kdl, KDL::Vector::Zero(), q, zero, Eigen::VectorXd::Unit(n, i));
  }
  const Eigen::VectorXd f = -kdl_torques(kdl, KDL::Vector(0, 0, -9.81), q, qdot, zero);
  return {M, f, M.ldlt().solve(f)};
}

// The URDF file in unidyn and in KDL at 20 random states (engine_oracle::expect_agreement): angles
// within ±2 rad, slides within ±0.5 m, rates within ±2.
inline void expect_agreement_with_kdl(const std::string& file, Paths paths = Paths::both) {
  const KdlTree kdl = read_kdl_tree(engine_oracle::formats_model(file));
  const engine_oracle::LoadedFile unidyn = engine_oracle::load_and_compile(file, paths);
  const auto& coordinates = unidyn.loaded.system.coordinates();
  ASSERT_EQ(coordinates.size(), kdl.joint_names.size());
  for (std::size_t i = 0; i < coordinates.size(); ++i) {
    ASSERT_EQ(coordinates[i].name, kdl.joint_names[i]);
  }
  const engine_oracle::Engine engine{
      "Orocos KDL 1.5",
      [&](test::Random& random, Eigen::VectorXd& q, Eigen::VectorXd& qdot) {
        const auto n = static_cast<Eigen::Index>(kdl.joint_names.size());
        q.resize(n);
        qdot.resize(n);
        for (Eigen::Index i = 0; i < n; ++i) {
          q[i] = kdl.prismatic[static_cast<std::size_t>(i)] ? random.uniform(-0.5, 0.5)
                                                            : random.uniform(-2.0, 2.0);
          qdot[i] = random.uniform(-2.0, 2.0);
        }
      },
      [&](const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
        return kdl_dynamics(kdl, q, qdot);
      }};
  engine_oracle::expect_agreement(file, unidyn, paths, engine);
}

}  // namespace
}  // namespace unidyn::kdl_oracle
