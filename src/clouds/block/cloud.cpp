// generator = "block": the cloud and its size (compiled into rkpm_sim).
#include "clouds/block/spec.hpp"

#include "rkpm/scene/scene.hpp"

namespace rkpm::clouds::block {

particles::Cloud make(const scene::BodySpec& body) { return particles::make_block(spec(body)); }

CloudSize estimate(const scene::BodySpec& body) {
  const particles::BlockSpec s = spec(body);
  CloudSize e;
  e.particles = 1.0;
  e.elements = 1.0;
  for (int i = 0; i < 3; ++i) {
    const auto n = static_cast<double>(s.cells[static_cast<std::size_t>(i)]);
    e.particles *= n + 1.0;
    e.elements *= n;
    e.spacing[i] = s.size[i] / n;
    e.extent[i] = s.size[i];
  }
  e.longest_edge = e.spacing.maxCoeff();
  e.size_key = key_at(body.cloud, "cells");
  return e;
}

}  // namespace rkpm::clouds::block
