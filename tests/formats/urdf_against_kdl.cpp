// The URDF test models (tests/formats/models) read by unidyn and by Orocos KDL 1.5 (an engine
// written independently of unidyn, reading the file by this test's own URDF reading,
// kdl_oracle.hpp): at random states M, f and q̈ agree to 1e-10 relative. KDL keeps what MuJoCo
// cannot check exactly: inertia tensors with two or three products of inertia, and links on fixed
// joints with tensors of their own (MuJoCo re-diagonalises the fused body).
#include "kdl_oracle.hpp"

namespace unidyn {
namespace {

#ifdef UNIDYN_HAVE_KDL

using kdl_oracle::expect_agreement_with_kdl;
using kdl_oracle::Paths;

// The files MuJoCo checks too (urdf_against_mujoco.cpp): the two oracles agree on them.
TEST(UrdfAgainstKdl, IiwaLikeArm) {
  expect_agreement_with_kdl("iiwa-like-arm.urdf");
}

TEST(UrdfAgainstKdl, PrismaticAndFixed) {
  expect_agreement_with_kdl("prismatic-and-fixed.urdf");
}

// (its compiled equations, 2.3 s to derive, are compared with MuJoCo's)
TEST(UrdfAgainstKdl, FullInertia) {
  expect_agreement_with_kdl("full-inertia.urdf", Paths::recursive);
}

// Four legs on a torso: branches, tensors with three products on turned inertial frames, a hip
// mounted at a generic rpy, feet on fixed joints; the recursive algorithms and the compiled
// Lagrange's equations.
TEST(UrdfAgainstKdl, LeggedTree) {
  expect_agreement_with_kdl("legged-tree.urdf");
}

#else

TEST(UrdfAgainstKdl, Skipped) {
  GTEST_SKIP() << "Orocos KDL is not installed (scripts/setup.sh test installs liborocos-kdl-dev)";
}

#endif

}  // namespace
}  // namespace unidyn
