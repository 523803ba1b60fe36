// Everything a simulation advances: the bodies, the physics terms the scene
// declared, and the clock. A term that the scene does not declare is never built.
#pragma once

#include "rkpm/sim/body.hpp"
#include "rkpm/sim/state_record.hpp"

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace rkpm::io {
class Json;
}

namespace rkpm::sim {

struct World;

// A physics term beyond each body's own material: loads, constraints, contact,
// surface tension. One virtual call per term per step, never per particle.
class Term {
 public:
  virtual ~Term() = default;
  virtual std::string name() const = 0;
  // Adds this term's forces to Body::force at the current positions.
  virtual void add_forces(World& world) = 0;
  // Conservative terms store energy (interface, constraint); the others do work,
  // reported as power at the current velocities.
  virtual double stored_energy(const World&) const { return 0.0; }
  virtual double power(const World&) const { return 0.0; }
  // Largest stable time step this term allows (stiff contact, etc.).
  virtual double stable_dt(const World&) const { return std::numeric_limits<double>::infinity(); }
  // Relaxation only, where the masses are free (contact_mass_scaling): raises the
  // inertia of the particles this term stiffens until its stable_dt reaches about `dt`;
  // the velocities stay as they are. A term without a stiffness of its own leaves the
  // inertia alone.
  virtual void scale_inertia_to(World&, double /*dt*/) {}
  // The term runs on more than one rank (its forces at the owned particles, its energy,
  // power and limits reduced over the ranks). A scene with a term that does not is
  // refused on more than one rank with a message naming it.
  virtual bool distributed() const { return false; }
  // Empty while the present state is one the term can act on; otherwise what went
  // wrong, for the user (contact: one body has passed through the other's surface).
  // Called after every step on every rank, with the same answer on each; a non-empty
  // one stops the run as unstable (exit 3) and keeps the last good frame. A term should
  // look only when something can have changed (contact: at each rebuild of its pairs).
  virtual std::string diagnose(const World&) { return {}; }
  // Adds the term's own metrics to the run summary.
  virtual void report(const World&, io::Json&) const {}
  // Per-particle fields the term shows in the output frames for `body`, by name, as
  // views of its own arrays at its last force evaluation (contact: each particle's
  // contact force); none by default. A distributed body's frame reads the owned
  // particles' values.
  virtual std::vector<materials::OutputField> output_fields(const Body&) const { return {}; }
  // Columns the term adds to history.csv: their names, and their values at the present
  // state as text, each preceded by a comma (",0.98,12.5"). None by default.
  virtual std::vector<std::string> history_columns() const { return {}; }
  virtual std::string history_values(const World&) const { return {}; }
  // Checkpoint state beyond the bodies, as named fields (none for stateless terms);
  // load_state reads them back by name (StateRecord throws on a missing or mis-sized one).
  virtual void save_state(StateRecord&) const {}
  virtual void load_state(const StateRecord&) {}
};

struct World {
  // The ranks the bodies are distributed over (one rank: the whole world here).
  const par::Comm* comm = &par::Comm::self();
  std::vector<std::unique_ptr<Body>> bodies;
  std::vector<std::unique_ptr<Term>> terms;
  double time = 0.0;
  std::int64_t step = 0;
  // Notes for the user found while building (the scene is valid, but a choice in it
  // has a consequence worth knowing); the run prints them as warnings.
  std::vector<std::string> setup_warnings;

  std::size_t particle_count() const {
    std::size_t n = 0;
    for (const auto& b : bodies) n += b->size();
    return n;
  }
  Body* find_body(const std::string& name) const {
    for (const auto& b : bodies)
      if (b->name == name) return b.get();
    return nullptr;
  }
};

// Internal forces of every body, then every term's forces.
void compute_forces(World& world);

// Kinetic energy sum_I m_I |v_I|^2 / 2 of every body [J], summed over the ranks.
// Convention: a function of the World (and every Term method) returns the value of the
// whole run on every rank; a function of one Body returns this rank's share.
double kinetic_energy(const World& world);

}  // namespace rkpm::sim
