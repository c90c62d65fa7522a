// Ball and floating joints in doubles (include/unidyn/tree/euler_parameter_joint.hpp).
#include "unidyn/tree/euler_parameter_joint.hpp"

namespace unidyn::tree {

template FramePlacement euler_joint_placement<double>(const TreeLink&, TreeVector, EulerJointData&);
template FramePlacement euler_joint_kinematics<double>(const TreeLink&, TreeVector, TreeVector,
                                                       EulerJointData&);
template void euler_joint_accelerations<double>(const TreeLink&, const EulerJointData&,
                                                const Vector6d&, Eigen::VectorXd&);

}  // namespace unidyn::tree
