// Repulsive contact between the walls of one body: the two faces of a cell must not
// pass through each other when a deep dimple brings them together.
//
// The surface-to-surface form of the repulsive part of the seed's Lennard-Jones
// potential (Eq. 13), cut at its minimum s0 and shifted to zero there:
//     w(r) = (p0 / s0) [(s0/r)^12 - 2 (s0/r)^6 + 1]   for r < s0,   0 beyond,
//     Pi_W = sum_{I<J, |X_I - X_J| >= exclusion} A_I A_J w(|p_I - p_J|),
// over the particles I, J of one named surface with reference boundary areas A, at
// their physical positions p (as the contact term, terms/contact/contact.hpp). Two flat sheets
// at gap d < s0 then press on each other with the continuum pressure
//     p(d) = 2 pi p0 (d/s0) [(s0/d)^12 - 2 (s0/d)^6 + 1],
// (4.4 p0 at d = 0.9 s0, 40 p0 at 0.8 s0): p0 sets the stiffness, s0 the distance at
// which the walls meet. That law is the continuum limit, for a particle spacing well
// below s0; with a spacing above sqrt(2) s0 a particle can pass between those of the
// other wall (the set-up warns). The force is continuous at s0 (w'(s0) = 0). Pairs closer than
// `exclusion` in the reference configuration are parts of the same wall and never
// interact, so the reference state carries no contact force when exclusion > s0.
// Pairs come from a symmetric Verlet list over the surface (contact_pairs.hpp); each
// particle sums its own row, so the result does not depend on the thread count.
#pragma once

#include "terms/contact/contact.hpp"
#include "terms/contact/contact_pairs.hpp"
#include "terms/wall_contact/settings.hpp"
#include "rkpm/sim/world.hpp"

#include <limits>
#include <string>
#include <vector>

namespace rkpm::sim {

class WallContact final : public Term {
 public:
  WallContact(Body& body, const WallContactSettings& settings);
  // The pair list's filter refers to this object: it is never copied or moved.
  WallContact(const WallContact&) = delete;
  WallContact& operator=(const WallContact&) = delete;
  std::string name() const override { return "wall_contact"; }
  void add_forces(World& world) override;
  double stored_energy(const World&) const override { return energy_; }
  // Gershgorin bound as for the contact term, over the pairs listed within s0 + skin.
  double stable_dt(const World&) const override;
  // The particles whose row exceeds the bound of `dt` get heavier, in a few passes (a
  // partner that gets heavier too lowers the row further); see Term::scale_inertia_to.
  void scale_inertia_to(World&, double dt) override;
  void report(const World&, io::Json& summary) const override;
  bool distributed() const override { return true; }

  double energy() const { return energy_; }
  std::size_t active_pairs() const { return active_pairs_; }  // each pair once
  // Smallest distance between two non-excluded listed particles at the last
  // evaluation [m]; infinity when none is listed.
  double closest() const { return closest_; }
  const std::vector<Index>& particles() const { return particles_; }  // the surface's particles
  // Root of the mean reference area per surface particle [m]: the particle spacing.
  double surface_spacing() const;
  const std::vector<Vec3>& point_force() const { return force_; }     // on their physical points

 private:
  // Pair energy scale A_I A_J p0 / s0 [J]; the energy is that times (s0/r)^12 - 2 (s0/r)^6 + 1.
  double pair_energy_scale(Index i, Index j) const { return area_[i] * area_[j] * pressure_ / lj_.s0; }
  bool excluded(Index i, Index j) const;
  // Gershgorin row of surface particle i, sum over its listed pairs of k_ij (1 / m_i +
  // 1 / sqrt(m_i m_j)) with the stiffness at min(r, s0): omega^2 of the row [1/s^2].
  double gershgorin_row(Index i) const;

  Body& body_;
  par::SharedParticles shared_;  // distributed: every rank's surface points, on every rank
  std::string surface_;
  LennardJones lj_;  // eps = 1: the shape of w
  double pressure_, exclusion2_;
  std::vector<Index> particles_;  // body particle of each surface index
  std::vector<double> area_;      // reference boundary area of each
  std::vector<Vec3> reference_, points_, force_;
  std::vector<double> row_energy_, row_closest_;
  ContactPairs pairs_;
  rk::RowScatter transfer_;  // the point forces to the particles, in the one-process order
  double energy_ = 0.0;
  double closest_ = std::numeric_limits<double>::infinity();
  double closest_over_run_ = std::numeric_limits<double>::infinity();
  std::size_t active_pairs_ = 0, max_active_pairs_ = 0;
  double seconds_ = 0.0;
};

}  // namespace rkpm::sim
