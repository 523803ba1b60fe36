// Interpolation-residual stabilization of nodal integration.
//
// Nodal integration, smoothed (SCNI) or not, leaves oscillatory displacement modes
// with almost no energy: on a regular grid the alternating field (-1)^(i+j+k) has a
// smoothed gradient that vanishes identically in the interior, because its RK
// interpolant is zero on every plane halfway between particles; jittered clouds
// keep hundreds of such modes at 1e-6..1e-4 of the largest stiffness.
//
// What those modes have in common is that the generalized coordinates d disagree
// with the field they interpolate: r_L = d_L - sum_I Psi_I(X_L) d_I is of the order
// of the mode's amplitude. For every linear field d_I = A X_I + c (which contains
// all rigid motions, finite rotations included) r = 0 exactly, by the linear
// reproducing condition; for a smooth field r = O(h^2 |grad grad u|). So the energy
//     E_stab = (alpha / 2) sum_L (mu_L V_L / h_L^2) |r_L|^2,    h_L = V_L^(1/3),
// penalises exactly the spurious modes, keeps the linear patch test and the six
// rigid-body modes exact, and adds only an O(h^2)-relative term for resolved
// deformations (it plays the role of hourglass control in under-integrated finite
// elements). Its force is f = -(I - N)^T W (I - N) d with N_LI = Psi_I(X_L),
// computed as a gather over the rows of N and a scatter from the same rows.
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/rk/nodal_integration.hpp"
#include "rkpm/rk/row_kernels.hpp"
#include "rkpm/rk/row_scatter.hpp"

#include <vector>

namespace rkpm::rk {

struct Stabilization {
  std::vector<double> weight;  // W_L = alpha mu_L V_L / h_L^2 [N/m]; empty = no stabilization
  RowScatter scatter;          // scratch of add_stabilization_forces (the simulator's force pass has its own)
  bool active() const { return !weight.empty(); }
};

// alpha = 0 gives an inactive stabilization. shear_modulus has one entry per particle.
Stabilization build_stabilization(const std::vector<double>& volume, const std::vector<double>& shear_modulus,
                                  double alpha);

// Adds the stabilization force to f and returns the stabilization energy [J].
double add_stabilization_forces(const NodalInterpolation& N, Stabilization& s, const std::vector<Vec3>& d,
                                std::vector<Vec3>& f);

}  // namespace rkpm::rk
