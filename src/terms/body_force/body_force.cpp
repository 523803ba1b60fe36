#include "terms/body_force/body_force.hpp"

#include "terms/body_force/settings.hpp"
#include "terms/catalog.hpp"
#include "terms/term_support.hpp"
#include "rkpm/common/parallel.hpp"

namespace rkpm::sim {

void BodyForce::add_forces(World&) {
#pragma omp parallel for schedule(static) if (worth_threads(body_.owned_end() - body_.owned_begin()))
  for (Index i = body_.owned_begin(); i < body_.owned_end(); ++i) body_.force[i] += body_.mass[i] * g_;
}

double BodyForce::power(const World& world) const {
  ExactSum p;
#pragma omp parallel for schedule(static) reduction(+ : p) if (worth_threads(body_.owned_end() - body_.owned_begin()))
  for (Index i = body_.owned_begin(); i < body_.owned_end(); ++i) p.add(body_.mass[i] * g_.dot(body_.v[i]));
  return world.comm->sum(p);
}

}  // namespace rkpm::sim

namespace rkpm::terms::body_force {

std::unique_ptr<sim::Term> build(const scene::ParamSet& params, sim::World& world) {
  const sim::BodyForceSettings s = settings_table().read(params);
  return std::make_unique<sim::BodyForce>(named_body(world, params, s.body), s.acceleration);
}

}  // namespace rkpm::terms::body_force
