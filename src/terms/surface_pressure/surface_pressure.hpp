// Follower pressure on a named surface: traction -p n in the current configuration,
// integrated with the boundary quadrature of the SCNI cells. By Nanson's formula the
// current area vector of a facet of cell L is J_L F_L^-T A, with the smoothed F_L:
//   f_I = -p sum_f Psi_I(X_f) J_L F_L^-T A_f.
// Distributed: a rank integrates the facets of the cells it owns (it holds their F);
// their support lies within the cell's gradient row, so the particles they reach are
// its own or its ghosts, and the ghosts' part goes back to the owners.
#pragma once

#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <vector>

namespace rkpm::sim {

class SurfacePressure final : public Term {
 public:
  // surface_bit = 0: every boundary facet. Builds the surface's quadrature (a body
  // keeps none of its own: only the terms on a surface pay for it).
  SurfacePressure(Body& body, std::uint32_t surface_bit, double pressure, const par::Comm& comm = par::Comm::self());
  std::string name() const override { return "surface_pressure"; }
  bool distributed() const override { return true; }
  void add_forces(World&) override;
  double power(const World&) const override;

 private:
  Body& body_;
  const par::Comm& comm_;
  rk::BoundaryQuadrature quadrature_;  // the surface's facets: built for this term alone
  double pressure_;
  std::vector<Vec3> force_;          // last forces, for the power (distributed: at owned particles)
  Index first_facet_ = 0, end_facet_ = 0;  // this rank's facets: those of its cells
  rk::RowScatter scatter_;           // the facets' sums, in the one-process order
};

}  // namespace rkpm::sim
