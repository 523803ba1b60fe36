// The director field of an LCE body (seed Eq. 5-8): per-particle state the force pass
// reads (the coupled field of the Frank term) and end_step advances.
#pragma once

#include "rkpm/common/types.hpp"

#include <vector>

namespace rkpm::materials::lce {

struct DirectorField {
  std::vector<Vec3> h;                 // current director per particle (unit)
  std::vector<Vec3> h0;                // reference director per particle (unit)
  std::vector<Mat3> grad_h;            // Grad_X h per integration point (Frank term only)
  std::vector<Mat3> frank_flux;        // dW/d(Grad_X h) per point (Frank term only)
  std::vector<Vec3> frank_divergence;  // Div_X of the flux at particles (Frank term only)
  std::vector<Vec3> rate;              // dh/dt
  std::vector<Mat3> F_start;           // F per point at the start of the step (begin_step)
  std::vector<Vec3> normals;           // scratch: current outward normals of the surface
  bool evolve = true;                  // integrate Eq. 5-7
  bool anchored = true;                // Eq. 8: h = current outward normal on the surface
  bool frank = false;                  // kappa > 0: the gradient terms are built
  // The force pass assembles frank_flux and frank_divergence (a second scatter per row)
  // only while something reads them every step: the director's relaxation (Eq. 5, L > 0)
  // or a director criterion of the relaxation. Otherwise residual() makes them when
  // asked. Grad_X h is always gathered: the Frank stress needs it.
  bool frank_divergence_tracked = true;
};

}  // namespace rkpm::materials::lce
