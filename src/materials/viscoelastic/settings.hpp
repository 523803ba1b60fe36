// Settings of the viscoelastic model, read from its [body.material] table (params.cpp).
#pragma once

#include "rkpm/scene/settings_table.hpp"

#include <vector>

namespace rkpm::materials::viscoelastic {

struct Settings {
  double mu = 0.0;            // [Pa] long-term (equilibrium) shear modulus
  double lambda = 0.0;        // [Pa] Lame's first parameter of the equilibrium branch
  std::vector<double> beta;   // [-] each Maxwell branch's shear modulus over mu
  std::vector<double> tau;    // [s] each branch's relaxation time
};

const scene::SettingsTable<Settings>& settings_table();

}  // namespace rkpm::materials::viscoelastic
