// The Python module rkpm._rkpm (docs/guide/python.md): exceptions, the parameter
// registry as data, and Simulation with its fields as NumPy arrays.
#include "arrays.hpp"
#include "simulation.hpp"

#include "rkpm/par/comm.hpp"
#include "rkpm/scene/param_registry.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/body_state.hpp"

#include <pybind11/stl.h>

#include <limits>

namespace py = pybind11;
using rkpm::python::Simulation;

namespace {

// Every key of every table: section, variant, key, type, unit, default, range, help.
py::list parameter_registry() {
  py::list rows;
  for (const auto& table : rkpm::scene::ParamRegistry::instance().tables()) {
    for (const auto& spec : table.specs) {
      py::dict row;
      row["section"] = table.section;
      row["variant"] = table.selector_value.empty() ? py::object(py::none()) : py::str(table.selector_value);
      row["key"] = spec.name;
      row["type"] = rkpm::scene::type_name(spec.type);
      row["unit"] = spec.unit;
      row["default"] = spec.default_text();
      row["range"] = spec.range_text();
      row["choices"] = spec.choices;
      row["help"] = spec.help_text;
      rows.append(row);
    }
  }
  return rows;
}

// A body's field as an array: a read-only view where the state stores it, a copy of
// what the frames compute.
template <class Get>
auto view(Get get) {
  return [get](Simulation& s, const std::string& body) {
    const rkpm::sim::Body& b = s.body(body);  // first: builds the world the keeper holds
    return get(s, b, s.world_keeper());
  };
}

}  // namespace

