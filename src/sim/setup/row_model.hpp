// How many particles an operator row holds, modelled from a cloud's size estimate
// before the cloud exists, and the support shape `support_shape = "auto"` resolves to.
//
// The model: the particles whose support covers a point, counted in the support's
// ellipsoid (a ball: all semi-axes equal) clipped to the body's extent
// (support_count in row_model.cpp). The pre-flight estimate sizes the operators with it;
// "auto" compares the two shapes with it, so that the pre-flight and the run decide
// alike from the scene file alone.
#pragma once

#include "clouds/catalog.hpp"
#include "rkpm/rk/rk_approximation.hpp"
#include "rkpm/scene/scene.hpp"

namespace rkpm::sim {

struct RowModel {
  double gradient = 0.0;       // particles per smoothed-gradient row (SCNI: the cell's reach too)
  double interpolation = 0.0;  // particles per interpolation row
};

RowModel row_model(const scene::BodySpec& spec, const clouds::CloudSize& grid, rk::SupportShape shape);

// "auto" takes ellipsoids when a ball would hold more than this many times the
// particles of the ellipsoid in an interpolation row. A ball's radius is support x
// the longest edge, so it overreaches where the spacings differ by direction: on a
// shell whose wall keeps its layers while its faces are refined, the ratio grows as
// (layer spacing / in-plane spacing)^2 (the RBC example: 1.0 at face_cells = 32, 1.2 at 48,
// 2.1 at 64, 3.3 at 80, 4.1 at 90, 17 at 182). Up to 4 the balls' longer rows cost less than
// what ellipsoids change (docs/verification/performance.md: the RBC example with
// ellipsoids on its own cloud takes more steps); beyond it the balls' rows dominate the
// memory and the step.
constexpr double kAutoEllipsoidRowRatio = 4.0;

// The shape a body's supports take: as declared, or for "auto" by the ratio above on a
// generated cloud (an imported mesh's estimate has no spacings: balls).
// The estimate is made only for "auto" (the overload without it).
rk::SupportShape resolved_support_shape(const scene::BodySpec& spec, const clouds::CloudSize& grid);
rk::SupportShape resolved_support_shape(const scene::BodySpec& spec);

}  // namespace rkpm::sim
