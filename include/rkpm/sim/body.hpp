// One deformable body: its particle cloud, the RK operators built once on the
// reference configuration, its material, and its state.
//
// State is stored as flat arrays per particle. The kinematic unknowns are the
// generalized displacements d_I of the RK approximation; the physical displacement
// at a particle is u(X_J) = sum_I Psi_I(X_J) d_I (see `physical_displacement`).
// x_I = X_I + d_I, the generalized (nodal) positions, are not stored: nodal_position
// forms them where they are read. The surface and contact terms act at the physical
// points X_J + u(X_J) (physical_point), which differ from x_J by O(h^2) for smooth fields.
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/par/ghost_exchange.hpp"
#include "rkpm/particles/cloud.hpp"
#include "rkpm/rk/nodal_integration.hpp"
#include "rkpm/rk/row_scatter.hpp"
#include "rkpm/rk/stabilization.hpp"
#include "rkpm/sim/director_field.hpp"
#include "rkpm/sim/essential_bc.hpp"

// Generated from src/materials/catalog.def: each model's body_material.hpp.
#include "materials/body_materials.hpp"

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace rkpm::sim {

namespace detail {
// std::variant of the types after the leading void: lets an X-macro list write
// ", Type" for every entry.
template <class Void, class... Models>
struct VariantAfterVoid {
  using type = std::variant<Models...>;
};
}  // namespace detail

// What a body holds of its constitutive model: one alternative per model of the
// material catalog (src/materials/catalog.def), each materials::<model>::BodyMaterial.
// Every alternative has the same interface (docs/theory/materials.md), so the per-step
// functions below dispatch once per body with std::visit and call the model's inline
// kernel per point: no virtual call per particle.
//   static constexpr bool needs_director;  the body carries a DirectorField
//   Mat3 first_piola(Index L, const Mat3& F, const Mat3& grad_h, Mat3* frank_flux,
//                    const DirectorField* director) const;
//   double energy(Index L, const Mat3& F, const DirectorField* director) const;
//   double wave_speed(Index L, const Mat3& F, const DirectorField* director, double rho0) const;
//   double shear_modulus(Index L) const;
//   std::size_t state_bytes() const;       its per-point arrays (memory accounting)
using Material = detail::VariantAfterVoid<void
#define RKPM_MATERIAL(model) , materials::model::BodyMaterial
#include "materials/catalog.def"
#undef RKPM_MATERIAL
                                          >::type;

struct Body {
  std::string name;
  int id = 0;
  particles::Cloud cloud;
  double density = 0.0;                // reference density rho0 [kg/m^3]

  // The RK approximation is not kept: its kd-tree and supports (a share of the peak
  // memory per particle that docs/verification/performance.md measures) are needed only
  // to build operators. approximation(body) rebuilds it, the
  // same bits, for the terms that build operators of their own and for nested iteration.
  rk::RKSettings rk_settings;
  rk::FacetRule cell_quadrature = rk::FacetRule::Corners;  // of the gradient operator and surface terms
  rk::GradientOperator gradient;            // smoothed gradients b_I(X_L), weights V_L
  rk::NodalInterpolation interpolation;     // Psi_I(X_J)
  rk::Stabilization stabilization;          // removes the spurious modes of nodal integration
  double stabilization_energy = 0.0;        // at the last force evaluation [J]
  std::vector<double> mass;                 // lumped: rho0 V_I [kg]; what gravity and centroids weigh
  std::vector<double> inertia;              // the mass the integrator moves [kg]: = mass, or heavier where
                                            // a relaxation scales it (scale_inertia)
  std::vector<double> spacing;              // shortest mesh edge at each particle [m]

  std::vector<Vec3> d, v;                   // generalized displacement and velocity
                                            // (the nodal position X + d is not stored:
                                            // nodal_position recomputes it, the same bits)
  std::vector<Vec3> force;                  // total force of this step [N]
  std::vector<Mat3> F;                      // per integration point; the stress is not kept
                                            // (first_piola_at recomputes it for output)
  rk::RowScatter force_scatter;             // scratch of the force pass (per-thread buffers)
  rk::RowScatter point_force_scatter;       // scratch of add_point_forces (planned on first use)

  Material material;
  std::optional<DirectorField> director;
  EssentialBC constraints;

  // Distributed runs (par/partition.hpp): this rank owns particles and rows
  // [owned_begin(), owned_end()); the arrays above keep every particle's slot, and those
  // outside the range hold current values only for the ghosts (par/ghost_exchange.hpp),
  // which the force pass pulls from their owners. One rank owns everything.
  par::GhostExchange ghosts;               // built only when the run has more than one rank
  par::GhostExchange output_halo;          // distributed: the nodes of this rank's output cells it does not own
  std::vector<std::int64_t> original_id;   // distributed: each particle's id in a one-rank run
  bool distributed() const { return ghosts.built(); }
  Index owned_begin() const { return distributed() ? ghosts.begin() : 0; }
  Index owned_end() const { return distributed() ? ghosts.end() : static_cast<Index>(size()); }

  Body() = default;
  Body(const Body&) = delete;
  Body& operator=(const Body&) = delete;

  std::size_t size() const { return cloud.size(); }
};

// x_I = X_I + d_I, the nodal (generalized) position; the particle's physical position is
// physical_point.
inline Vec3 nodal_position(const Body& body, Index I) { return body.cloud.X[I] + body.d[I]; }

// a_I = f_I / inertia_I from the forces of the last evaluation (not stored: it is read
// where the integrator needs it).
inline Vec3 acceleration(const Body& body, Index I) { return body.force[I] / body.inertia[I]; }

// The body's RK approximation over its reference cloud (kd-tree and supports), built
// from body.rk_settings: the same on every call. It refers to body.cloud.X.
rk::RKApproximation approximation(const Body& body);

// The body's particles in their one-rank numbering (the identity on one rank): a sum over
// every particle taken in this order has the same bits for any rank count, as the
// quantities derived from whole-body sums must (a centroid, a mean modulus).
std::vector<Index> one_rank_order(const Body& body);

// F at every integration point, the director gradient where the Frank term needs it,
// and body.force = -f_int (the internal force) from the first Piola-Kirchhoff stress,
// which is used and dropped row by row (72 bytes per point not stored).
// Distributed: at the points this rank owns, after pulling the ghosts' displacements
// (and directors) and before returning the ghosts' force contributions to their owners;
// body.force is then complete at the owned particles.
void compute_internal_forces(Body& body);

// F at this rank's integration points from the current displacements, and nothing else:
// a third of a force pass (the gather alone). The Newton-Krylov finish carries the
// director to new coordinates with it before their force pass.
void update_deformation_gradients(Body& body);

// The first Piola-Kirchhoff stress at point L from the stored F (and Grad_X h) and the
// current director: what output reports. After a step it is the stress of the state the
// frame shows (the director has moved since the force pass, at fixed positions).
Mat3 first_piola_at(const Body& body, Index L);

// Stored (passive) energy sum_L V_L W(F_L) [J]; active stress is not stored energy.
// Distributed: this rank's share (its owned points); the caller sums over the ranks.
double strain_energy(const Body& body);

// Physical displacement u(X_J) = sum_I Psi_I(X_J) d_I at every particle.
void physical_displacement(const Body& body, std::vector<Vec3>& u);

// Physical position p_J = X_J + u(X_J) of one particle (X + d for a body without RK
// operators, as in some tests): where contact and surface terms act.
inline Vec3 physical_point(const Body& body, Index J) {
  if (body.interpolation.row_offset.empty()) return nodal_position(body, J);
  return body.cloud.X[J] + rk::interpolate(body.interpolation, body.d, J);
}

// Current outward unit normals of the boundary particles (area-weighted over the
// boundary faces at the generalized positions x), indexed like cloud.boundary_particles.
void current_boundary_normals(const Body& body, std::vector<Vec3>& normals);

// The deformation gradient at the start of a step (DirectorField::F_start), from which
// the director update takes the step's motion. Called before the step moves the body.
void hold_step_start(Body& body);

// Work of the active stress (Eq. 1) at this rank's points along the motion from F_from
// (per point) to the current F, at the current director: -sum_L V_L int P_a : dF by the
// trapezoidal rule in F [J]. 0 without activity. LCE bodies only.
double active_work_since(const Body& body, const std::vector<Mat3>& F_from);

// Director evolution over dt (Eq. 5-8: Allen-Cahn relaxation, the co-rotational rate
// of Eq. 7 with the step's velocity gradient (F - F_start) / dt F^-1, renormalisation to unit length, and
// h = current outward normal on the surface when anchored). LCE bodies only.
// Distributed: at this rank's particles, and the DirectorStep is this rank's share
// (the ghost layer holds the nodes of the boundary faces the normals need).
struct DirectorStep {
  double active_work = 0.0;    // work of the active stress (Eq. 1) over the step, -sum_L V_L int P_a : dF [J]
  double energy_change = 0.0;  // change of the stored energy by the director update at fixed F [J]:
                               // relaxation dissipates it, the anchoring (Eq. 8) may add to it
};
DirectorStep advance_director(Body& body, double dt);

// How far the director is from its own equilibrium, where Eq. 5 at rest asks that the
// part of dF/dh across h vanish: the largest |(I - h h^T) dF/dh| over mu at this rank's
// particles off the anchored surface, from the current state (the Frank divergence of
// the last force evaluation). Dimensionless (the molecular field over the shear
// modulus); at rest it is |dh/dt| / (L mu). Measured whatever L, a held director (L = 0)
// too; 0 for a body without a director.
double director_residual(const Body& body);

// Div_X of the Frank flux at every particle, from the state of the last force pass
// (F, h and Grad_X h), for a body whose pass does not track it (DirectorField::
// frank_divergence_tracked); one process only (a distributed body always tracks it).
void frank_divergence(const Body& body, std::vector<Vec3>& divergence);

// Whether the body's director relaxes by Eq. 5 (an LCE with L > 0 that evolves): the
// only reader of the Frank divergence in a step.
bool director_relaxes(const Body& body);

// The largest step at which the explicit director update (Eq. 5-7) is stable at the
// current state: min over this rank's particles of 2 / (L director_stiffness); infinity
// when the director does not evolve. A mobility high enough to bind here would otherwise
// make the director swing from step to step (its length is renormalised, so nothing
// diverges: the run just never settles).
double director_stable_dt(const Body& body);

// The body's reference stiffness, defined once: the small-strain shear modulus mu of
// the material at integration point (= particle) L [Pa]. The stabilization's
// stiffness scale and the contact stiffness law (eps_J = eps mu_J / mu_ref) use it
// per point.
double shear_modulus(const Body& body, Index L);
// Its volume-weighted mean over the body, sum_I V_I mu_I / sum_I V_I [Pa]: the scale
// of the relaxation criterion and the contact law's default mu_ref. For a graded
// substrate it does not depend on which particle comes first.
double mean_shear_modulus(const Body& body);

// Largest stable time step of the body's material: min_I spacing_I / c_I sqrt(inertia_I / mass_I)
// (the particle's own wave step, lengthened by its mass scaling).
// Distributed: over this rank's particles.
double material_stable_dt(const Body& body);

// Each particle's own wave step spacing_I / c_I at the current state, without mass scaling [s].
void particle_wave_steps(const Body& body, std::vector<double>& steps);

// Mass scaling (relaxation only: the masses of a static problem are free): every particle
// whose wave step (`steps`, from particle_wave_steps) is below `target` gets the inertia
// mass_I (target / step_I)^2, so that its own step reaches the target; the others keep
// their mass. Dynamic relaxation in the sense of Underwood (1983): the equilibrium does
// not depend on the masses, the number of steps to reach it does.
void scale_inertia(Body& body, double target, const std::vector<double>& steps);

}  // namespace rkpm::sim
