// FIRE, the fast inertial relaxation engine: the relaxation mode's velocity control.
// After each velocity Verlet step it looks at the power P = F . v of the whole system:
//  * P > 0 (moving downhill): the velocity is steered toward the force,
//      v <- (1 - alpha) v + alpha |v| F / |F|   (norms over all degrees of freedom),
//    which never lengthens v (|v'| <= |v|, equal when v is parallel to F); after more
//    than n_delay such steps in a row the step grows by f_inc up to dt_max and alpha
//    shrinks by f_alpha;
//  * P <= 0 (moving uphill, or at rest): the velocity is set to zero, the step shrinks
//    by f_dec and alpha returns to alpha_start.
// Two parameter sets (FireParameters):
//  * Bitzek, Koskinen, Gaehler, Moseler and Gumbsch, PRL 97, 170201 (2006): the original;
//  * FIRE 2.0, Guenole, Noehring, Vaid, Houlle, Xie, Prakash and Bitzek, Comput. Mater.
//    Sci. 175, 109584 (2020), with the defaults LAMMPS's min_style fire uses: a longer
//    delay before the step grows, a larger alpha_start, a floor on the step, no shrink of
//    the step during the first n_delay steps of a run, and the "inertia correction": an
//    uphill step first moves the positions back by dt v / 2, which the caller does
//    (FireStep::step_back; Integrator::step_back books its energy).
// The kinetic energy the mixing or the stop removes is returned for the energy ledger.
#pragma once

#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <string>

namespace rkpm::sim {

struct FireParameters {
  int n_delay = 5;               // downhill steps in a row before dt grows and alpha shrinks
  double f_inc = 1.1;            // growth of dt
  double f_dec = 0.5;            // shrink of dt on an uphill step
  double alpha_start = 0.1;      // mixing after an uphill step
  double f_alpha = 0.99;         // shrink of alpha
  double dt_min_fraction = 0.0;  // dt never below this fraction of dt_max (0: no floor)
  bool initial_delay = false;    // uphill steps among the first n_delay steps of a run keep dt and alpha
  bool half_step_back = false;   // an uphill step moves the positions back by dt v / 2

  static FireParameters bitzek2006() { return {}; }
  static FireParameters guenole2020() { return {20, 1.1, 0.5, 0.25, 0.99, 0.02, true, true}; }
  // "fire" or "fire2", the scene's relax_method.
  static FireParameters named(const std::string& method);
};

struct FireStep {
  double dissipated = 0.0;  // kinetic energy removed from the bodies [J]
  double dt = 0.0;          // the step to take next [s]
  // Uphill with half_step_back: the velocities are left as they were; the caller moves
  // the positions back by dt v / 2 and then sets every velocity to zero.
  bool step_back = false;
};

// Stops every body: velocities zero, the essential boundary conditions re-imposed (the
// supports keep their prescribed velocities). FIRE's uphill step, and the end of
// FIRE 2.0's step back.
void stop_bodies(World& world);

class Fire {
 public:
  explicit Fire(FireParameters parameters = FireParameters::bitzek2006()) : p_(parameters), alpha_(p_.alpha_start) {}
  // A state restored from a checkpoint.
  Fire(FireParameters parameters, double alpha, std::int64_t positive_steps)
      : p_(parameters), alpha_(alpha), positive_steps_(positive_steps) {}

  // One FIRE update of every body's velocity from its force (Body::v, Body::force),
  // the essential boundary conditions re-imposed after it; `dt` is the step just
  // taken, `dt_max` the ceiling of its growth. World::step counts the run's steps
  // (FireParameters::initial_delay).
  FireStep update(World& world, double dt, double dt_max);

  double alpha() const { return alpha_; }
  std::int64_t positive_steps() const { return positive_steps_; }  // P > 0 steps in a row

 private:
  FireParameters p_;
  double alpha_;
  std::int64_t positive_steps_ = 0;
};

}  // namespace rkpm::sim
