// A URDF joint as a body's `joint:` on its parent, its coordinates and its damper.
#pragma once

#include <string>
#include <vector>

#include "urdf_parts.hpp"
#include "urdf_tree.hpp"

namespace unidyn::formats {

struct JointText {
  std::string line;                      // `    joint: {...}`
  std::vector<std::string> coordinates;  // named after the joint
  std::vector<std::string> initial;      // `NAME: value` of coordinates that cannot start at 0
  std::string damper;                    // a `torsion_damper` force, or ""
};

// The joint's line for the child body, its coordinates named by `names`; refused: a zero axis, a
// planar axis off the joint frame's basis, <mimic>, friction, damping but on a revolute joint.
JointText joint_text(const LinkContext& context, const UrdfJoint& joint, const std::string& parent,
                     Names& names);

// With --limits, a revolute or prismatic joint's <limit lower upper> (default 0, 0) as two
// unilateral contacts; lower ≥ upper refused (a joint held at one value is a fixed joint).
void write_joint_limits(const LinkContext& context, const UrdfJoint& joint,
                        const std::string& coordinate, Names& names, Written& written);

}  // namespace unidyn::formats
