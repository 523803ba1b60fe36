// Whether the contact law can keep each body's particles out of the other's surface
// layer: the set-up check behind the contact term's refusal of clouds too coarse for s0.
//
// A particle of one body that reaches the middle of a hollow of the other's surface
// layer (a face between its surface particles) is pushed back only by the face's corner
// particles. With the hollow's radius R_h (the largest distance from a point of the face
// to its nearest corner: the circumradius of an acute triangle, half the longest edge of
// an obtuse one), the corners repel it only while R_h < s0, the minimum of Eq. 13's
// potential: at R_h >= s0 every corner pulls it into the hollow and the layers beneath
// pull it on, so nothing stops it (a square grid of spacing a has R_h = a / sqrt(2): it
// fails at a >= sqrt(2) s0). The cutoff changes no force, and it exceeds s0 already.
// Below that limit the barrier is finite and shrinks towards it (docs/theory/contact.md
// measures where it holds); the run watches those clouds (Contact::diagnose).
// Only the faces that face the other body count (outward normal towards its reference
// centroid): a block's sides and bottom never meet a cell resting on its top.
#pragma once

#include "rkpm/sim/body.hpp"

#include <string>

namespace rkpm::sim {

struct SurfaceHollow {
  double radius = 0.0;  // R_h [m]; 0 when the body has no facing face
  Vec3 centre = Vec3::Zero();
};

// The widest hollow among the faces of `body` (reference configuration, quadrilaterals
// split along their 0-2 diagonal) whose outward normal points towards `towards`.
SurfaceHollow widest_facing_hollow(const Body& body, const Vec3& towards);

}  // namespace rkpm::sim
