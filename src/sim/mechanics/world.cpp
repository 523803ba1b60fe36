#include "rkpm/sim/world.hpp"

namespace rkpm::sim {

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
