// The URDF test models (tests/formats/models) read by unidyn and by MuJoCo 2.2.2, an engine written
// independently of unidyn: at random states (q, q̇) the mass matrix M, the forcing f of
// Lagrange's equations M q̈ = f (book (3.7); no constraints) and the accelerations q̈ agree with
// MuJoCo's mj_fullM, −qfrc_bias and the qacc of mj_forward.
//
// What the models assume of MuJoCo's URDF reader, measured (2.2.2): the root link is a body welded
// to the world (no joint); each moving joint is one dof, in the file's depth-first order, named
// after the joint; <mujoco><compiler fusestatic="false"/> keeps a link on a fixed joint a body of
// its own; a link without <inertial> is a body of mass 0, which MuJoCo accepts only when no joint
// moves it alone (a "moving body" needs mass, or a fixed child with mass); no <collision>, and
// discardvisual="true", leave no geom, hence no contact; joint damping, armature, friction loss
// and stiffness are 0, limits only become constraints outside their range (nefc is checked 0).
#include "mujoco_oracle.hpp"

namespace unidyn {
namespace {

using mujoco_oracle::expect_agreement_with_mujoco;

TEST(UrdfAgainstMujoco, IiwaLikeArmMassMatrixBiasAndAccelerations) {
  expect_agreement_with_mujoco("iiwa-like-arm.urdf");
}

TEST(UrdfAgainstMujoco, PlanarThreeLinkMassMatrixBiasAndAccelerations) {
  expect_agreement_with_mujoco("planar-three-link.urdf");
}

TEST(UrdfAgainstMujoco, PrismaticAndFixedMassMatrixBiasAndAccelerations) {
  expect_agreement_with_mujoco("prismatic-and-fixed.urdf");
}

// <dynamics damping> in a continuous joint (a torsion damper) and a prismatic one on a tilted rail
// (a slide damper): MuJoCo's passive forces −b q̇.
TEST(UrdfAgainstMujoco, DampedJointsMassMatrixForcesAndAccelerations) {
  expect_agreement_with_mujoco("damped-joints.urdf");
}

TEST(UrdfAgainstMujoco, FullInertiaMassMatrixBiasAndAccelerations) {
  expect_agreement_with_mujoco("full-inertia.urdf");
}

// Twelve links on parallel axes: their frames must compose to angle sums (tree_joint.cpp), or the
// derivation runs out of memory before it is compared.
TEST(UrdfAgainstMujoco, TwelveLinkChainMassMatrixBiasAndAccelerations) {
  expect_agreement_with_mujoco("twelve-link-chain.urdf");
}

}  // namespace
}  // namespace unidyn
