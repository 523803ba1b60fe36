// The director state of one material point, gathered from a body's director field:
// the one place a DirectorPoint (liquid_crystal_elastomer.hpp) is built from the
// per-particle arrays (force pass, energy, stable step, director update).
#pragma once

#include "materials/lce/liquid_crystal_elastomer.hpp"
#include "materials/lce/director_field.hpp"

namespace rkpm::materials::lce {

// h_L, h0_L and the given Grad_X h (the force pass has it at hand, freshly gathered).
inline DirectorPoint director_point(const DirectorField& dir, Index L, const Mat3& grad_h) {
  DirectorPoint p;
  p.h = dir.h[L];
  p.h0 = dir.h0[L];
  p.grad_h = grad_h;
  return p;
}

// h_L, h0_L and Grad_X h as the last force pass stored it (zero without the Frank term).
inline DirectorPoint director_point(const DirectorField& dir, Index L) {
  return director_point(dir, L, dir.frank ? dir.grad_h[L] : Mat3::Zero());
}

}  // namespace rkpm::materials::lce
