// peer_simbody: the benchmark models of bench/MODELS.md in Simbody (see peer_common.hpp for the
// command line).
//
// Conventions:
// - pendulum-N: a chain of MobilizedBody::Pin. A Pin rotates about the common Z axis of its F and
//   M frames, so with Ground's E3 as that axis and gravity −9.81 E2 the motion is in the E1–E2
//   plane of MODELS.md. Each link's body frame sits at its inboard hinge with the exact point
//   mass at (0, −L, 0); the next Pin's F frame is at that particle. q and u are then the relative
//   angles and their rates.
// - heavy-top: MobilizedBody::Ball at O; q = quaternion (w, x, y, z) of R_FM = R_GB.
// - torque-free: MobilizedBody::Free; q = (quaternion, position), no gravity element.
// For Ball and Free the rotational u are w_FM expressed in F (here Ground), not in the body
// (MobilizedBody_Ball.h): the peer sets u = R ω_b and reports ω̇_b = Rᵀ α_G, with α_G the body's
// angular acceleration in Ground; d/dt(Rᵀ ω_G) = Rᵀ ω̇_G + Ṙᵀ ω_G and Ṙᵀ ω_G = −Rᵀ (ω_G × ω_G) = 0.
#include <simbody/internal/Force_Gravity.h>
#include <simbody/internal/GeneralForceSubsystem.h>
#include <simbody/internal/MobilizedBody_Ball.h>
#include <simbody/internal/MobilizedBody_Free.h>
#include <simbody/internal/MobilizedBody_Ground.h>
#include <simbody/internal/MobilizedBody_Pin.h>
#include <simbody/internal/MultibodySystem.h>
#include <simbody/internal/SimbodyMatterSubsystem.h>
#include <simmath/RungeKutta3Integrator.h>
#include <simmath/RungeKuttaMersonIntegrator.h>
#include <simmath/VerletIntegrator.h>

#include <memory>
#include <string>
#include <vector>

#include "peer_common.hpp"

namespace unidyn::peers {
namespace {

using SimTK::MobilizedBody;
using SimTK::Rotation;
using SimTK::Stage;
using SimTK::Vec3;

class SimbodyBackend final : public Backend {
 public:
  explicit SimbodyBackend(const Model& model) : model_(model), matter_(system_), forces_(system_) {
    build();
    system_.realizeTopology();
    state_ = system_.getDefaultState();
    system_.realizeModel(state_);
  }

  std::vector<double> rhs(const std::vector<double>& state) override {
    setState(state_, state);
    system_.realize(state_, Stage::Acceleration);
    if (!model_.isBody()) {
      std::vector<double> qdd(model_.links);
      for (int k = 0; k < model_.links; ++k) qdd[k] = bodies_[k].getOneUDot(state_, 0);
      return qdd;
    }
    const Rotation& rotation = bodies_[0].getBodyRotation(state_);
    const Vec3 alpha = ~rotation * bodies_[0].getBodyAngularAcceleration(state_);
    return {alpha[0], alpha[1], alpha[2]};
  }

  // Each evaluation assigns Q and U (invalidating the Position stage and everything after it),
  // then realizes through Stage::Acceleration: kinematics, forces, articulated-body inertias and
  // accelerations are all recomputed.
  double nsPerEval(const std::vector<double>& state, double minSeconds) override {
    setState(state_, state);
    const SimTK::Vector q = state_.getQ();
    const SimTK::Vector u = state_.getU();
    return timeEvaluations(
        [&] {
          state_.updQ() = q;
          state_.updU() = u;
          system_.realize(state_, Stage::Acceleration);
        },
        minSeconds);
  }

  // Error-controlled integrators with setAccuracy(--accuracy) and setFinalTime(--t-end), advanced
  // with Integrator::stepTo (projection settings left at their defaults). Pass 1 returns after
  // every internal step and checks system.calcEnergy; pass 2, timed, steps to the end without
  // returning. The step sequence is the same; steps and the final state come from pass 2.
  SimulateResult simulate(const std::vector<double>& initial,
                          const SimulateOptions& options) override {
    if (!options.accuracy) throw UsageError("peer_simbody simulate needs --accuracy");
    if (options.dt) throw UsageError("peer_simbody integrators are error-controlled: drop --dt");
    const std::string& name = options.integrator;
    if (name != "rkmerson" && name != "rk3" && name != "verlet") {
      throw UsageError("unknown Simbody integrator '" + name + "' (rkmerson, rk3, verlet)");
    }
    SimTK::State start = system_.getDefaultState();
    setState(start, initial);

    // Pass 1: energy after every internal step.
    auto checked = makeIntegrator(name, options);
    checked->setReturnEveryInternalStep(true);
    checked->initialize(start);
    EnergyMonitor monitor(system_.calcEnergy(checked->getState()));
    while (!checked->isSimulationOver()) {
      checked->stepTo(options.tEnd);
      monitor.observe(system_.calcEnergy(checked->getState()));
    }

    // Pass 2: the integration alone, timed.
    auto timed = makeIntegrator(name, options);
    timed->initialize(start);
    const Stopwatch stopwatch;
    while (!timed->isSimulationOver()) timed->stepTo(options.tEnd);
    const double wall = stopwatch.seconds();

    SimulateResult result;
    result.wallSeconds = wall;
    result.steps = timed->getNumStepsTaken();
    result.maxRelativeEnergyError = monitor.maxRelativeError();
    result.initialEnergy = monitor.initial();
    result.finalState = peerState(timed->getState());
    if (result.steps != checked->getNumStepsTaken() ||
        result.finalState != peerState(checked->getState())) {
      std::fprintf(stderr, "peer_simbody: warning: timed pass took a different path\n");
    }
    return result;
  }

