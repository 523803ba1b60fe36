// Checks that need the whole scene: names that refer to other objects, and
// combinations of keys from different sections.
#pragma once

#include "rkpm/scene/scene.hpp"

namespace rkpm::scene {

// Body names are unique; every Reference::body / bodies / surface key names a
// declared body or one of its surfaces; integrator and output agree.
// Fills output defaults that derive from the integrator (every = t_end / 50).
void check_scene(Scene& scene);

}  // namespace rkpm::scene
