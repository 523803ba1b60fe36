// Static equilibrium by an inexact Newton method whose linear systems are solved by
// GMRES with the Jacobian applied as a difference of two force evaluations
// (Jacobian-free Newton-Krylov, Knoll & Keyes 2004): the relaxation's `relax_finish =
// "newton_krylov"` (docs/theory/relaxation.md, "The Newton-Krylov finish"). It solves f(d) = 0 for the
// free generalized displacements of every body, f the force after the essential
// conditions' transformation. A material's state is not an unknown of its own: in every
// evaluation the caller carries it from the Newton step's base state to the evaluated
// coordinates (`Hooks::follow`: for the LCE, Eq. 7's co-rotation and Eq. 8's anchoring,
// as a step's motion carries it), so the difference Jacobian includes how it follows.
#pragma once

#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rkpm::sim {

struct NewtonKrylovSettings {
  double force_tol = 1e-8;  // the stop: the integrator's residual measure (max_I |f_I| / (mu V_I^(2/3)))
  int max_newton_steps = 50;
  int max_krylov_iterations = 400;  // per Newton step
  int restart = 60;                 // GMRES's Krylov vectors before a restart
  double perturbation = 1e-7;       // the difference step: the largest perturbed coordinate moves by this
                                    // fraction of the mean particle spacing
};

struct NewtonKrylovReport {
  bool converged = false;
  int newton_steps = 0;
  std::int64_t krylov_iterations = 0;
  std::int64_t force_evaluations = 0;  // made here (the Jacobian products, the line search)
  double residual = 0.0;               // the measure at the end
  std::vector<double> residuals;       // the measure after each accepted Newton step
  std::string stop;                    // why it stopped: "converged", or what failed
};

// What the caller does around each Newton update.
struct NewtonKrylovHooks {
  // The residual measure at the world's present forces (the integrator's).
  std::function<double()> residual;
  // Called at the base state of each Newton step (its forces and F current): the caller
  // holds what `follow` carries the materials' state from.
  std::function<void()> hold;
  // Called in every evaluation after `hold`, with the coordinates set and before their
  // force pass: the caller moves the state from the held base state to them.
  std::function<void()> follow;
  // Called after an accepted update, the world at the new coordinates with their forces
  // and state: the caller books the update in the energy ledger and checks the state.
  // `from` holds each body's coordinates before the update.
  std::function<void(const std::vector<std::vector<Vec3>>& from)> carry;
  // Optional: called after each accepted Newton step with the report so far, so that a
  // long finish shows where it is (a Newton step is many force evaluations, one per GMRES
  // iteration; docs/verification/relaxation.md measures them).
  std::function<void(const NewtonKrylovReport& so_far)> stepped;
};

// Runs on one process only (the caller refuses a distributed world). The world's
// velocities are set to zero; the forces at entry must be those of its coordinates.
NewtonKrylovReport solve_static_equilibrium(World& world, const std::vector<double>& body_shear_modulus,
                                            const NewtonKrylovSettings& settings, const NewtonKrylovHooks& hooks);

}  // namespace rkpm::sim
