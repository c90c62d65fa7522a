// Pass 1 of the recursive algorithms in doubles (include/unidyn/tree/tree_kinematics.hpp).
#include "unidyn/tree/tree_kinematics.hpp"

namespace unidyn::tree {

template void tree_placements<double>(const TreeModel&, TreeVector, TreeData&);
template void tree_kinematics<double>(const TreeModel&, TreeVector, TreeVector, TreeData&);

}  // namespace unidyn::tree
