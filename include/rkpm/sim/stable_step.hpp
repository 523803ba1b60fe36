// The stable step of the central-difference scheme measured on the discretisation
// itself. Velocity Verlet with lumped masses is stable for dt < 2 / omega_max, omega_max
// the largest natural frequency of M^-1 K (K = -df/dd, the tangent of every force the
// world computes: the bodies' internal forces and every term). The wave-speed estimate
// spacing / c (body.hpp, material_stable_dt) only bounds it from the mesh: with
// smoothed (SCNI) gradients over supports of several spacings the discretisation is
// softer at its shortest wavelengths than a lattice of springs, and on the red-blood-cell
// shell 2 / omega_max is well above spacing / c (docs/verification/relaxation.md gives
// the ratio).
//
// omega_max^2 is the dominant eigenvalue of the mass-weighted tangent
// A = M^-1/2 K M^-1/2, found by power iteration; each product A y is one evaluation of
// every force at d + delta M^-1/2 y (a forward difference of the forces, delta a
// millionth of the shortest spacing), so an estimate costs a few tens of force passes.
#pragma once

#include "rkpm/sim/world.hpp"

namespace rkpm::sim {

struct FrequencyEstimate {
  double omega_max = 0.0;  // [rad/s]; 0 when the iteration found no positive stiffness
  int iterations = 0;      // power iterations, one force evaluation each (two more: the state's own
                           // forces before, and restoring everything they derive from after)
};

// The largest natural frequency of the world linearised at its current state, with
// the integrator's masses (Body::inertia) and the essential boundary conditions
// (the constrained components do not move; the free ones see the transformed forces).
// The iteration starts from the same pseudo-random vector every time, so the estimate
// depends on the state alone, and stops when |A y| changes by less than `tolerance`
// relative between two iterations, or after `max_iterations`. On return every body's
// displacement, positions and Body::force are those it was called with; the fields the
// forces derive from (F, P, the terms' data) are re-evaluated at that displacement.
FrequencyEstimate largest_frequency(World& world, int max_iterations = 60, double tolerance = 1e-3);

}  // namespace rkpm::sim