PYBIND11_MODULE(_rkpm, m) {
  m.doc() = "rkpm: a reproducing-kernel particle simulator for cell mechanics (the C++ core)";

  // SceneError: a scene file or text that does not validate (file, line, key, value and
  // what was expected in the message). SetupError: one that validated but cannot be
  // built or run (a mesh the importer refuses, a support too small). Unstable: a run
  // that blew up, with the diagnosis.
  static py::exception<rkpm::scene::SceneError> scene_error(m, "SceneError", PyExc_ValueError);
  py::exception<std::exception>(m, "SetupError", PyExc_RuntimeError);
  py::exception<std::exception>(m, "Unstable", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const rkpm::scene::SceneError& e) {
      PyErr_SetString(scene_error.ptr(), e.what());
    }
  });

  m.def("_launched_by_mpi", &rkpm::par::Session::launched_by_mpi,
        "Whether an MPI launcher (mpirun, srun) started this process.");
  m.def("_join_mpi", &rkpm::par::Session::join_running_mpi,
        "Makes the MPI that mpi4py initialised rkpm's world: simulations then run on every rank.");
  m.def("params", &parameter_registry,
        "The parameter registry: a list of dicts (section, variant, key, type, unit, default, range, choices, help), "
        "the tables `rkpm params` prints.");

  py::class_<Simulation>(m, "Simulation", "A scene, and once it has run or stepped, its state.")
      .def_static("from_file", &Simulation::from_file, py::arg("path"), py::arg("threads") = 0,
                  "Loads and validates a scene file (SceneError if it does not validate). threads: OpenMP threads "
                  "for this simulation's work, 0 for OpenMP's default.")
      .def_static("from_string", &Simulation::from_string, py::arg("text"), py::arg("name") = "scene.toml",
                  py::arg("threads") = 0, "A scene from TOML text; `name` names it in messages.")
      .def_property_readonly("name", [](const Simulation& s) { return s.scene().scene.text("name"); })
      .def_property_readonly("bodies", &Simulation::body_names, "The bodies' names in scene order.")
      .def("run", &Simulation::run, py::arg("out") = py::none(), py::arg("progress") = py::none(),
           py::arg("max_steps") = 0,
           "Runs the scene as `rkpm run` does, writing frames, history.csv, checkpoints and summary.json into `out` "
           "(default out/<scene name>). progress(step, time) is called after every step; Ctrl-C or an exception it "
           "raises stops the run cleanly and is raised again. max_steps > 0 stops after that many steps. Returns the "
           "exit code of `rkpm run` (0 done, 4 stopped early); raises SetupError or Unstable.")
      .def("step", &Simulation::step, py::arg("n") = 1, py::arg("progress") = py::none(),
           "Advances the state in memory by n steps (without the scene's nested levels, without output).")
      .def("relax", &Simulation::relax, py::arg("max_steps") = 1000000, py::arg("progress") = py::none(),
           "Steps a relax-mode scene until its criteria hold or max_steps more steps; returns whether they hold.")
      .def("summary", &Simulation::summary, "summary.json of the last run() as a dict.")
      .def("energy", &Simulation::energy, "The energy ledger of the present state as a dict.")
      .def("shape", &Simulation::shape, py::arg("body"),
           "The red-blood-cell shape report of a shell body in the present state (`rkpm shape`): the summary's "
           "\"shape\" entries and \"profile\", a dict of arrays r, thickness, top, bottom, evans_fung [m].")
      .def_property_readonly("time", &Simulation::time, "Simulated time of the present state [s].")
      .def_property_readonly("step_count", &Simulation::steps, "Steps taken to the present state.")
      .def_property_readonly("out_dir", &Simulation::out_dir)
      .def("positions", [](Simulation& s, const std::string& body) {
             return rkpm::python::copied(s.fields(body).position, 3);
           }, py::arg("body"),
           "(n, 3) current physical positions X + u(X), as the frames write them (a copy).")
      .def("displacement", [](Simulation& s, const std::string& body) {
             return rkpm::python::copied(s.fields(body).displacement, 3);
           }, py::arg("body"), "(n, 3) physical displacement u(X_J) (a copy).")
      .def("velocity", [](Simulation& s, const std::string& body) {
             return rkpm::python::copied(s.fields(body).velocity, 3);
           }, py::arg("body"), "(n, 3) physical velocity (a copy).")
      .def("cauchy_stress", [](Simulation& s, const std::string& body) {
             return rkpm::python::copied(s.fields(body).cauchy_stress, 9);
           }, py::arg("body"), "(n, 3, 3) Cauchy stress [Pa] (a copy).")
      .def("von_mises", [](Simulation& s, const std::string& body) {
             return rkpm::python::copied(s.fields(body).von_mises, 1);
           }, py::arg("body"), "(n,) von Mises stress [Pa] (a copy).")
      .def("J", [](Simulation& s, const std::string& body) { return rkpm::python::copied(s.fields(body).J, 1); },
           py::arg("body"), "(n,) det F (a copy).")
      .def("reference_positions", view([](Simulation&, const rkpm::sim::Body& b, py::capsule keep) {
             return rkpm::python::vectors_view(b.cloud.X, keep);
           }), py::arg("body"), "(n, 3) reference positions X (a read-only view).")
      .def("volume", view([](Simulation&, const rkpm::sim::Body& b, py::capsule keep) {
             return rkpm::python::scalars_view(b.cloud.volume, keep);
           }), py::arg("body"), "(n,) nodal integration volumes (a read-only view).")
      .def("deformation_gradient", view([](Simulation&, const rkpm::sim::Body& b, py::capsule keep) {
             return rkpm::python::matrices_view(b.F, keep);
           }), py::arg("body"), "(n, 3, 3) deformation gradient F of the last force evaluation (a read-only view).")
      .def("material_field",
           [](Simulation& s, const std::string& body, const std::string& name) -> py::object {
             const rkpm::sim::Body& b = s.body(body);
             for (const auto& f : rkpm::sim::material_output_fields(b))
               if (f.name == name)
                 return rkpm::python::field_view(f.values, b.size(), f.components, s.world_keeper());
             return py::none();
           },
           py::arg("body"), py::arg("name"),
           "(n, components) per-particle state a body's material declares under `name` (the LCE's "
           "\"director\"; a read-only view), None when its material has no such field.")
      .def("material_field_names",
           [](Simulation& s, const std::string& body) {
             std::vector<std::string> names;
             for (const auto& f : rkpm::sim::material_output_fields(s.body(body))) names.push_back(f.name);
             return names;
           },
           py::arg("body"), "Names of the per-particle state fields the body's material declares.");
}
