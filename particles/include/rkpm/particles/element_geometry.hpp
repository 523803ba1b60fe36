// Geometry of single elements of a cloud's mesh: validity and quality checks for
// generators, importers and tests.
#pragma once

#include "rkpm/particles/cloud.hpp"

namespace rkpm::particles {

// Volume of element e: exact for tetrahedra and for trilinear hexahedra.
double element_volume(const Cloud& cloud, int e);

// Smallest corner quality det(e1, e2, e3) / (|e1| |e2| |e3|) over the element's
// corners, e_k the edges leaving the corner in right-handed order. 1 for a
// right-angled corner, <= 0 for an inverted or degenerate element.
double element_min_scaled_jacobian(const Cloud& cloud, int e);

}  // namespace rkpm::particles
