// Block-Jacobi preconditioned conjugate gradients for K d = f with K symmetric
// positive semi-definite whose null space is the rigid motions (a pure-traction
// problem). The load is self-equilibrated, so the system is consistent; keeping
// the preconditioned residual orthogonal to the rigid motions keeps every search
// direction in the range of K, where CG converges as for a definite system, and
// the iterate (started at 0) free of rigid motion.
#pragma once

#include "elastic_stiffness.hpp"
#include "field.hpp"
#include "rigid_modes.hpp"

namespace rkpm::study {

struct SolverSettings {
  double relative_tolerance = 1e-10;  // on |f - K d| / |f|, f with its rigid part removed
  int max_iterations = 20000;
};

struct SolverReport {
  int iterations = 0;
  double relative_residual = 0.0;
  bool converged = false;
};

// Solves K d = f; `d` is overwritten. `rigid` uses the Euclidean inner product of d-space.
SolverReport solve_projected_cg(ElasticStiffness& K, const RigidModes& rigid, Field f, Field& d,
                                const SolverSettings& settings);

}  // namespace rkpm::study
