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
// the wall away from the fluid: f_I = p s sum_f Psi_I(X_f) a_f.
// The term is declared per scene ([[term]] type = "volume_constraint"); a body
// without it has no enclosed fluid at all.
#pragma once

#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <vector>

namespace rkpm::sim {

class VolumeConstraint final : public Term {
 public:
  VolumeConstraint(Body& body, std::uint32_t surface_bit, double bulk, double target);
  std::string name() const override { return "volume_constraint"; }
  void add_forces(World&) override;
  double stored_energy(const World&) const override;
  void report(const World&, io::Json&) const override;

  double volume() const { return volume_; }            // [m^3] at the last force evaluation
  double initial_volume() const { return initial_; }  // V0 [m^3]
  double pressure() const { return pressure_; }        // [Pa]

 private:
  double measure_signed_volume() const;

  Body& body_;
  std::vector<std::size_t> facets_;  // boundary-quadrature points on the surface
  double bulk_, target_;
  double sign_ = 1.0, initial_ = 0.0, volume_ = 0.0, pressure_ = 0.0;
};

}  // namespace rkpm::sim
