// examples/crawling/crawling.toml as the crawling study runs it: the default scene,
// or with the changes `scripts/study crawling --coarse` makes (keep the two in step).
#pragma once

#include "rkpm/scene/scene.hpp"

#include <cstdint>

namespace rkpm::testing {

inline scene::Scene crawling_scene(bool coarse) {
  scene::Scene s = scene::load_scene(RKPM_SOURCE_DIR "/examples/crawling/crawling.toml");
  if (!coarse) return s;
  for (scene::BodySpec& body : s.bodies) {
    if (body.name() == "cell") {
      body.cloud.set("cells", std::int64_t{11}, 0, true);
      body.cloud.set("center", Vec3(0.0, 0.0, 10.3368e-6), 0, true);
    } else if (body.name() == "substrate") {
      body.cloud.set("cells", scene::Int3{30, 30, 3}, 0, true);
    }
  }
  return s;
}

}  // namespace rkpm::testing
