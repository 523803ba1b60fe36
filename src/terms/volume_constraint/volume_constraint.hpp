// An enclosed, nearly incompressible fluid: the cytoplasm inside a cell's wall.
//
// The fluid fills the region bounded by a closed surface of a body (the shell's
// "inner" surface). Its volume is measured with the divergence theorem on the
// boundary quadrature of the SCNI cells, at the current configuration:
//     V = (s/3) sum_f x_f . a_f,   x_f = X_f + sum_I Psi_I(X_f) d_I,   a_f = J_L F_L^-T A_f,
// with s = +1 if the surface's outward normal points out of the fluid, -1 if it points
// into it (a shell's inner surface). The fluid pressure follows a logarithmic
// equation of state,
//     p = -K ln(V / V*),   V* = target * V0,
// whose stored energy is U(V) = K (V ln(V / V*) - V + V*) (dU/dV = -p), and pushes
// the wall away from the fluid: f_I = p s sum_f Psi_I(X_f) a_f. That force is the
// quadrature of the continuum first variation p (surface integral of du . n da), not the
// exact gradient of the discrete V above (whose a_f also moves with the smoothed F):
// the two differ by a discretisation error, 27 % RMS per particle on a 6-cell shell and
// 18 % on a 12-cell one (tests/terms/volume_constraint/test_volume_constraint.cpp), so
// the energy ledger of a scene with this term closes only to that order.
// The term is declared per scene ([[term]] type = "volume_constraint"); a body
// without it has no enclosed fluid at all.
// Distributed: a rank measures the rows of the cells it owns (the volume is summed over
// the ranks) and returns the force its rows put on ghosts to their owners.
// Cost: the facets are folded per owning cell once (the sums are linear in the facet
// terms), both sums then run in parallel over cells, and the force is gathered per
// particle through the transposed rows, so no two threads write one particle.
#pragma once

#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <vector>

namespace rkpm::sim {

class VolumeConstraint final : public Term {
 public:
  VolumeConstraint(Body& body, std::uint32_t surface_bit, double bulk, double target,
                   const par::Comm& comm = par::Comm::self());
  std::string name() const override { return "volume_constraint"; }
  void add_forces(World&) override;
  double stored_energy(const World&) const override;
  void report(const World&, io::Json&) const override;
  std::vector<std::string> history_columns() const override { return {"enclosed_volume_ratio", "enclosed_pressure"}; }
  std::string history_values(const World&) const override;
  bool distributed() const override { return true; }

  double volume() const { return volume_; }            // [m^3] at the last force evaluation
  double initial_volume() const { return initial_; }  // V0 [m^3]
  double pressure() const { return pressure_; }        // [Pa]

 private:
  // The signed volume at the current d and F (also stores each row's cofactor), summed
  // over the ranks.
  double measure_signed_volume();
  bool owns_row(std::size_t r) const;  // the row's cell is this rank's
  void check_ghosts() const;
  // Scratch of the fold: the running B_LI of one cell, by particle.
  struct Fold {
    std::vector<Vec3> value;
    std::vector<char> used;
    std::vector<Index> touched;
  };
  // Appends one row per cell of q's facets (a cell's facets are listed together).
  void fold_facets(const rk::BoundaryQuadrature& q, Fold& fold);
  void gather_by_particle();

  Body& body_;
  const par::Comm& comm_;
  // Distributed: this rank's rows (its cells, a range: rows are in cell order) and their
  // push on the particles, summed in the one-process order over the ranks.
  Index first_row_ = 0, end_row_ = 0;
  rk::RowScatter push_;
  // The facets on the surface, folded per owning cell L (one row each), so that a step
  // reads each (cell, particle) pair once instead of once per facet:
  //   B_LI = sum_{f in L} Psi_I(X_f) A_f,   C_L = sum_{f in L} X_f (x) A_f.
  std::vector<Index> owner_, row_offset_, col_;
  std::vector<Vec3> B_;
  std::vector<Mat3> C_;
  std::vector<Mat3> cofactor_;       // J F^-T of each row's cell, at the last measure
  std::vector<double> cone_;         // each row's share of the volume (summed exactly)
  // One process: particle I -> the rows that push it (by_particle_.row) and their B,
  // copied in that order (gather_by_particle; by_particle_.entry is not kept).
  rk::CsrTranspose by_particle_;
  std::vector<Vec3> B_by_particle_;
  double bulk_, target_;
  double sign_ = 1.0, initial_ = 0.0, volume_ = 0.0, pressure_ = 0.0;
};

}  // namespace rkpm::sim
