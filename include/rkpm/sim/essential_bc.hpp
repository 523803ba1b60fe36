// Essential (displacement) boundary conditions by the transformation method.
//
// RK shape functions do not interpolate: the physical displacement at particle J is
// u(X_J) = sum_I Psi_I(X_J) d_I, not the generalized coordinate d_J. Fixing d_J would
// impose the condition only approximately and break the patch test. Instead, for
// every constrained component (particle J in the set C of one axis) we impose
//     sum_I Lambda_JI d_I = ubar_J,   Lambda_JI = Psi_I(X_J),
// and eliminate the constrained coordinates: d_C = Lambda_CC^-1 (ubar_C - Lambda_CF d_F).
// Virtual displacements then satisfy delta d_C = -Lambda_CC^-1 Lambda_CF delta d_F, so the
// force that drives the free coordinates is the transformed one
//     f~_F = f_F - Lambda_CF^T Lambda_CC^-T f_C,
// and the lumped mass of the free coordinates is kept (the usual lumped
// transformation, Chen et al. 1996). Lambda_CC depends only on the set C, so the axes
// that constrain the same particles (all three, for a fixed surface) share one
// factorization, built once, and one solve with a column per axis: a step costs two
// sparse solves per distinct set (one for the displacements and velocities together,
// one for the reactions).
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/par/comm.hpp"
#include "rkpm/rk/nodal_integration.hpp"

#include <array>
#include <memory>
#include <vector>

namespace rkpm::sim {

struct ConstrainedComponent {
  Index particle;
  int axis;
  double velocity;  // prescribed velocity of u(X_J) along axis [m/s]; 0 = fixed
};

class EssentialBC {
 public:
  EssentialBC();
  ~EssentialBC();
  EssentialBC(EssentialBC&&) noexcept;
  EssentialBC& operator=(EssentialBC&&) noexcept;

  // `interp` gives Psi_I(X_J); `d` the generalized displacements at set-up (their
  // physical values at the constrained particles become the initial targets).
  EssentialBC(const rk::NodalInterpolation& interp, std::vector<ConstrainedComponent> components,
              const std::vector<Vec3>& d);

  bool empty() const { return components_ == 0; }
  std::size_t size() const { return components_; }

  // Replaces the constrained components of f by zero and the free ones by the
  // transformed force f~_F. Returns the work rate of the reactions, sum R . ubar_dot [W].
  double transform_forces(std::vector<Vec3>& f) const;

  // Advances the targets by their prescribed velocities over dt, then sets d_C and v_C
  // from the free coordinates so that the constraints hold exactly.
  void advance(double dt, std::vector<Vec3>& d, std::vector<Vec3>& v);

  // Re-imposes the constraints without advancing time (after set-up or restart).
  void impose(std::vector<Vec3>& d, std::vector<Vec3>& v) const;

  // Distributed runs: the constrained rows couple particles of several ranks. The
  // system Lambda_CC is cut into parts that do not depend on the rank count, coupled
  // through a small separator (sim/integration/constraint_solver.hpp): the ranks take
  // equal runs of the parts, and every rank solves the separator's system, so a rank's
  // share of the solve is its share of the parts, and every rank count gives the
  // one-process bits. The work per row is split too:
  // each rank forms the free part Lambda_CF d of the rows of the constrained particles
  // it owns (pulling the columns it does not own from their owners), and the ranks
  // gather those sums (par/shared_particles.hpp), so the solve reads the same values
  // everywhere; the reactions' transfer -Lambda_CF^T r is applied by each rank to the
  // columns it owns. f at the constrained particles is gathered before that solve.
  void distribute(const par::Comm& comm, const std::vector<Index>& offset);

  // How far the transformation moves the constrained coordinates when the free ones
  // move: the largest |d_C| over a few fixed patterns of free motions of size 1
  // (d_C = -Lambda_CC^-1 Lambda_CF d_F). About 0.1 on a lattice; on an unstructured
  // tetrahedral cloud Lambda_CC can be near singular and the value reach hundreds. The
  // free coordinates then drive constrained ones whose mass the lumped transformation
  // does not count, at frequencies the wave-speed step does not see (a 10 x 10 x 4 um
  // Gmsh box at mesh_size 1 um with a fixed base: 853, and 2 / omega_max is 0.31 x the
  // wave-speed step). Computed at construction, on every rank alike; 0 without constraints.
  double amplification() const { return amplification_; }

  // Particle/axis pairs that are constrained, for masks in the integrator.
  bool constrained(Index particle, int axis) const;

  // Targets, for checkpoints: the constrained displacements at the current time.
  std::vector<double> targets() const;
  void set_targets(const std::vector<double>& t);

 private:
  struct Group;
  std::vector<std::unique_ptr<Group>> groups_;  // by their lowest axis
  std::vector<std::array<char, 3>> mask_;
  std::size_t components_ = 0;
  double amplification_ = 0.0;
};

}  // namespace rkpm::sim
