// The six rigid-body motions c + w x X of a particle cloud, orthonormalised in a
// weighted inner product <u, v> = sum_I m_I u_I . v_I. A pure-traction problem
// determines the displacement only up to such a motion: the stiffness has them as
// its null space (both SCNI and the stabilization reproduce linear fields exactly).
#pragma once

#include "field.hpp"

#include <array>
#include <vector>

namespace rkpm::study {

class RigidModes {
 public:
  RigidModes(const std::vector<Vec3>& X, std::vector<double> weight);

  // v -= (the weighted projection of v onto the rigid motions).
  void remove_from(Field& v) const;

  // The rigid motion closest to v in the weighted norm, evaluated at the particles.
  Field fit(const Field& v) const;

 private:
  double inner(const Field& u, const Field& v) const;
  std::vector<double> weight_;
  std::array<Field, 6> basis_;
};

}  // namespace rkpm::study
