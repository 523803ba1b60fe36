// Deterministic random numbers and random tensors for the material tests.
// The project's SplitMix64: the same numbers on every platform (std:: distributions
// are implementation-defined).
#pragma once

#include "rkpm/common/split_mix64.hpp"
#include "rkpm/common/types.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>

namespace rkpm::materials::testing {

// uniform() in [0, 1), uniform(a, b) in [a, b): the project's generator.
using Rng = SplitMix64;

// Uniform on the unit sphere (rejection from the cube).
inline Vec3 random_unit_vector(Rng& rng) {
  for (;;) {
    const Vec3 v(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    const double n = v.norm();
    if (n > 0.1 && n <= 1.0) return v / n;
  }
}

// Uniform rotation from a unit quaternion drawn uniformly on S^3.
inline Mat3 random_rotation(Rng& rng) {
  for (;;) {
    const Eigen::Vector4d q(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    const double n = q.norm();
    if (n > 0.1 && n <= 1.0) return Eigen::Quaterniond(q[0] / n, q[1] / n, q[2] / n, q[3] / n).toRotationMatrix();
  }
}

// F = R1 diag(l1, l2, l3) R2 (I + g e_a (x) e_b): principal stretches
// log-uniform in [min_stretch, max_stretch] (so J ranges over
// [min^3, max^3]), random rotations, plus a simple shear of amount up to max_shear.
inline Mat3 random_deformation(Rng& rng, double min_stretch, double max_stretch, double max_shear) {
  Vec3 stretches;
  for (int i = 0; i < 3; ++i)
    stretches[i] = std::exp(rng.uniform(std::log(min_stretch), std::log(max_stretch)));
  Mat3 shear = Mat3::Identity();
  const int a = static_cast<int>(rng.next() % 3);
  const int b = (a + 1 + static_cast<int>(rng.next() % 2)) % 3;
  shear(a, b) = rng.uniform(-max_shear, max_shear);
  return random_rotation(rng) * stretches.asDiagonal() * random_rotation(rng) * shear;
}

// A director gradient with entries of order `scale` [1/length].
inline Mat3 random_gradient(Rng& rng, double scale) {
  Mat3 A;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A(i, j) = scale * rng.uniform(-1, 1);
  return A;
}

}  // namespace rkpm::materials::testing
