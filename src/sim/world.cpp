#include "rkpm/sim/world.hpp"

namespace rkpm::sim {

void compute_forces(World& world) {
  for (auto& body : world.bodies) compute_internal_forces(*body);
  // Terms in declaration order: each adds to Body::force, so the sum is deterministic.
  for (auto& term : world.terms) term->add_forces(world);
}

double kinetic_energy(const World& world) {
  double ke = 0.0;
  for (const auto& bp : world.bodies) {
    const Body& b = *bp;
    const auto n = static_cast<Index>(b.size());
#pragma omp parallel for schedule(static) reduction(+ : ke)
    for (Index i = 0; i < n; ++i) ke += 0.5 * b.mass[i] * b.v[i].squaredNorm();
  }
  return ke;
}

}  // namespace rkpm::sim
