#include "rkpm/sim/body_points.hpp"

#include <omp.h>

#include <algorithm>

namespace rkpm::sim {

void physical_points(const Body& body, std::vector<Vec3>& out) {
  out.resize(body.size());
#pragma omp parallel for schedule(static)
  for (Index J = body.owned_begin(); J < body.owned_end(); ++J) out[J] = physical_point(body, J);
}

void physical_points(const Body& body, const std::vector<Index>& particles, std::vector<Vec3>& out) {
  out.resize(body.size());
  for (Index J : particles)
    if (J >= body.owned_begin() && J < body.owned_end()) out[J] = physical_point(body, J);
}

void add_point_forces(Body& body, const std::vector<Vec3>& f) {
  const auto& N = body.interpolation;
  const auto n = static_cast<Index>(body.size());
  const Index begin = body.owned_begin(), end = body.owned_end();
  if (N.row_offset.empty()) {
    for (Index i = begin; i < end; ++i) body.force[i] += f[i];
    return;
  }
  // Distributed: the owned rows' transfer lands on owned particles and ghosts alike;
  // the ghosts' part goes back to the owners (as in the list version below).
  const bool distributed = body.distributed();
  if (distributed) body.point_force_ghosts.assign(body.size(), Vec3::Zero());
  std::vector<Vec3>& out = distributed ? body.point_force_ghosts : body.force;
  auto& scatter = body.point_force_scatter;
  const int threads = omp_get_max_threads();
  if (!scatter.planned_for(threads)) scatter.plan(n, n, {{&N.row_offset, &N.col}}, threads, 1);
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    scatter.clear(t);
    Vec3* sum = scatter.buffer(t, 0);
    for (Index J = std::max(scatter.row_begin(t), begin); J < std::min(scatter.row_end(t), end); ++J) {
      const Vec3& fJ = f[J];
      if (fJ.isZero(0.0)) continue;  // most particles carry no point force
      for (Index k = N.row_offset[J]; k < N.row_offset[J + 1]; ++k) sum[N.col[k]] += N.psi[k] * fJ;
    }
#pragma omp barrier
    scatter.reduce_add(t, 0, 1.0, out);
  }
  if (distributed) {
    body.ghosts.push_add(body.point_force_ghosts);
    for (Index I = begin; I < end; ++I) body.force[I] += body.point_force_ghosts[I];
  }
}

std::vector<char> readable_particles(const Body& body) {
  if (!body.distributed()) return std::vector<char>(body.size(), 1);
  std::vector<char> readable(body.size(), 0);
  std::fill(readable.begin() + body.owned_begin(), readable.begin() + body.owned_end(), 1);
  for (const auto& group : body.ghosts.ghosts_by_owner())
    for (Index g : group) readable[static_cast<std::size_t>(g)] = 1;
  return readable;
}

std::uint32_t surface_selector(const Body& body, const std::string& surface) {
  return surface == "all" ? 0u : body.cloud.surface_bit(surface);
}

}  // namespace rkpm::sim
