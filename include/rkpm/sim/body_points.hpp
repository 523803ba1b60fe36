// What every surface and contact term needs from a body: the physical points of its
// particles, and the transfer of forces acting at those points to the generalized
// coordinates d the integrator advances.
//
// The physical position of particle J is p_J = X_J + u(X_J), u(X_J) = sum_I Psi_I(X_J) d_I
// (body.hpp). A force f_J acting at p_J does virtual work f_J . delta p_J =
// sum_I Psi_I(X_J) f_J . delta d_I, so it enters the generalized force of particle I
// as sum_J Psi_I(X_J) f_J. Bodies without RK operators (some tests) use p = x = X + d
// and receive f_J directly.
#pragma once

#include "rkpm/sim/body.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace rkpm::sim {

// p_J for every particle (parallel), out indexed by particle. Distributed: for this
// rank's own particles only (it holds their interpolation rows); the other entries are
// untouched, for the caller to exchange.
void physical_points(const Body& body, std::vector<Vec3>& out);
// p_J for the listed particles only (distributed: those of them this rank owns); out
// is indexed by particle (its other entries untouched).
void physical_points(const Body& body, const std::vector<Index>& particles, std::vector<Vec3>& out);

// A term's sums over its own rows (list entries, faces, facets, pairs), made in the
// one-process order on any rank count (rk/row_scatter.hpp): the rows [first, end) this
// rank evaluates must be a contiguous range, and the ranks' ranges in rank order the
// one-process rows in order (rows grouped by a particle the rank owns, in increasing
// particle order, are). Serial: one block. `columns(row, channel, emit)` names each
// row's contributions in the order the term makes them; `ghosts` is the exchange that
// holds the columns this rank reaches but does not own (null: the body's own ghosts).
void plan_term_rows(rk::RowScatter& scatter, const Body& body, Index first, Index end, int channels,
                    const rk::RowScatter::RowColumns& columns, const par::GhostExchange* ghosts = nullptr);
// After a pass (scatter.clear(0), then the rows through scatter.sink(0, channel, row) in
// increasing order): out[I] += scale * the sum of the contributions at I, at every
// particle this rank owns (collective on a distributed body).
void add_term_rows(rk::RowScatter& scatter, int channel, double scale, std::vector<Vec3>& out);
// The entries [first, end) of a list sorted by particle (`by_particle[k]` the particle
// entry k belongs to) whose particle this rank owns: a term's own rows.
std::pair<Index, Index> owned_entries(const Body& body, const std::vector<Index>& by_particle);

// Generalized forces of point forces at every particle: force_I += sum_J Psi_I(X_J) f_J,
// scattered from the interpolation's rows into per-thread buffers, ordered over
// threads and ranks (rk/row_scatter.hpp: the same bits on any split, no stored
// transpose).
// Distributed: f is read at this rank's own particles only, and must be their whole
// force there (contributions made on other ranks already added).
void add_point_forces(Body& body, const std::vector<Vec3>& f);

// The same for forces at a few listed particles (a surface, the pairs in contact),
// listed in increasing order: force_I += sum_i (scale Psi_I(X_{J_i})) f_i with
// J_i = particles[i] and f_i = force_at(i). A serial scatter in list order (cheap for a
// small set), ordered over the ranks through the caller's `scatter` (planned on first
// use; the list must not change afterwards). Distributed: a rank transfers the forces
// of the listed particles it owns (it holds their interpolation rows).
template <class ForceAt>
void add_point_forces(Body& body, const std::vector<Index>& particles, double scale, ForceAt force_at,
                      rk::RowScatter& scatter) {
  const auto& N = body.interpolation;
  const bool rows = !N.row_offset.empty();
  const auto [first, end] = owned_entries(body, particles);
  if (!scatter.planned_for(1))
    plan_term_rows(scatter, body, first, end, 1, [&](Index i, int, const std::function<void(Index)>& emit) {
      const Index J = particles[static_cast<std::size_t>(i)];
      if (!rows) return emit(J);
      rk::for_each_weight_column(N, J, emit);
    });
  scatter.clear(0);
  for (Index i = first; i < end; ++i) {
    const Index J = particles[static_cast<std::size_t>(i)];
    const Vec3& f = force_at(static_cast<std::size_t>(i));
    const auto sink = scatter.sink(0, 0, i);
    if (f.isZero(0.0) && !sink.records()) continue;  // a row at a seam still records its zeros
    if (!rows) {
      sink(J, Vec3(scale * f));
      continue;
    }
    rk::for_each_weight(N, J, [&](Index I, double w) { sink(I, Vec3((scale * w) * f)); });
  }
  add_term_rows(scatter, 0, 1.0, body.force);
}

// Distributed: 1 for each particle this rank owns or holds as a ghost (whose values it
// reads and to whose owner it can return forces), 0 for the others; all 1 on one rank.
std::vector<char> readable_particles(const Body& body);

// The surface-mask bit of a named surface of the body's cloud; 0 for "all" (every
// boundary particle or facet qualifies).
std::uint32_t surface_selector(const Body& body, const std::string& surface);

}  // namespace rkpm::sim
