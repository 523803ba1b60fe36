// Shared material choices for the liquid-crystal elastomer tests.
#pragma once

#include "materials/lce/liquid_crystal_elastomer.hpp"

namespace rkpm::materials::testing {

// Nondimensional LCE (mu = 1) with a Frank term as large as the elastic one for
// director gradients of order 1, so the Frank stress is really exercised.
inline LiquidCrystalElastomer dimensionless_lce(double s) {
  LiquidCrystalElastomer m;
  m.mu = 1.0;
  m.K = 3.0;
  m.s = s;
  m.kappa = 0.5;
  m.zeta = 0.3;
  m.mobility = 1.0;
  return m;
}

}  // namespace rkpm::materials::testing
