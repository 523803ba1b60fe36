// The same scene on a coarser (or finer) particle cloud: the levels of nested
// iteration (docs/verification/relaxation.md).
#pragma once

#include "rkpm/scene/scene.hpp"

namespace rkpm::scene {

// A copy of `scene` whose generated clouds have their cell counts multiplied by
// `factor` (rounded, never below the generator's minimum): a block's cells along each
// direction, a sphere's cells across the diameter, a shell's face_cells. A shell keeps
// its layers: the driver of the red-blood-cell scene acts on halves of the wall, so
// the layer count is part of the model, not of the resolution. The copy has no
// nested levels of its own. Imported clouds cannot be coarsened (check_scene rejects
// nested levels for them); they are copied unchanged.
Scene at_resolution(const Scene& scene, double factor);

}  // namespace rkpm::scene
