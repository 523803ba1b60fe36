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
  // s0 = lateral spacing / 1.25 = 1 um (the contact law holds the coarser grid);
  // eps keeps |W(d0)| = 1e-3 J/m^2.
  for (scene::TermSpec& term : s.terms) {
    if (term.type() != "contact") continue;
    term.params.set("s0", 1e-6, 0, true);
    term.params.set("epsilon", 1.0331e-15, 0, true);
    term.params.set("cutoff", 3e-6, 0, true);
    term.params.set("skin", 0.5e-6, 0, true);
  }
  return s;
}

}  // namespace rkpm::testing
