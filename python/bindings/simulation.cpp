#include "simulation.hpp"

#include "arrays.hpp"

#include "rkpm/io/json.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/history.hpp"

#include <omp.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace rkpm::python {
namespace {

// Raised for a scene that validated but cannot be built, and for a run that blew up.
py::object& setup_error() {
  static py::object type = py::module_::import("rkpm._rkpm").attr("SetupError");
  return type;
}
py::object& unstable_error() {
  static py::object type = py::module_::import("rkpm._rkpm").attr("Unstable");
  return type;
}

[[noreturn]] void raise(py::object& type, const std::string& message) {
  PyErr_SetString(type.ptr(), message.c_str());
  throw py::error_already_set();
}

// The last "error: " line of a run's log, without the prefix.
std::string last_error(const std::string& log) {
  std::string found, line;
  std::istringstream in(log);
  while (std::getline(in, line))
    if (line.rfind("error: ", 0) == 0) found = line.substr(7);
  return found.empty() ? log : found;
}

// Calls progress(step, time) with the GIL held and checks for Ctrl-C. A Python error
// (KeyboardInterrupt, or whatever progress raises) is kept to be raised once the C++
// work has ended cleanly; returns false to stop it.
class StepWatch {
 public:
  explicit StepWatch(const py::object& progress) : progress_(progress) {}

  bool operator()(long long step, double time) {
    py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!progress_.is_none()) progress_(step, time);
    } catch (py::error_already_set& e) {
      error_ = std::make_unique<py::error_already_set>(std::move(e));
      return false;
    }
    return true;
  }
  // With the GIL held again.
  void raise_if_stopped() {
    if (error_) {
      auto e = std::move(error_);
      throw std::move(*e);
    }
  }

 private:
  py::object progress_;
  std::unique_ptr<py::error_already_set> error_;
};

}  // namespace

Simulation::Simulation(scene::Scene scene, int threads) : scene_(std::move(scene)), threads_(threads) {
  const int ceiling = 8 * std::max(1, omp_get_num_procs());
  if (threads_ < 0 || threads_ > ceiling)
    throw std::invalid_argument("threads = " + std::to_string(threads_) + ": expected 1 to " +
                                std::to_string(ceiling) + " (8 per core), or 0 for OpenMP's default");
}

Simulation Simulation::from_file(const std::string& path, int threads) {
  return Simulation(scene::load_scene(path), threads);
}

Simulation Simulation::from_string(const std::string& text, const std::string& name, int threads) {
  return Simulation(scene::parse_scene(text, name), threads);
}

void Simulation::use_threads() const {
  if (threads_ > 0) omp_set_num_threads(threads_);
}

py::list Simulation::body_names() const {
  py::list names;
  for (const auto& b : scene_.bodies) names.append(b.name());
  return names;
}

int Simulation::run(const std::optional<std::string>& out, const py::object& progress, long long max_steps) {
  out_dir_ = out ? *out : "out/" + scene_.scene.text("name");
  sim::RunOptions options;
  options.out_dir = out_dir_;
  options.quiet = true;
  options.max_steps_override = max_steps;
  StepWatch watch(progress);
  options.after_step = [&](const sim::World& w, const sim::Integrator&) { return watch(w.step, w.time); };
  sim::RunState state;
  options.keep = &state;
  std::ostringstream log;
  int code = 0;
  {
    py::gil_scoped_release release;
    use_threads();
    code = sim::run_scene(scene_, options, log);
    // Every rank returns once the root has written summary.json.
    par::Comm::world().barrier();
  }
  if (state.world) {
    integrator_ = std::move(state.integrator);
    world_ = std::move(state.world);
  }
  watch.raise_if_stopped();
  if (code == sim::kBadInput || code == sim::kInternalError) raise(setup_error(), last_error(log.str()));
  if (code == sim::kUnstable) raise(unstable_error(), last_error(log.str()));
  if (code == sim::kOutputFailed) throw std::runtime_error(last_error(log.str()));
  return code;
}

