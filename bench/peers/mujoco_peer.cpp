// peer_mujoco: the benchmark models of bench/MODELS.md in MuJoCo (see peer_common.hpp for the
// command line).
//
// Conventions (checked against libmujoco 2.2.2 by comparing qvel with cvel/xmat):
// - pendulum-N: one body per link, a hinge about +z at the link's inboard end and the particle
//   as an `inertial` (mass 1, diaginertia 1e-12) at the outboard end; gravity −9.81 E2, so
//   qpos/qvel/qacc are the relative angles and their rates directly.
// - heavy-top: ball joint at the body origin O; qpos = (w, x, y, z) body-to-world, qvel = ω in
//   body components, hence qacc = ω̇ in body components.
// - torque-free: free joint; qpos = (position, quaternion), qvel = (linear velocity in world
//   components, ω in body components).
// Contacts are disabled (the models have no geoms anyway).
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "peer_common.hpp"

namespace unidyn::peers {
namespace {

// MJCF text of one benchmark model.
std::string buildMjcf(const Model& model) {
  std::string xml = "<mujoco model=\"" + model.name + "\">\n";
  xml += "  <compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n";
  const std::string gravity =
      model.kind == ModelKind::kPendulum   ? "0 " + formatNumber(-kGravity) + " 0"
      : model.kind == ModelKind::kHeavyTop ? "0 0 " + formatNumber(-kGravity)
                                           : "0 0 0";
  xml += "  <option gravity=\"" + gravity + "\">\n";
  xml += "    <flag contact=\"disable\"/>\n  </option>\n  <worldbody>\n";
  switch (model.kind) {
    case ModelKind::kPendulum: {
      // Nested link bodies; each child frame sits at its parent's particle.
      const std::string point = formatNumber(kPointMassInertia);
      std::string indent = "    ";
      for (int k = 1; k <= model.links; ++k) {
        const std::string offset = k == 1 ? "0 0 0" : "0 " + formatNumber(-kPendulumLength) + " 0";
        xml += indent + "<body name=\"link" + std::to_string(k) + "\" pos=\"" + offset + "\">\n";
        xml += indent + "  <joint name=\"q" + std::to_string(k) +
               "\" type=\"hinge\" axis=\"0 0 1\" pos=\"0 0 0\"/>\n";
        xml += indent + "  <inertial pos=\"0 " + formatNumber(-kPendulumLength) + " 0\" mass=\"" +
               formatNumber(kPendulumMass) + "\" diaginertia=\"" + point + " " + point + " " +
               point + "\"/>\n";
        indent += "  ";
      }
      for (int k = model.links; k >= 1; --k) {
        indent.resize(indent.size() - 2);
        xml += indent + "</body>\n";
      }
      break;
    }
    case ModelKind::kHeavyTop:
      xml += "    <body name=\"top\" pos=\"0 0 0\">\n";
      xml += "      <joint name=\"ball\" type=\"ball\" pos=\"0 0 0\"/>\n";
      xml += "      <inertial pos=\"0 0 " + formatNumber(kTopL) + "\" mass=\"" +
             formatNumber(kTopMass) + "\" diaginertia=\"" + formatNumber(kTopA) + " " +
             formatNumber(kTopA) + " " + formatNumber(kTopC) + "\"/>\n";
      xml += "    </body>\n";
      break;
    case ModelKind::kTorqueFree:
      xml += "    <body name=\"body\" pos=\"0 0 0\">\n";
      xml += "      <joint name=\"free\" type=\"free\"/>\n";
      xml += "      <inertial pos=\"0 0 0\" mass=\"" + formatNumber(kFreeMass) +
             "\" diaginertia=\"" + formatNumber(kFreeInertia[0]) + " " +
             formatNumber(kFreeInertia[1]) + " " + formatNumber(kFreeInertia[2]) + "\"/>\n";
      xml += "    </body>\n";
      break;
    case ModelKind::kRobotFile:  // read from its file (loadFile)
      break;
  }
  xml += "  </worldbody>\n</mujoco>\n";
  return xml;
}

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
struct VfsDeleter {
  void operator()(mjVFS* vfs) const {
    mj_deleteVFS(vfs);
    delete vfs;
  }
};

// Compiles MJCF text through MuJoCo's virtual file system (no temporary file).
std::unique_ptr<mjModel, ModelDeleter> loadMjcf(const std::string& xml) {
  const char* fileName = "unidyn_peer_model.xml";
  std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);  // ~2 MB: keep it off the stack
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), fileName, static_cast<int>(xml.size())) != 0) {
    throw std::runtime_error("mj_makeEmptyFileVFS failed");
  }
  const int index = mj_findFileVFS(vfs.get(), fileName);
  if (index < 0) throw std::runtime_error("mj_findFileVFS failed");
  std::memcpy(vfs->filedata[index], xml.data(), xml.size());
  char error[1024] = "";
  std::unique_ptr<mjModel, ModelDeleter> m(mj_loadXML(fileName, vfs.get(), error, sizeof error));
  if (!m) throw std::runtime_error(std::string("mj_loadXML: ") + error + "\n" + xml);
  return m;
}

