// Settings of the mooney_rivlin model, read from its [body.material] table (params.cpp).
#pragma once

#include "rkpm/scene/settings_table.hpp"

namespace rkpm::materials::mooney_rivlin {

struct Settings {
  double c1 = 0.0;            // [Pa] Eq. 9
  double c2 = 0.0;            // [Pa] Eq. 9
  double lambda = 0.0;        // [Pa] Eq. 9
  int grade_axis = -1;        // Eq. 18: reference axis the moduli vary along (0, 1, 2); -1 = homogeneous
  double grade_a = 0.0;       // [-] slope a of the grading factor
  double grade_b = 1.0;       // [-] offset b of the grading factor
  double grade_length = 0.0;  // [m] L0; 0 = the body's extent along the axis
};

const scene::SettingsTable<Settings>& settings_table();

}  // namespace rkpm::materials::mooney_rivlin
