// The clouds the RK tests run on: every generator the project has, small enough
// for dense linear algebra where a test needs it.
#pragma once

#include "rkpm/particles/generators.hpp"

namespace rkpm::test {

inline particles::Cloud jittered_block(int cells = 6, double jitter = 0.25) {
  particles::BlockSpec spec;
  spec.size = particles::Vec3(1.0, 0.8, 0.6);
  spec.cells = {cells, cells, cells};
  spec.jitter = jitter;
  spec.seed = 7;
  return particles::make_block(spec);
}

inline particles::Cloud small_sphere(int cells = 8) {
  particles::SphereSpec spec;
  spec.radius = 1.0;
  spec.cells = cells;
  return particles::make_sphere(spec);
}

inline particles::Cloud default_shell() { return particles::make_shell(particles::ShellSpec{}); }

}  // namespace rkpm::test
