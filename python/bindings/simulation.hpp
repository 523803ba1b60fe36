// The Python module's Simulation: a validated scene, and once it has run or stepped,
// its world and integrator (sim::RunState). run() is `rkpm run` itself (the same
// output, bit for bit); step() and relax() drive the integrator in memory.
#pragma once

#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/output.hpp"
#include "rkpm/sim/shape_report.hpp"
#include "rkpm/sim/run.hpp"

#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>

namespace rkpm::python {

namespace py = pybind11;

class Simulation {
 public:
  Simulation(scene::Scene scene, int threads);

  static Simulation from_file(const std::string& path, int threads);
  static Simulation from_string(const std::string& text, const std::string& name, int threads);

  // The scene's name and file, and its bodies' names in scene order.
  const scene::Scene& scene() const { return scene_; }
  py::list body_names() const;

  // `rkpm run` on the scene into `out` (default out/<scene name>); progress(step, time)
  // is called after every step of the main loop, and a KeyboardInterrupt (Ctrl-C) or
  // an exception it raises stops the run cleanly (frame and summary written) and is
  // raised again. Returns the exit code; raises SetupError for a scene that cannot be
  // built and Unstable for a blow-up (after its output is written).
  int run(const std::optional<std::string>& out, const py::object& progress, long long max_steps);
  // n steps of the integrator in memory (building the world at the first call; a
  // scene's nested levels are not run); progress as for run().
  void step(long long n, const py::object& progress);
  // Steps until the relaxation criteria hold or max_steps more steps; returns whether
  // they hold. Only for mode = "relax".
  bool relax(long long max_steps, const py::object& progress);

  // The summary.json of the last run() as a dict.
  py::dict summary() const;
  // Kinetic, stored, interface and external energy, the ledger's terms and its error.
  py::dict energy();
  // The red-blood-cell shape report (`rkpm shape`) of a body's surface named "outer" in
  // the present state: the summary's "shape" entries and the profile as arrays.
  py::dict shape(const std::string& body_name);

  double time();
  long long steps();
  // The state's fields (builds the world at first use).
  const sim::Body& body(const std::string& name);
  sim::BodyFields fields(const std::string& name);
  std::string out_dir() const { return out_dir_; }
  // Keeps the present world alive for as long as an array viewing it lives (a later
  // run() replaces the world; the old views stay valid).
  py::capsule world_keeper() const;

 private:
  void ensure_world();
  // Up to n steps in memory, stopping early once converged() if until_converged.
  void advance(long long n, bool until_converged, const py::object& progress);
  // The relaxation criteria hold (not before the first step).
  bool converged() const;
  void use_threads() const;

  scene::Scene scene_;
  int threads_;
  std::shared_ptr<sim::World> world_;
  std::shared_ptr<sim::Integrator> integrator_;  // refers to *world_
  std::string out_dir_;
};

}  // namespace rkpm::python
