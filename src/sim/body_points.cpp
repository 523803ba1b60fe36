#include "rkpm/sim/body_points.hpp"

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
  const auto& T = N.transpose;
#pragma omp parallel for schedule(static)
  for (Index I = 0; I < n; ++I) {
    Vec3 s = Vec3::Zero();
    for (Index e = T.offset[I]; e < T.offset[I + 1]; ++e) s += N.psi[T.entry[e]] * f[T.row[e]];
    body.force[I] += s;
  }
}

std::uint32_t surface_selector(const Body& body, const std::string& surface) {
  return surface == "all" ? 0u : body.cloud.surface_bit(surface);
}

}  // namespace rkpm::sim
