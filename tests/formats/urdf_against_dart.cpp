// The URDF test models (tests/formats/models) read by unidyn and by DART 6.12 — a third engine,
// written independently of unidyn, MuJoCo and KDL, reading the file with its own URDF loader
// (dart::utils::DartLoader, the root link fixed to the world, a link without <inertial> massless
// as URDF has it): at random states DART's mass
// matrix (its composite-rigid-body recursion), −(Coriolis + gravity forces) as f, and q̈ of its
// articulated-body forward dynamics agree with unidyn's to 1e-10 relative
// (engine_oracle::expect_agreement).
#include "engine_oracle.hpp"

#ifdef UNIDYN_HAVE_DART
#include <dart/dynamics/DegreeOfFreedom.hpp>
#include <dart/dynamics/PrismaticJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/utils/urdf/DartLoader.hpp>
#endif

namespace unidyn {
namespace {

#ifdef UNIDYN_HAVE_DART

using engine_oracle::Dynamics;
using engine_oracle::Paths;

// The file as DART's skeleton, gravity −9.81 E3, and where each of unidyn's coordinates (by its
// joint's name) sits among DART's degrees of freedom.
struct DartSkeleton {
  dart::dynamics::SkeletonPtr skeleton;
  std::vector<std::size_t> dof_of;  // coordinate i ↦ DART's index
  std::vector<bool> prismatic;      // by coordinate
};

DartSkeleton read_dart_skeleton(const std::string& path, const System& system) {
  dart::utils::DartLoader::Options options;
  options.mDefaultRootJointType = dart::utils::DartLoader::RootJointType::FIXED;
  // a link without <inertial> has no mass (URDF's rule; DART's default would be 1 kg)
  options.mDefaultInertia =
      dart::dynamics::Inertia(0.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero());
  dart::utils::DartLoader loader(options);
  DartSkeleton result{loader.parseSkeleton(dart::common::Uri::createFromPath(path)), {}, {}};
  if (!result.skeleton) throw std::runtime_error("DART cannot read " + path);
  result.skeleton->setGravity(Eigen::Vector3d(0, 0, -9.81));
  const auto& coordinates = system.coordinates();
  if (result.skeleton->getNumDofs() != coordinates.size()) {
    throw std::runtime_error("DART reads " + std::to_string(result.skeleton->getNumDofs()) +
                             " degrees of freedom, unidyn " + std::to_string(coordinates.size()));
  }
  for (const auto& q : coordinates) {
    const dart::dynamics::DegreeOfFreedom* dof = result.skeleton->getDof(q.name);
    if (dof == nullptr) throw std::runtime_error("DART has no degree of freedom " + q.name);
    result.dof_of.push_back(dof->getIndexInSkeleton());
    result.prismatic.push_back(dof->getJoint()->getType() ==
                               dart::dynamics::PrismaticJoint::getStaticType());
  }
  return result;
}

// DART's M, f = −(C q̇ + g) and its forward dynamics' q̈ (no joint forces), in unidyn's order.
Dynamics dart_dynamics(const DartSkeleton& dart, const Eigen::VectorXd& q,
                       const Eigen::VectorXd& qdot) {
  const auto n = q.size();
  Eigen::VectorXd positions(n), velocities(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<Eigen::Index>(dart.dof_of[static_cast<std::size_t>(i)]);
    positions[k] = q[i];
    velocities[k] = qdot[i];
  }
  auto& skeleton = *dart.skeleton;
  skeleton.setPositions(positions);
  skeleton.setVelocities(velocities);
  skeleton.setForces(Eigen::VectorXd::Zero(n));
  skeleton.computeForwardDynamics();
  const Eigen::MatrixXd& M = skeleton.getMassMatrix();
  const Eigen::VectorXd f = -skeleton.getCoriolisAndGravityForces();
  const Eigen::VectorXd& qddot = skeleton.getAccelerations();
  Dynamics result{Eigen::MatrixXd(n, n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<Eigen::Index>(dart.dof_of[static_cast<std::size_t>(i)]);
    result.f[i] = f[k];
    result.qddot[i] = qddot[k];
    for (Eigen::Index j = 0; j < n; ++j) {
      result.M(i, j) = M(k, static_cast<Eigen::Index>(dart.dof_of[static_cast<std::size_t>(j)]));
    }
  }
  return result;
}

// The URDF file in unidyn and in DART at 20 random states: angles within ±2 rad, slides within
// ±0.5 m, rates within ±2.
void expect_agreement_with_dart(const std::string& file, Paths paths = Paths::both) {
  const engine_oracle::LoadedFile unidyn = engine_oracle::load_and_compile(file, paths);
  const DartSkeleton dart =
      read_dart_skeleton(engine_oracle::formats_model(file), unidyn.loaded.system);
  const engine_oracle::Engine engine{
      std::string("DART ") + DART_VERSION,
      [&](test::Random& random, Eigen::VectorXd& q, Eigen::VectorXd& qdot) {
        const auto n = static_cast<Eigen::Index>(dart.dof_of.size());
        q.resize(n);
        qdot.resize(n);
        for (Eigen::Index i = 0; i < n; ++i) {
          q[i] = dart.prismatic[static_cast<std::size_t>(i)] ? random.uniform(-0.5, 0.5)
                                                             : random.uniform(-2.0, 2.0);
          qdot[i] = random.uniform(-2.0, 2.0);
        }
      },
      [&](const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
        return dart_dynamics(dart, q, qdot);
      }};
  engine_oracle::expect_agreement(file, unidyn, paths, engine);
}

// The files KDL checks (urdf_against_kdl.cpp): three oracles on the same trees.
TEST(UrdfAgainstDart, IiwaLikeArm) {
  expect_agreement_with_dart("iiwa-like-arm.urdf", Paths::recursive);
}

TEST(UrdfAgainstDart, PrismaticAndFixed) {
  expect_agreement_with_dart("prismatic-and-fixed.urdf", Paths::recursive);
}

TEST(UrdfAgainstDart, FullInertia) {
  expect_agreement_with_dart("full-inertia.urdf", Paths::recursive);
}

TEST(UrdfAgainstDart, LeggedTree) {
  expect_agreement_with_dart("legged-tree.urdf", Paths::recursive);
}

TEST(UrdfAgainstDart, TwelveLinkChain) {
  expect_agreement_with_dart("twelve-link-chain.urdf", Paths::recursive);
}

#else

TEST(UrdfAgainstDart, Skipped) {
  GTEST_SKIP() << "DART is not installed (scripts/setup.sh test installs libdart-utils-urdf-dev)";
}

#endif

}  // namespace
}  // namespace unidyn
