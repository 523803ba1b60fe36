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
#include "rkpm/sim/essential_bc.hpp"

// Generated from src/materials/catalog.def: each model's body_material.hpp.
#include "materials/body_materials.hpp"

#include <memory>
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
//   Mat3 stress(Index L, const Mat3& F) const;          first Piola-Kirchhoff P at point L
//   double energy(Index L, const Mat3& F) const;        stored energy per reference volume
//   double wave_speed(Index L, const Mat3& F, double rho0) const;
//   double shear_modulus(Index L) const;
//   std::size_t state_bytes() const;                    its per-point arrays (memory accounting)
// and the state hooks of materials/state_hooks.hpp (a stateless model inherits them from
// materials::Stateless; body_state.hpp calls them). A model whose stress reads the
// gradient of a per-particle field (coupled_field, the LCE's Frank term) also has
//   Mat3 stress_and_flux(Index L, const Mat3& F, Mat3& flux) const;
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

  Material material;                        // with its per-point state (body_state.hpp)
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

// Particle i's id in a one-rank run of the scene (the identity on one rank): how
// messages and outputs name a particle whatever the rank count.
inline std::int64_t one_rank_id(const Body& body, Index i) {
  return body.original_id.empty() ? static_cast<std::int64_t>(i) : body.original_id[static_cast<std::size_t>(i)];
}

// The volume-weighted centre of the reference cloud, summed in the one-rank numbering:
// the same bits for any rank count (an initial stretch and a material's initial state
// read it, and a round-off difference would change what a particle at the centre gets).
Vec3 reference_centroid(const Body& body);

// F at every integration point (and the gradient of the material's coupled field, if
// it has one), and body.force = -f_int (the internal force) from the first
// Piola-Kirchhoff stress, which is used and dropped row by row (72 bytes per point not
// stored). Distributed: at the points this rank owns, after pulling the ghosts'
// displacements (and coupled field) and before returning the ghosts' force
// contributions to their owners; body.force is then complete at the owned particles.
void compute_internal_forces(Body& body);

// Plans the order of the force pass's scatter for the present thread count (and the
// body's ranks): called at set-up, once the body's operators and material state exist
// (the Integrator's constructor); the force pass plans again only when the thread count
// has changed since, or when no integrator set it up (tests that call it directly).
void plan_force_scatter(Body& body);

// F at this rank's integration points from the current displacements, and nothing else:
// a third of a force pass (the gather alone). The Newton-Krylov finish carries the
// material's state to new coordinates with it before their force pass.
void update_deformation_gradients(Body& body);

// The first Piola-Kirchhoff stress at point L from the stored F and the material's
// current state: what output reports. After a step it is the stress of the state the
// frame shows (the state has moved since the force pass, at fixed positions).
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