// A URDF or MJCF file as MuJoCo reads it.
std::unique_ptr<mjModel, ModelDeleter> loadFile(const std::string& path) {
  char error[1024] = "";
  std::unique_ptr<mjModel, ModelDeleter> m(mj_loadXML(path.c_str(), nullptr, error, sizeof error));
  if (!m) throw std::runtime_error("mj_loadXML " + path + ": " + error);
  return m;
}

class MujocoBackend final : public Backend {
 public:
  explicit MujocoBackend(const Model& model)
      : model_(model),
        m_(model.kind == ModelKind::kRobotFile ? loadFile(model.name) : loadMjcf(buildMjcf(model))),
        d_(mj_makeData(m_.get())) {
    if (!d_) throw std::runtime_error("mj_makeData failed");
    // a robot file: its (qpos, qvel), no contact (as unidyn reads it)
    if (model.kind == ModelKind::kRobotFile) {
      m_->opt.disableflags |= mjDSBL_CONTACT;
      model_.links = m_->nv;
      return;
    }
    const int expectedNv = model.kind == ModelKind::kPendulum   ? model.links
                           : model.kind == ModelKind::kHeavyTop ? 3
                                                                : 6;
    if (m_->nv != expectedNv) throw std::runtime_error("unexpected number of dofs");
  }

  std::vector<double> rhs(const std::vector<double>& state) override {
    setEnergy(false);
    setState(state);
    mj_forward(m_.get(), d_.get());
    const int offset = model_.kind == ModelKind::kTorqueFree ? 3 : 0;
    const auto n = static_cast<int>(model_.accelerationSize());
    return std::vector<double>(d_->qacc + offset, d_->qacc + offset + n);
  }

  // mj_forward repeated on the first state (it recomputes every stage from qpos/qvel).
  double nsPerEval(const std::vector<double>& state, double minSeconds) override {
    setEnergy(false);
    setState(state);
    mjModel* m = m_.get();
    mjData* d = d_.get();
    return timeEvaluations([m, d] { mj_forward(m, d); }, minSeconds);
  }

  // Fixed-step mj_step with opt.integrator = RK4 or Euler (semi-implicit) and timestep = --dt;
  // when --t-end is not a whole number of steps, one last shorter step lands on it.
  // Pass 1 checks the energy after every step: mj_step, then mj_forward to bring the derived
  // quantities (and data->energy) up to the new state, then mj_energyPos/mj_energyVel. The extra
  // mj_forward changes qpos/qvel at most by renormalising quaternions (a rounding-level change), so
  // pass 2, timed, runs the same steps bare with the energy flag off; the final state is taken
  // from it.
  SimulateResult simulate(const std::vector<double>& initial,
                          const SimulateOptions& options) override {
    if (!options.dt) throw UsageError("peer_mujoco simulate needs --dt (fixed step)");
    if (options.accuracy) throw UsageError("peer_mujoco has no error control: drop --accuracy");
    if (options.integrator == "rk4") {
      m_->opt.integrator = mjINT_RK4;
    } else if (options.integrator == "euler") {
      m_->opt.integrator = mjINT_EULER;
    } else {
      throw UsageError("unknown MuJoCo integrator '" + options.integrator + "' (rk4, euler)");
    }
    const double dt = *options.dt;
    const auto fullSteps = static_cast<long long>(std::floor(options.tEnd / dt * (1.0 + 1e-12)));
    const double rest = options.tEnd - static_cast<double>(fullSteps) * dt;
    const bool lastStep = rest > 1e-9 * dt;
    mjModel* m = m_.get();
    mjData* d = d_.get();
    // Runs all the steps, calling afterStep() after each.
    const auto integrate = [&](auto&& afterStep) {
      m->opt.timestep = dt;
      for (long long i = 0; i < fullSteps; ++i) {
        mj_step(m, d);
        afterStep();
      }
      if (lastStep) {
        m->opt.timestep = rest;
        mj_step(m, d);
        afterStep();
        m->opt.timestep = dt;
      }
    };

    // Pass 1: energy after every step.
    setEnergy(true);
    reset(initial);
    mj_forward(m, d);
    EnergyMonitor monitor(energy());
    integrate([&] {
      mj_forward(m, d);
      monitor.observe(energy());
    });
    const std::vector<double> checkedFinal = state();

    // Pass 2: the integration alone, timed.
    setEnergy(false);
    reset(initial);
    const Stopwatch stopwatch;
    integrate([] {});
    const double wall = stopwatch.seconds();

    SimulateResult result;
    result.wallSeconds = wall;
    result.steps = fullSteps + (lastStep ? 1 : 0);
    result.maxRelativeEnergyError = monitor.maxRelativeError();
    result.initialEnergy = monitor.initial();
    result.finalState = state();
    // The extra mj_forward renormalises quaternions in place, so the two passes may differ by
    // rounding; anything larger would mean the energy was checked on another trajectory.
    for (std::size_t i = 0; i < checkedFinal.size(); ++i) {
      if (!(std::abs(result.finalState[i] - checkedFinal[i]) <=
            1e-9 * std::max(1.0, std::abs(checkedFinal[i])))) {
        std::fprintf(stderr, "peer_mujoco: warning: timed pass ended in a different state\n");
        break;
      }
    }
    return result;
  }

