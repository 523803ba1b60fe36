#include "terms/surface_pressure/surface_pressure.hpp"

#include "terms/catalog.hpp"
#include "terms/surface_pressure/settings.hpp"
#include "terms/term_support.hpp"

#include "rkpm/sim/body_points.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace rkpm::sim {

SurfacePressure::SurfacePressure(Body& body, std::uint32_t surface_bit, double pressure, const par::Comm& comm)
    : body_(body),
      comm_(comm),
      quadrature_(rk::build_boundary_quadrature(body.cloud, *body.rk, surface_bit)),
      pressure_(pressure),
      force_(body.size(), Vec3::Zero()) {
  if (!body.distributed()) return;
  // The facets of the owned cells reach the cell's gradient-row columns: owned
  // particles or ghosts. Anything else would be a force silently dropped.
  const std::vector<char> readable = readable_particles(body);
  const auto& q = quadrature_;
  for (std::size_t f = 0; f < q.point.size(); ++f) {
    if (q.owner[f] < body.owned_begin() || q.owner[f] >= body.owned_end()) continue;
    for (Index k = q.row_offset[f]; k < q.row_offset[f + 1]; ++k)
      if (!readable[static_cast<std::size_t>(q.col[k])])
        throw std::logic_error(fmt::format("surface pressure on body '{}': a facet of particle {} reaches particle {}, "
                                           "which its rank neither owns nor holds as a ghost",
                                           body.name, q.owner[f], q.col[k]));
  }
}

void SurfacePressure::add_forces(World&) {
  const auto& q = quadrature_;
  std::fill(force_.begin(), force_.end(), Vec3::Zero());
  // Serial over facets: scattering to particles in a fixed order keeps the sum deterministic.
  const Index begin = body_.owned_begin(), end = body_.owned_end();
  for (std::size_t f = 0; f < q.point.size(); ++f) {
    if (q.owner[f] < begin || q.owner[f] >= end) continue;  // another rank's cell
    const Mat3& F = body_.F[q.owner[f]];
    const Vec3 current_area = F.determinant() * F.inverse().transpose() * q.area[f];
    for (Index k = q.row_offset[f]; k < q.row_offset[f + 1]; ++k) force_[q.col[k]] -= pressure_ * q.psi[k] * current_area;
  }
  if (body_.distributed()) body_.ghosts.push_add(force_);
  for (Index i = begin; i < end; ++i) body_.force[i] += force_[i];
}

double SurfacePressure::power(const World&) const {
  double p = 0.0;
  for (Index i = body_.owned_begin(); i < body_.owned_end(); ++i) p += force_[i].dot(body_.v[i]);
  return comm_.sum(p);
}

}  // namespace rkpm::sim

namespace rkpm::terms::surface_pressure {

std::unique_ptr<sim::Term> build(const scene::ParamSet& params, sim::World& world) {
  const sim::SurfacePressureSettings s = settings_table().read(params);
  sim::Body& body = named_body(world, params, s.body);
  return std::make_unique<sim::SurfacePressure>(body, sim::surface_selector(body, s.surface), s.pressure,
                                                *world.comm);
}

}  // namespace rkpm::terms::surface_pressure
