// Placement of particles along a meridian of an ellipsoid, shared by the shell's layers.
#pragma once

#include <vector>

namespace rkpm::particles::detail {

// The meridian is the quarter ellipse (rho sin psi, c cos psi), psi in [0, pi/2]
// from the pole to the equator, mirrored onto the southern half. Its outward normal
// makes the angle beta(psi) = atan2(c sin psi, rho cos psi) with the polar axis.
//
// psi(theta) maps the sphere's colatitude theta to the ellipse's parameter so that
// equal steps in theta give equal steps in the blend
//     g(psi) = (1 - w) s(psi) / s(pi/2) + w beta(psi) / (pi/2),
// s the arc length from the pole. w = 0 spaces particles evenly in arc length,
// which leaves the tight rim of a flat spheroid (radius of curvature c^2/rho) with
// few particles: the normal turns by h rho / c^2 between neighbours at spacing h.
// w = 1 spaces them evenly in normal angle, which starves the flat caps. A small
// w moves particles from the caps to the rim in proportion to the curvature kappa
// (dg/ds = (1 - w) / s(pi/2) + w kappa / (pi/2)), bounding both the spacing and
// the turn of the normal per step. For a circle g = psi / (pi/2) whatever w.
class MeridianSampling {
 public:
  MeridianSampling(double rho, double c, double turning_weight);

  double psi(double theta) const;

 private:
  double blend(double psi) const;        // g(psi)
  double blend_rate(double psi) const;   // g'(psi) > 0
  double speed(double psi) const;        // ds / dpsi
  double arc_from_pole(double psi) const;

  double rho_, c_, w_;
  std::vector<double> cumulative_;  // arc length from the pole to k * kStep
  double quarter_arc_ = 0.0;
};

}  // namespace rkpm::particles::detail