 private:
  void setEnergy(bool enabled) {
    if (enabled) {
      m_->opt.enableflags |= mjENBL_ENERGY;
    } else {
      m_->opt.enableflags &= ~mjENBL_ENERGY;
    }
  }

  void reset(const std::vector<double>& state) {
    mj_resetData(m_.get(), d_.get());
    setState(state);
  }

  // Peer state → qpos/qvel.
  void setState(const std::vector<double>& x) {
    mjtNum* qpos = d_->qpos;
    mjtNum* qvel = d_->qvel;
    switch (model_.kind) {
      case ModelKind::kRobotFile:
        if (x.size() != static_cast<std::size_t>(m_->nq + m_->nv)) {
          throw UsageError("expected " + std::to_string(m_->nq + m_->nv) +
                           " numbers (qpos, qvel) for " + model_.name);
        }
        std::copy(x.begin(), x.begin() + m_->nq, qpos);
        std::copy(x.begin() + m_->nq, x.end(), qvel);
        break;
      case ModelKind::kPendulum:
        for (int k = 0; k < model_.links; ++k) {
          qpos[k] = x[k];
          qvel[k] = x[model_.links + k];
        }
        break;
      case ModelKind::kHeavyTop:
        for (int i = 0; i < 4; ++i) qpos[i] = x[i];
        for (int i = 0; i < 3; ++i) qvel[i] = x[4 + i];
        break;
      case ModelKind::kTorqueFree:
        for (int i = 0; i < 3; ++i) qpos[i] = 0.0;  // centre at rest at O
        for (int i = 0; i < 4; ++i) qpos[3 + i] = x[i];
        for (int i = 0; i < 3; ++i) qvel[i] = 0.0;
        for (int i = 0; i < 3; ++i) qvel[3 + i] = x[4 + i];
        break;
    }
  }

  // qpos/qvel → peer state.
  std::vector<double> state() const {
    const mjtNum* qpos = d_->qpos;
    const mjtNum* qvel = d_->qvel;
    switch (model_.kind) {
      case ModelKind::kPendulum: {
        std::vector<double> x(qpos, qpos + model_.links);
        x.insert(x.end(), qvel, qvel + model_.links);
        return x;
      }
      case ModelKind::kRobotFile: {
        std::vector<double> x(qpos, qpos + m_->nq);
        x.insert(x.end(), qvel, qvel + m_->nv);
        return x;
      }
      case ModelKind::kHeavyTop:
        return {qpos[0], qpos[1], qpos[2], qpos[3], qvel[0], qvel[1], qvel[2]};
      case ModelKind::kTorqueFree:
        return {qpos[3], qpos[4], qpos[5], qpos[6], qvel[3], qvel[4], qvel[5]};
    }
    return {};
  }

  // Potential + kinetic energy; the derived quantities must be current (after mj_forward).
  double energy() {
    mj_energyPos(m_.get(), d_.get());
    mj_energyVel(m_.get(), d_.get());
    return d_->energy[0] + d_->energy[1];
  }

  Model model_;
  std::unique_ptr<mjModel, ModelDeleter> m_;
  std::unique_ptr<mjData, DataDeleter> d_;
};

std::unique_ptr<Backend> makeMujoco(const Model& model) {
  return std::make_unique<MujocoBackend>(model);
}

}  // namespace
}  // namespace unidyn::peers

int main(int argc, char** argv) {
  return unidyn::peers::peerMain(argc, argv, "rk4, euler (fixed step --dt)",
                                 unidyn::peers::makeMujoco);
}