 private:
  void build() {
    using SimTK::Body;
    using SimTK::Inertia;
    using SimTK::MassProperties;
    using SimTK::Transform;
    switch (model_.kind) {
      case ModelKind::kPendulum: {
        // The force subsystem owns the element; the handle may go out of scope.
        SimTK::Force::Gravity gravity(forces_, matter_, -SimTK::YAxis, kGravity);
        const Vec3 particle(0, -kPendulumLength, 0);
        const Body::Rigid link(
            MassProperties(kPendulumMass, particle, Inertia(particle, kPendulumMass)));
        MobilizedBody parent = matter_.Ground();
        for (int k = 0; k < model_.links; ++k) {
          const Transform inboard = k == 0 ? Transform() : Transform(particle);
          MobilizedBody::Pin pin(parent, inboard, link, Transform());
          bodies_.push_back(pin);
          parent = pin;
        }
        break;
      }
      case ModelKind::kHeavyTop: {
        SimTK::Force::Gravity gravity(forces_, matter_, -SimTK::ZAxis, kGravity);
        const Vec3 centre(0, 0, kTopL);
        const Inertia aboutO = Inertia(kTopA, kTopA, kTopC).shiftFromMassCenter(centre, kTopMass);
        bodies_.push_back(MobilizedBody::Ball(matter_.Ground(), Transform(),
                                              Body::Rigid(MassProperties(kTopMass, centre, aboutO)),
                                              Transform()));
        break;
      }
      case ModelKind::kTorqueFree: {
        const Inertia inertia(kFreeInertia[0], kFreeInertia[1], kFreeInertia[2]);
        bodies_.push_back(MobilizedBody::Free(
            matter_.Ground(), Transform(), Body::Rigid(MassProperties(kFreeMass, Vec3(0), inertia)),
            Transform()));
        break;
      }
      case ModelKind::kRobotFile:
        throw UsageError(
            "peer_simbody reads no robot files (Simbody's URDF reader is not in Debian)");
    }
  }

  std::unique_ptr<SimTK::Integrator> makeIntegrator(const std::string& name,
                                                    const SimulateOptions& options) const {
    std::unique_ptr<SimTK::Integrator> integrator;
    if (name == "rkmerson") {
      integrator = std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system_);
    } else if (name == "rk3") {
      integrator = std::make_unique<SimTK::RungeKutta3Integrator>(system_);
    } else {
      integrator = std::make_unique<SimTK::VerletIntegrator>(system_);
    }
    integrator->setAccuracy(*options.accuracy);
    integrator->setFinalTime(options.tEnd);
    return integrator;
  }

  // Peer state → Q/U of `s` (Ball/Free: q[0..3] is the quaternion, u[0..2] = R ω_b).
  void setState(SimTK::State& s, const std::vector<double>& x) const {
    if (!model_.isBody()) {
      for (int k = 0; k < model_.links; ++k) {
        bodies_[k].setOneQ(s, 0, x[k]);
        bodies_[k].setOneU(s, 0, x[model_.links + k]);
      }
      return;
    }
    const MobilizedBody& body = bodies_[0];
    for (int i = 0; i < 4; ++i) body.setOneQ(s, i, x[i]);
    const Rotation rotation(SimTK::Quaternion(x[0], x[1], x[2], x[3]));
    const Vec3 omega = rotation * Vec3(x[4], x[5], x[6]);
    for (int i = 0; i < 3; ++i) body.setOneU(s, i, omega[i]);
    if (model_.kind == ModelKind::kTorqueFree) {
      for (int i = 4; i < 7; ++i) body.setOneQ(s, i, 0.0);  // centre at rest at O
      for (int i = 3; i < 6; ++i) body.setOneU(s, i, 0.0);
    }
  }

  // Q/U of `s` → peer state (the quaternion is Simbody's q, continuous along a trajectory).
  std::vector<double> peerState(const SimTK::State& s) const {
    std::vector<double> x;
    if (!model_.isBody()) {
      for (int k = 0; k < model_.links; ++k) x.push_back(bodies_[k].getOneQ(s, 0));
      for (int k = 0; k < model_.links; ++k) x.push_back(bodies_[k].getOneU(s, 0));
      return x;
    }
    const MobilizedBody& body = bodies_[0];
    for (int i = 0; i < 4; ++i) x.push_back(body.getOneQ(s, i));
    const Rotation rotation(SimTK::Quaternion(x[0], x[1], x[2], x[3]));
    const Vec3 omega = ~rotation * Vec3(body.getOneU(s, 0), body.getOneU(s, 1), body.getOneU(s, 2));
    for (int i = 0; i < 3; ++i) x.push_back(omega[i]);
    return x;
  }

  Model model_;
  SimTK::MultibodySystem system_;
  SimTK::SimbodyMatterSubsystem matter_;
  SimTK::GeneralForceSubsystem forces_;
  std::vector<MobilizedBody> bodies_;
  SimTK::State state_;
};

std::unique_ptr<Backend> makeSimbody(const Model& model) {
  return std::make_unique<SimbodyBackend>(model);
}

}  // namespace
}  // namespace unidyn::peers

int main(int argc, char** argv) {
  return unidyn::peers::peerMain(argc, argv, "rkmerson, rk3, verlet (error-controlled --accuracy)",
                                 unidyn::peers::makeSimbody);
}
