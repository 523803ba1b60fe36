// The reference the wave-speed bounds are tested against: the largest eigenvalue of
// the numerical acoustic tensor over the coordinate axes and random directions.
#pragma once

#include "support/finite_differences.hpp"
#include "support/random_tensors.hpp"

#include <algorithm>
#include <cmath>

namespace rkpm::materials::testing {

// sqrt(max over N of lambda_max(Q(N)) / rho0), Q from differences of P.
template <class Stress>
double numerical_wave_speed(const Stress& first_piola, const Mat3& F, Rng& rng, int directions, double rho0) {
  double largest = 0.0;
  for (int i = 0; i < directions + 3; ++i) {
    const Vec3 N = i < 3 ? Vec3(Vec3::Unit(i)) : random_unit_vector(rng);
    largest = std::max(largest, largest_eigenvalue_symmetrised(acoustic_tensor(first_piola, F, N, 1e-4)));
  }
  return std::sqrt(largest / rho0);
}

}  // namespace rkpm::materials::testing
