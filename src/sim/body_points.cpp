#include "rkpm/sim/body_points.hpp"

#include <omp.h>

namespace rkpm::sim {

void physical_points(const Body& body, std::vector<Vec3>& out) {
  const auto n = static_cast<Index>(body.size());
  out.resize(body.size());
#pragma omp parallel for schedule(static)
  for (Index J = 0; J < n; ++J) out[J] = physical_point(body, J);
}

void physical_points(const Body& body, const std::vector<Index>& particles, std::vector<Vec3>& out) {
  out.resize(body.size());
  for (Index J : particles) out[J] = physical_point(body, J);
}

void add_point_forces(Body& body, const std::vector<Vec3>& f) {
  const auto& N = body.interpolation;
  const auto n = static_cast<Index>(body.size());
  if (N.row_offset.empty()) {
    for (Index i = 0; i < n; ++i) body.force[i] += f[i];
    return;
  }
  auto& scatter = body.point_force_scatter;
  const int threads = omp_get_max_threads();
  if (!scatter.planned_for(threads)) scatter.plan(n, n, {{&N.row_offset, &N.col}}, threads, 1);
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    scatter.clear(t);
    Vec3* sum = scatter.buffer(t, 0);
    for (Index J = scatter.row_begin(t); J < scatter.row_end(t); ++J) {
      const Vec3& fJ = f[J];
      if (fJ.isZero(0.0)) continue;  // most particles carry no point force
      for (Index k = N.row_offset[J]; k < N.row_offset[J + 1]; ++k) sum[N.col[k]] += N.psi[k] * fJ;
    }
#pragma omp barrier
    scatter.reduce_add(t, 0, 1.0, body.force);
  }
}

std::uint32_t surface_selector(const Body& body, const std::string& surface) {
  return surface == "all" ? 0u : body.cloud.surface_bit(surface);
}

}  // namespace rkpm::sim
