#include "terms/surface_pressure/surface_pressure.hpp"

#include "terms/catalog.hpp"
#include "terms/surface_pressure/settings.hpp"
#include "terms/term_support.hpp"

#include "rkpm/sim/body_points.hpp"

#include <algorithm>

namespace rkpm::sim {

SurfacePressure::SurfacePressure(Body& body, std::uint32_t surface_bit, double pressure)
    : body_(body),
      quadrature_(rk::build_boundary_quadrature(body.cloud, *body.rk, surface_bit)),
      pressure_(pressure),
      force_(body.size(), Vec3::Zero()) {}

void SurfacePressure::add_forces(World&) {
  const auto& q = quadrature_;
  std::fill(force_.begin(), force_.end(), Vec3::Zero());
  // Serial over facets: scattering to particles in a fixed order keeps the sum deterministic.
  for (std::size_t f = 0; f < q.point.size(); ++f) {
    const Mat3& F = body_.F[q.owner[f]];
    const Vec3 current_area = F.determinant() * F.inverse().transpose() * q.area[f];
    for (Index k = q.row_offset[f]; k < q.row_offset[f + 1]; ++k) force_[q.col[k]] -= pressure_ * q.psi[k] * current_area;
  }
  for (std::size_t i = 0; i < force_.size(); ++i) body_.force[i] += force_[i];
}

double SurfacePressure::power(const World&) const {
  double p = 0.0;
  for (std::size_t i = 0; i < force_.size(); ++i) p += force_[i].dot(body_.v[i]);
  return p;
}

}  // namespace rkpm::sim

namespace rkpm::terms::surface_pressure {

std::unique_ptr<sim::Term> build(const scene::ParamSet& params, sim::World& world) {
  const sim::SurfacePressureSettings s = settings_table().read(params);
  sim::Body& body = named_body(world, params, s.body);
  return std::make_unique<sim::SurfacePressure>(body, sim::surface_selector(body, s.surface), s.pressure);
}

}  // namespace rkpm::terms::surface_pressure
