// MuJoCo peer: the pendulum chain as MJCF, mj_forward timing, and the double pendulum
// stepped with mj_step. See peer_mujoco.hpp for the frames and the angle map.
#include "bench/peer_mujoco.hpp"

#include <mujoco/mujoco.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <system_error>
#include <vector>

#include "bench/timing.hpp"
#include "core/error.hpp"

namespace linkage::bench {
namespace {

/// Shortest text that reads back as the same double, independent of the locale.
std::string number(double x) {
  std::array<char, 32> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x);
  if (ec != std::errc()) throw Error::failure("cannot format a number for the MJCF");
  return {buffer.data(), end};
}

/// qpos and qvel of a chain from absolute angles and rates: each hinge holds its link's
/// angle relative to the parent link.
void set_absolute(const mjModel& m, mjData& d, const std::vector<double>& theta, const std::vector<double>& omega) {
  double previous_theta = 0, previous_omega = 0;
  for (int k = 0; k < m.nq; ++k) {
    const auto i = static_cast<std::size_t>(k);
    d.qpos[k] = theta[i] - previous_theta;
    d.qvel[k] = omega[i] - previous_omega;
    previous_theta = theta[i];
    previous_omega = omega[i];
  }
}

struct Rod {
  double length = 0, mass = 0;
};

void check_positive(const char* setting, double value, const char* unit) {
  if (!(value > 0) || !std::isfinite(value))
    throw Error::invalid(setting, number(value) + " " + unit + " is out of range; valid: finite, > 0");
}

/// The MJCF of rods hinged in series from a ground pin (see pendulum_chain_mjcf).
std::string chain_mjcf(const std::vector<Rod>& rods, double g) {
  if (!std::isfinite(g)) throw Error::invalid("g", number(g) + " m/s^2 is out of range; valid: finite");
  std::string xml = "<mujoco model=\"pendulum_chain_" + std::to_string(rods.size()) + "\">\n";
  // Explicit inertials only: the geoms are for looking at the model.
  xml += "  <compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n";
  xml += "  <option gravity=\"0 " + number(-g) + " 0\">\n    <flag contact=\"disable\"/>\n  </option>\n";
  xml += "  <worldbody>\n";
  std::string indent = "    ";
  double parent_length = 0;
  for (std::size_t k = 0; k < rods.size(); ++k) {
    const Rod& rod = rods[k];
    check_positive("length", rod.length, "m");
    check_positive("mass", rod.mass, "kg");
    const std::string L = number(rod.length);
    const double centre_inertia = rod.mass * rod.length * rod.length / 12;
    // A slender rod's inertia about its own axis (x) is zero; MuJoCo wants every entry
    // positive with A + B >= C, which (tiny, I, I) meets. x is no degree of freedom.
    const std::string inertia =
        number(centre_inertia * 1e-6) + " " + number(centre_inertia) + " " + number(centre_inertia);
    xml += indent + "<body name=\"link" + std::to_string(k + 1) + "\" pos=\"" + number(parent_length) + " 0 0\">\n";
    indent += "  ";
    xml += indent + "<joint name=\"q" + std::to_string(k + 1) + "\" type=\"hinge\" pos=\"0 0 0\" axis=\"0 0 1\"/>\n";
    xml += indent + "<inertial pos=\"" + number(rod.length / 2) + " 0 0\" mass=\"" + number(rod.mass) +
           "\" diaginertia=\"" + inertia + "\"/>\n";
    xml += indent + "<geom type=\"capsule\" fromto=\"0 0 0 " + L + " 0 0\" size=\"" + number(rod.length / 50) +
           "\" contype=\"0\" conaffinity=\"0\"/>\n";
    parent_length = rod.length;
  }
  for (std::size_t k = 0; k < rods.size(); ++k) {
    indent.resize(indent.size() - 2);
    xml += indent + "</body>\n";
  }
  xml += "  </worldbody>\n</mujoco>\n";
  return xml;
}

}  // namespace

std::string pendulum_chain_mjcf(const ChainSpec& spec) {
  if (spec.links < 1) throw Error::invalid("links", std::to_string(spec.links) + " is out of range; valid: 1 or more");
  return chain_mjcf(std::vector<Rod>(static_cast<std::size_t>(spec.links), Rod{spec.length, spec.mass}), spec.g);
}

std::string double_pendulum_mjcf(const DoublePendulumSpec& spec) {
  return chain_mjcf({{spec.L1, spec.m1}, {spec.L2, spec.m2}}, spec.g);
}

void MujocoModelDeleter::operator()(mjModel_* m) const noexcept { mj_deleteModel(m); }
void MujocoDataDeleter::operator()(mjData_* d) const noexcept { mj_deleteData(d); }

