#include "terms/body_force/body_force.hpp"

#include "terms/body_force/settings.hpp"
#include "terms/catalog.hpp"
#include "terms/term_support.hpp"

namespace rkpm::sim {

void BodyForce::add_forces(World&) {
  const auto n = static_cast<Index>(body_.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) body_.force[i] += body_.mass[i] * g_;
}

double BodyForce::power(const World&) const {
  double p = 0.0;
  const auto n = static_cast<Index>(body_.size());
#pragma omp parallel for schedule(static) reduction(+ : p)
  for (Index i = 0; i < n; ++i) p += body_.mass[i] * g_.dot(body_.v[i]);
  return p;
}

}  // namespace rkpm::sim

namespace rkpm::terms::body_force {

std::unique_ptr<sim::Term> build(const scene::ParamSet& params, sim::World& world) {
  const sim::BodyForceSettings s = settings_table().read(params);
  return std::make_unique<sim::BodyForce>(named_body(world, params, s.body), s.acceleration);
}

}  // namespace rkpm::terms::body_force
