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
    // Each body's sum starts from zero: an OpenMP reduction onto a non-zero total
    // combines the threads' parts in arrival order, so a multi-body run would depend
    // on thread timing. (Two threads' parts added to zero commute exactly.)
    double body_ke = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : body_ke)
    for (Index i = b.owned_begin(); i < b.owned_end(); ++i) body_ke += 0.5 * b.inertia[i] * b.v[i].squaredNorm();
    ke += body_ke;
  }
  return world.comm->sum(ke);
}

}  // namespace rkpm::sim