MujocoModel load_mjcf(const std::string& xml) {
  // mjVFS holds 2000 fixed-size file names (about 2 MB): too big for the stack.
  struct VfsDeleter {
    void operator()(mjVFS* v) const noexcept {
      mj_deleteVFS(v);
      delete v;
    }
  };
  const std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  const char* name = "linkage_model.xml";
  // A trailing NUL: TinyXML may read one past the buffer's end.
  const auto size = static_cast<int>(xml.size() + 1);
  if (mj_makeEmptyFileVFS(vfs.get(), name, size) != 0) throw Error::failure("MuJoCo: cannot add the MJCF to its VFS");
  const int file = mj_findFileVFS(vfs.get(), name);
  if (file < 0) throw Error::failure("MuJoCo: the MJCF is missing from its VFS");
  std::memcpy(vfs->filedata[file], xml.c_str(), xml.size() + 1);

  std::array<char, 1024> error{};
  MujocoModel model(mj_loadXML(name, vfs.get(), error.data(), static_cast<int>(error.size())));
  if (!model) {
    std::string message(error.data());
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
    for (char& c : message)
      if (c == '\n') c = ' ';
    throw Error::failure("MuJoCo rejected the model: " + (message.empty() ? std::string("no reason given") : message));
  }
  return model;
}

MujocoData make_data(const mjModel_& model) {
  MujocoData data(mj_makeData(&model));
  if (!data) throw Error::failure("MuJoCo: mj_makeData failed");
  return data;
}

double mujoco_forward_ns(int links, double seconds_budget) {
  const MujocoModel model = load_mjcf(pendulum_chain_mjcf({.links = links}));
  const MujocoData data = make_data(*model);
  // A generic state, the same every run: a folded chain, not the symmetric rest pose.
  std::mt19937_64 random(20240611);
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi), rate(-3.0, 3.0);
  for (int k = 0; k < model->nq; ++k) data->qpos[k] = angle(random);
  for (int k = 0; k < model->nv; ++k) data->qvel[k] = rate(random);

  mjModel* m = model.get();
  mjData* d = data.get();
  constexpr int batches = 7;
  // nanoseconds_per_call doubles the batch size up to min_batch: about
  // (batches + 2) min_batch in all, plus the warm-up.
  const double min_batch = seconds_budget / (batches + 3);
  const double warm_start = thread_cpu_seconds();
  while (thread_cpu_seconds() - warm_start < min_batch)
    for (int i = 0; i < 64; ++i) mj_forward(m, d);
  return nanoseconds_per_call([&](std::size_t) { mj_forward(m, d); }, min_batch, batches).cpu_ns;
}

MujocoRun mujoco_double_pendulum(const DoublePendulumSpec& spec, int integrator, double dt, double t_end) {
  if (integrator != mjINT_RK4 && integrator != mjINT_EULER)
    throw Error::invalid("integrator", std::to_string(integrator) + " is not supported; valid: mjINT_RK4 (" +
                                           std::to_string(mjINT_RK4) + "), mjINT_EULER (" +
                                           std::to_string(mjINT_EULER) + ")");
  if (!(dt > 0) || !std::isfinite(dt))
    throw Error::invalid("dt", number(dt) + " s is out of range; valid: finite, > 0");
  if (!(t_end >= 0) || !std::isfinite(t_end))
    throw Error::invalid("t_end", number(t_end) + " s is out of range; valid: finite, >= 0");
  const MujocoModel model = load_mjcf(double_pendulum_mjcf(spec));
  const MujocoData data = make_data(*model);
  model->opt.timestep = dt;
  model->opt.integrator = integrator;
  set_absolute(*model, *data, {spec.theta1, spec.theta2}, {spec.omega1, spec.omega2});

  MujocoRun run;
  run.steps = std::lround(t_end / dt);
  mjModel* m = model.get();
  mjData* d = data.get();
  const double start = thread_cpu_seconds();
  for (long i = 0; i < run.steps; ++i) mj_step(m, d);
  run.seconds = thread_cpu_seconds() - start;
  // MuJoCo resets a state that left the finite numbers and only counts a warning.
  for (const int warning : {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC})
    if (d->warning[warning].number > 0)
      throw Error::diverged("MuJoCo: the double pendulum left the finite numbers (t = " + number(d->time) + " s)");
  run.theta1 = d->qpos[0];
  run.theta2 = d->qpos[0] + d->qpos[1];
  run.omega1 = d->qvel[0];
  run.omega2 = d->qvel[0] + d->qvel[1];
  return run;
}

}  // namespace linkage::bench
