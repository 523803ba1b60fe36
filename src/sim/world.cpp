#include "rkpm/sim/world.hpp"

namespace rkpm::sim {

void compute_forces(World& world) {
  for (auto& body : world.bodies) compute_internal_forces(*body);
  // Terms in declaration order: each adds to Body::force, so the sum is deterministic.
  for (auto& term : world.terms) term->add_forces(world);
}

double kinetic_energy(const World& world) {
  // Exact: the same bits on any thread and rank count (common/exact_sum.hpp).
  ExactSum ke;
  for (const auto& bp : world.bodies) {
    const Body& b = *bp;
#pragma omp parallel for schedule(static) reduction(+ : ke)
    for (Index i = b.owned_begin(); i < b.owned_end(); ++i) ke.add(0.5 * b.inertia[i] * b.v[i].squaredNorm());
  }
  return world.comm->sum(ke);
}

}  // namespace rkpm::sim
