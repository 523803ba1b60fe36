#include "rkpm/sim/body_points.hpp"

#include <omp.h>

#include <algorithm>
#include <functional>

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
  // Ordered on several threads or ranks (rk/row_scatter.hpp): each particle gets
  // force + (the transfer's sum in row order), the same bits on any split. Distributed:
  // the owned rows' transfer lands on owned particles and ghosts alike; the ghosts'
  // part goes to the owners as records.
  auto& scatter = body.point_force_scatter;
  const int threads = rk::RowScatter::team_threads();
  if (!scatter.planned_for(threads)) {
    if (threads == 1 && !body.distributed()) {
      scatter.plan(n, n, {{&N.row_offset, &N.col}}, threads, 1);
    } else {
      const rk::RowScatter::Links links = body.distributed() ? body.ghosts.scatter_links() : rk::RowScatter::Links{};
      scatter.plan_ordered(
          begin, end, n, threads, 1,
          [&](Index J, int, const std::function<void(Index)>& emit) { rk::for_each_weight_column(N, J, emit); },
          body.distributed() ? &links : nullptr);
    }
  }
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    scatter.clear(t);
    for (Index J = std::max(scatter.row_begin(t), begin); J < std::min(scatter.row_end(t), end); ++J) {
      const Vec3& fJ = f[J];
      const auto transfer = [&](const auto& add) {
        rk::for_each_weight(N, J, [&](Index I, double w) { add(I, Vec3(w * fJ)); });
      };
      // A row at a seam makes every contribution, zeros too (its plan counts them); the
      // others add in place and skip the many particles that carry no point force.
      if (scatter.seam_row(J))
        transfer(scatter.sink(t, 0, J));
      else if (!fJ.isZero(0.0))
        transfer(rk::RowScatter::AddTo{scatter.buffer(t, 0)});
    }
#pragma omp barrier
    scatter.reduce_add(t, 0, 1.0, body.force);
  }
  scatter.fold(0, 1.0, body.force, true);
}

void plan_term_rows(rk::RowScatter& scatter, const Body& body, Index first, Index end, int channels,
                    const rk::RowScatter::RowColumns& columns, const par::GhostExchange* ghosts) {
  if (ghosts == nullptr) ghosts = &body.ghosts;
  const bool linked = body.distributed() && ghosts->built();
  const rk::RowScatter::Links links = linked ? ghosts->scatter_links() : rk::RowScatter::Links{};
  scatter.plan_ordered(first, end, static_cast<Index>(body.size()), 1, channels, columns, linked ? &links : nullptr);
}

std::pair<Index, Index> owned_entries(const Body& body, const std::vector<Index>& by_particle) {
  const auto at = [&](Index particle) {
    return static_cast<Index>(std::lower_bound(by_particle.begin(), by_particle.end(), particle) - by_particle.begin());
  };
  return {at(body.owned_begin()), at(body.owned_end())};
}

void add_term_rows(rk::RowScatter& scatter, int channel, double scale, std::vector<Vec3>& out) {
  scatter.reduce_add(0, channel, scale, out);
  scatter.fold(channel, scale, out, true);
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
