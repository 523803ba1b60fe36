#include "rkpm/sim/world.hpp"

namespace rkpm::sim {

void compute_forces(World& world) {
  for (auto& body : world.bodies) compute_internal_forces(*body);
  // Terms in declaration order: each adds to Body::force, so the sum is deterministic.
  for (auto& term : world.terms) term->add_forces(world);
}

}  // namespace rkpm::sim
