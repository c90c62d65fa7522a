// The articulated-body algorithm in doubles (include/unidyn/tree/articulated_body.hpp).
#include "unidyn/tree/articulated_body.hpp"

#include "unidyn/tree/tree_dynamics.hpp"

namespace unidyn::tree {

template void articulated_body_accelerations<double>(const TreeModel&, TreeVector, TreeVector,
                                                     TreeVector, Eigen::VectorXd&, TreeData&);

}  // namespace unidyn::tree