void Simulation::ensure_world() {
  if (world_) return;
  std::string error;
  {
    py::gil_scoped_release release;
    use_threads();
    try {
      world_ = sim::build_world(scene_);
      integrator_ = std::make_shared<sim::Integrator>(*world_, sim::integrator_settings(scene_));
      integrator_->initialize();
    } catch (const std::exception& e) {  // SetupError, a mesh the importer refuses, a blow-up at the start
      error = e.what();
      integrator_.reset();
      world_.reset();
    }
  }
  if (!error.empty()) raise(setup_error(), error);
}

void Simulation::advance(long long n, bool until_converged, const py::object& progress) {
  ensure_world();
  StepWatch watch(progress);
  std::string blew_up;
  {
    py::gil_scoped_release release;
    use_threads();
    try {
      for (long long k = 0; k < n && !(until_converged && converged()); ++k) {
        integrator_->step();
        if (!watch(world_->step, world_->time)) break;
      }
    } catch (const sim::BlowUp& e) {
      blew_up = e.what();
    }
  }
  watch.raise_if_stopped();
  if (!blew_up.empty()) raise(unstable_error(), blew_up);
}

bool Simulation::converged() const { return world_->step > 0 && integrator_->converged(); }

void Simulation::step(long long n, const py::object& progress) { advance(n, false, progress); }

bool Simulation::relax(long long max_steps, const py::object& progress) {
  if (scene_.integrator.choice("mode") != "relax")
    throw std::invalid_argument("relax(): the scene's [integrator] mode is \"" + scene_.integrator.choice("mode") +
                                "\"; expected \"relax\" (use step() or run())");
  advance(max_steps, true, progress);
  return converged();
}

py::dict Simulation::summary() const {
  if (out_dir_.empty()) throw std::runtime_error("summary(): the simulation has not run; call run() first");
  std::ifstream in(out_dir_ + "/summary.json");
  if (!in) throw std::runtime_error("summary(): no summary.json in " + out_dir_);
  std::stringstream text;
  text << in.rdbuf();
  return py::module_::import("json").attr("loads")(text.str());
}

py::dict Simulation::energy() {
  ensure_world();
  const sim::EnergyLedger& e = integrator_->measure_energy();
  py::dict d;
  d["kinetic"] = e.kinetic;
  d["strain"] = e.strain;
  d["interface"] = e.interface;
  d["external"] = e.external;
  d["active"] = e.active;
  d["state"] = e.state;
  d["dissipated"] = e.dissipated;
  d["initial"] = e.initial;
  d["relative_error"] = e.relative_error();
  return d;
}

py::dict Simulation::shape(const std::string& body_name) {
  const sim::Body& b = body(body_name);
  if (b.cloud.surface_bit("outer") == 0u)
    throw std::invalid_argument("shape(): body '" + body_name + "' has no surface named \"outer\" (a shell cloud has one)");
  sim::ShapeReport s;
  {
    py::gil_scoped_release release;
    s = sim::final_shape(b, *world_->comm);
  }
  // The summary's entries, from the one function that writes them.
  py::dict d = py::module_::import("json").attr("loads")(sim::shape_entries(s).dump());
  py::dict profile;
  profile["r"] = copied(std::move(s.r), 1);
  profile["thickness"] = copied(std::move(s.thickness), 1);
  profile["top"] = copied(std::move(s.top), 1);
  profile["bottom"] = copied(std::move(s.bottom), 1);
  profile["evans_fung"] = copied(std::move(s.evans_fung), 1);
  d["profile"] = profile;
  return d;
}

double Simulation::time() {
  ensure_world();
  return world_->time;
}

long long Simulation::steps() {
  ensure_world();
  return world_->step;
}

const sim::Body& Simulation::body(const std::string& name) {
  ensure_world();
  const sim::Body* b = world_->find_body(name);
  if (!b) {
    std::string known;
    for (const auto& each : world_->bodies) known += (known.empty() ? "" : ", ") + each->name;
    throw py::key_error("no body named '" + name + "'; the scene has " + known);
  }
  return *b;
}

sim::BodyFields Simulation::fields(const std::string& name) {
  const sim::Body& b = body(name);
  py::gil_scoped_release release;
  return sim::body_fields(b, *world_->comm);
}

py::capsule Simulation::world_keeper() const {
  auto* keep = new std::shared_ptr<sim::World>(world_);
  return py::capsule(keep, [](void* p) { delete static_cast<std::shared_ptr<sim::World>*>(p); });
}

}  // namespace rkpm::python
