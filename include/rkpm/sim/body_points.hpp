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

#include <cstdint>
#include <string>
#include <vector>

namespace rkpm::sim {

// p_J for every particle (parallel), out indexed by particle. Distributed: for this
// rank's own particles only (it holds their interpolation rows); the other entries are
// untouched, for the caller to exchange.
void physical_points(const Body& body, std::vector<Vec3>& out);
// p_J for the listed particles only (distributed: those of them this rank owns); out
// is indexed by particle (its other entries untouched).
void physical_points(const Body& body, const std::vector<Index>& particles, std::vector<Vec3>& out);

// Generalized forces of point forces at every particle: force_I += sum_J Psi_I(X_J) f_J,
// scattered from the interpolation's rows into per-thread buffers summed in thread
// order (rk/row_scatter.hpp: deterministic for a thread count, no stored transpose).
// Distributed: f is read at this rank's own particles only, and must be their whole
// force there (contributions made on other ranks already added).
void add_point_forces(Body& body, const std::vector<Vec3>& f);

// The same for forces at a few listed particles (a surface, the pairs in contact):
// force_I += sum_i (scale Psi_I(X_{J_i})) f_i with J_i = particles[i] and f_i =
// force_at(i). A serial scatter in list order: cheap for a small set and deterministic.
// Zero forces are skipped.
template <class ForceAt>
void add_point_forces(Body& body, const std::vector<Index>& particles, double scale, ForceAt force_at) {
  const auto& N = body.interpolation;
  // Distributed: a rank holds the interpolation rows of its own particles only, so only
  // their forces are transferred; what they put on ghosts goes back to the owners.
  const bool distributed = body.distributed();
  if (distributed) body.point_force_ghosts.assign(body.size(), Vec3::Zero());
  std::vector<Vec3>& out = distributed ? body.point_force_ghosts : body.force;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Index J = particles[i];
    if (distributed && (J < body.owned_begin() || J >= body.owned_end())) continue;
    const Vec3& f = force_at(i);
    if (f.isZero(0.0)) continue;
    if (N.row_offset.empty()) {
      out[J] += scale * f;
      continue;
    }
    for (Index k = N.row_offset[J]; k < N.row_offset[J + 1]; ++k) out[N.col[k]] += (scale * N.psi[k]) * f;
  }
  if (distributed) {
    body.ghosts.push_add(body.point_force_ghosts);
    for (Index I = body.owned_begin(); I < body.owned_end(); ++I) body.force[I] += body.point_force_ghosts[I];
  }
}

// Distributed: 1 for each particle this rank owns or holds as a ghost (whose values it
// reads and to whose owner it can return forces), 0 for the others; all 1 on one rank.
std::vector<char> readable_particles(const Body& body);

// The surface-mask bit of a named surface of the body's cloud; 0 for "all" (every
// boundary particle or facet qualifies).
std::uint32_t surface_selector(const Body& body, const std::string& surface);

}  // namespace rkpm::sim
