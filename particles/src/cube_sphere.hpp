// Equiangular cubed-sphere projection, shared by the sphere and shell generators.
#pragma once

#include "rkpm/particles/cloud.hpp"

namespace rkpm::particles::detail {

// tan(pi/4 s) for s in [-1, 1]: equal angles for equal steps in s. Exact at
// s = -1, 0, 1 so nodes on the cube's edges project to identical bits from
// either adjacent face.
double equiangular(double s);

// Unit direction of a point p != 0 of the cube [-1, 1]^3: the face selected by
// p's largest component, with both face coordinates mapped by `equiangular`.
Vec3 equiangular_direction(const Vec3& p);

}  // namespace rkpm::particles::detail
