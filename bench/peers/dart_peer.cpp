// peer_dart: URDF robot files (bench part 10) in DART 6.12 (see peer_common.hpp for the command
// line). Only `rhs FILE.urdf`: DART's own URDF loader (the root link fixed to the world, gravity
// −9.81 E3), the state (q, q̇) in the file's depth-first order of its moving joints (as MuJoCo
// and unidyn order them), q̈ by Skeleton::computeForwardDynamics (Featherstone's articulated-body
// algorithm) with no joint forces; the timing repeats setPositions, setVelocities and the forward
// dynamics, which recomputes every stage from them.
#include <tinyxml2.h>

#include <dart/dynamics/DegreeOfFreedom.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/utils/urdf/DartLoader.hpp>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "peer_common.hpp"

namespace unidyn::peers {
namespace {

// The moving joints' names in the file's depth-first order (children in the order of the file's
// <joint> elements).
std::vector<std::string> jointsInFileOrder(const std::string& path) {
  tinyxml2::XMLDocument document;
  if (document.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) {
    throw std::runtime_error("cannot read " + path);
  }
  const tinyxml2::XMLElement* robot = document.FirstChildElement("robot");
  if (robot == nullptr) throw std::runtime_error(path + " has no <robot>");
  std::multimap<std::string, const tinyxml2::XMLElement*> byParent;
  std::map<std::string, bool> isChild;
  for (auto* j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
    byParent.emplace(j->FirstChildElement("parent")->Attribute("link"), j);
    isChild[j->FirstChildElement("child")->Attribute("link")] = true;
  }
  std::vector<std::string> names;
  const std::function<void(const std::string&)> visit = [&](const std::string& link) {
    const auto [first, last] = byParent.equal_range(link);
    for (auto it = first; it != last; ++it) {
      if (std::string(it->second->Attribute("type")) != "fixed") {
        names.emplace_back(it->second->Attribute("name"));
      }
      visit(it->second->FirstChildElement("child")->Attribute("link"));
    }
  };
  for (auto* l = robot->FirstChildElement("link"); l; l = l->NextSiblingElement("link")) {
    if (!isChild.count(l->Attribute("name"))) visit(l->Attribute("name"));
  }
  return names;
}

class DartBackend final : public Backend {
 public:
  explicit DartBackend(const Model& model) {
    const std::string& path = model.name;
    if (model.kind != ModelKind::kRobotFile || path.size() < 5 ||
        path.compare(path.size() - 5, 5, ".urdf") != 0) {
      throw UsageError("peer_dart reads URDF robot files only (bench part 10)");
    }
    dart::utils::DartLoader::Options options;
    options.mDefaultRootJointType = dart::utils::DartLoader::RootJointType::FIXED;
    // a link without <inertial> has no mass (URDF's rule; DART's default would be 1 kg)
    options.mDefaultInertia =
        dart::dynamics::Inertia(0.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero());
    skeleton_ =
        dart::utils::DartLoader(options).parseSkeleton(dart::common::Uri::createFromPath(path));
    if (!skeleton_) throw std::runtime_error("DART cannot read " + path);
    skeleton_->setGravity(Eigen::Vector3d(0, 0, -kGravity));
    for (const std::string& name : jointsInFileOrder(path)) {
      const dart::dynamics::DegreeOfFreedom* dof = skeleton_->getDof(name);
      if (dof == nullptr) throw std::runtime_error("DART has no degree of freedom " + name);
      dofOf_.push_back(static_cast<Eigen::Index>(dof->getIndexInSkeleton()));
    }
    if (dofOf_.size() != skeleton_->getNumDofs()) {
      throw std::runtime_error("DART's degrees of freedom are not the file's moving joints");
    }
    positions_.resize(static_cast<Eigen::Index>(dofOf_.size()));
    velocities_.resize(positions_.size());
    skeleton_->setForces(Eigen::VectorXd::Zero(positions_.size()));
  }

  std::vector<double> rhs(const std::vector<double>& state) override {
    setState(state);
    skeleton_->computeForwardDynamics();
    const Eigen::VectorXd& qddot = skeleton_->getAccelerations();
    std::vector<double> out;
    for (const Eigen::Index k : dofOf_) out.push_back(qddot[k]);
    return out;
  }

  double nsPerEval(const std::vector<double>& state, double minSeconds) override {
    setState(state);
    dart::dynamics::Skeleton* skeleton = skeleton_.get();
    return timeEvaluations(
        [&] {
          skeleton->setPositions(positions_);
          skeleton->setVelocities(velocities_);
          skeleton->computeForwardDynamics();
        },
        minSeconds);
  }

  SimulateResult simulate(const std::vector<double>&, const SimulateOptions&) override {
    throw UsageError("peer_dart has no simulate (it times the right-hand side of robot files)");
  }

 private:
  void setState(const std::vector<double>& state) {
    const std::size_t n = dofOf_.size();
    if (state.size() != 2 * n) {
      throw UsageError("expected " + std::to_string(2 * n) + " numbers (q, q')");
    }
    for (std::size_t i = 0; i < n; ++i) {
      positions_[dofOf_[i]] = state[i];
      velocities_[dofOf_[i]] = state[n + i];
    }
    skeleton_->setPositions(positions_);
    skeleton_->setVelocities(velocities_);
  }

  dart::dynamics::SkeletonPtr skeleton_;
  std::vector<Eigen::Index> dofOf_;  // the file's joint i ↦ DART's index
  Eigen::VectorXd positions_, velocities_;
};

std::unique_ptr<Backend> makeDart(const Model& model) {
  return std::make_unique<DartBackend>(model);
}

}  // namespace
}  // namespace unidyn::peers

int main(int argc, char** argv) {
  return unidyn::peers::peerMain(argc, argv, "none (rhs only)", unidyn::peers::makeDart);
}
