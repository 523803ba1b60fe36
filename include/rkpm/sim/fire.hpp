// FIRE, the fast inertial relaxation engine (Bitzek, Koskinen, Gaehler, Moseler and
// Gumbsch, PRL 97, 170201, 2006): the relaxation mode's velocity control. After each
// velocity Verlet step it looks at the power P = F . v of the whole system:
//  * P > 0 (moving downhill): the velocity is steered toward the force,
//      v <- (1 - alpha) v + alpha |v| F / |F|   (norms over all degrees of freedom),
//    which never lengthens v (|v'| <= |v|, equal when v is parallel to F); after more
//    than N_min such steps in a row the step grows by f_inc up to dt_max and alpha
//    shrinks by f_alpha;
//  * P <= 0 (moving uphill, or at rest): the velocity is set to zero, the step is
//    halved (f_dec) and alpha returns to alpha_start.
// The kinetic energy the mixing or the stop removes is returned for the energy ledger.
#pragma once

#include "rkpm/sim/world.hpp"

#include <cstdint>

namespace rkpm::sim {

struct FireStep {
  double dissipated = 0.0;  // kinetic energy removed from the bodies [J]
  double dt = 0.0;          // the step to take next [s]
};

class Fire {
 public:
  // The constants of Bitzek et al. 2006.
  static constexpr int kMinPositive = 5;          // N_min
  static constexpr double kIncrease = 1.1;        // f_inc
  static constexpr double kDecrease = 0.5;        // f_dec
  static constexpr double kAlphaStart = 0.1;      // alpha_start
  static constexpr double kAlphaShrink = 0.99;    // f_alpha

  Fire() = default;
  // A state restored from a checkpoint.
  Fire(double alpha, std::int64_t positive_steps) : alpha_(alpha), positive_steps_(positive_steps) {}

  // One FIRE update of every body's velocity from its force (Body::v, Body::force),
  // the essential boundary conditions re-imposed after it; `dt` is the step just
  // taken, `dt_max` the ceiling of its growth.
  FireStep update(World& world, double dt, double dt_max);

  double alpha() const { return alpha_; }
  std::int64_t positive_steps() const { return positive_steps_; }  // P > 0 steps in a row

 private:
  double alpha_ = kAlphaStart;
  std::int64_t positive_steps_ = 0;
};

}  // namespace rkpm::sim
