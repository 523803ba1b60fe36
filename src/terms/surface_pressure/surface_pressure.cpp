#include "terms/surface_pressure/surface_pressure.hpp"

#include "terms/catalog.hpp"
#include "terms/surface_pressure/settings.hpp"
#include "terms/term_support.hpp"

#include "rkpm/sim/body_points.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <tuple>

namespace rkpm::sim {

SurfacePressure::SurfacePressure(Body& body, std::uint32_t surface_bit, double pressure, const par::Comm& comm)
    : body_(body),
      comm_(comm),
      quadrature_(rk::build_boundary_quadrature(body.cloud, approximation(body), surface_bit, body.cell_quadrature)),
      pressure_(pressure),
      force_(body.size(), Vec3::Zero()) {
  // A cell's facets are listed together, cells in increasing order: a rank's cells' are
  // one range.
  std::tie(first_facet_, end_facet_) = owned_entries(body, quadrature_.owner);
  plan_term_rows(scatter_, body, first_facet_, end_facet_, 1, [this](Index f, int, const std::function<void(Index)>& emit) {
    for (Index k = quadrature_.row_offset[f]; k < quadrature_.row_offset[f + 1]; ++k) emit(quadrature_.col[k]);
  });
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
  // Serial over this rank's facets, ordered over the ranks (plan_term_rows).
  scatter_.clear(0);
  for (Index f = first_facet_; f < end_facet_; ++f) {
    const Mat3& F = body_.F[q.owner[f]];
    const Vec3 current_area = F.determinant() * F.inverse().transpose() * q.area[f];
    const auto sink = scatter_.sink(0, 0, f);
    for (Index k = q.row_offset[f]; k < q.row_offset[f + 1]; ++k)
      sink(q.col[k], Vec3(-(pressure_ * q.psi[k] * current_area)));
  }
  add_term_rows(scatter_, 0, 1.0, force_);
  for (Index i = body_.owned_begin(); i < body_.owned_end(); ++i) body_.force[i] += force_[i];
}

double SurfacePressure::power(const World&) const {
  ExactSum p;
  for (Index i = body_.owned_begin(); i < body_.owned_end(); ++i) p.add(force_[i].dot(body_.v[i]));
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
