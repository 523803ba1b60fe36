// Spatially graded material parameters (seed Eq. 18, the stiffness-gradient
// substrate of the durotaxis example, section 4.3).
//
// The seed scales all three Mooney-Rivlin constants by the same linear factor
// of the reference coordinate:
//   value(X) = base * ( a * (X[axis] - x_min) / L0 + b ),
// with a = 4.0, b = 0.5, axis = y and L0 the length of the substrate along y
// (x_min its lower face). The factor is evaluated once per material point when
// the body is built; the force loop then sees one plain MooneyRivlin per point.
#pragma once

#include "rkpm/common/types.hpp"
#include "materials/mooney_rivlin/mooney_rivlin.hpp"

namespace rkpm::materials {

struct LinearGrading {
  int axis = 1;         // reference axis the parameters vary along: 0 = X, 1 = Y, 2 = Z
  double x_min = 0.0;   // [m] coordinate where the factor equals b
  double length = 1.0;  // [m] L0, the graded extent (length of the substrate along axis)
  double slope = 4.0;   // [-] a in Eq. 18 (seed: 4.0)
  double offset = 0.5;  // [-] b in Eq. 18 (seed: 0.5)

  // Throws std::invalid_argument unless axis is 0..2, length > 0, and the
  // factor is > 0 at both ends of [x_min, x_min + length].
  void validate() const;

  // Dimensionless factor a (X[axis] - x_min) / L0 + b. Outside [x_min, x_min + L0]
  // it extrapolates linearly (a jittered particle may sit slightly outside).
  double factor(const Vec3& X) const { return slope * (X[axis] - x_min) / length + offset; }
};

struct GradedMooneyRivlin {
  MooneyRivlin base;  // [Pa] c1, c2, lambda at factor 1 (seed: 2.126e3, 1.7e2, 1.7e5)
  LinearGrading grading;

  // Validates the grading and the base parameters.
  void validate() const;

  // Parameters at reference point X. Throws std::invalid_argument if the factor
  // at X is not positive (a point far outside the graded range).
  MooneyRivlin at(const Vec3& X) const;
};

}  // namespace rkpm::materials
