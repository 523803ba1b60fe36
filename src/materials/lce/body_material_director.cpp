// The director as the LCE material's per-point state (seed Eq. 5-8): the hooks of
// materials/state_hooks.hpp that the integrator, the checkpoint, the output and nested
// iteration call. Compiled into rkpm_sim.
#include "materials/lce/body_material.hpp"

#include "rkpm/sim/body.hpp"
#include "rkpm/sim/state_record.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rkpm::materials::lce {

namespace {
// The director's share of the passive energy, sum_L V_L W_h(F_L, h_L) over this rank's
// points (LiquidCrystalElastomer::director_energy): at fixed F and Grad h, the rest of
// sum_L V_L W does not change when the director does, so the difference of two of
// these is the update's change of the passive energy.
ExactSum director_energy(const sim::Body& body, const BodyMaterial& m) {
  const DirectorField& dir = m.director;
  ExactSum total;
#pragma omp parallel for schedule(static) reduction(+ : total)
  for (Index L = body.owned_begin(); L < body.owned_end(); ++L)
    total.add(body.gradient.weight[L] * m.model.director_energy(body.F[L], dir.h[L], dir.h0[L]));
  return total;
}

// Whether the director relaxes by Eq. 5 (L > 0 and it evolves): the only reader of the
// Frank divergence in a step.
bool relaxes(const BodyMaterial& m) { return m.director.evolve && m.model.mobility > 0.0; }
}  // namespace

std::size_t BodyMaterial::state_bytes() const {
  const DirectorField& d = director;
  return activity.size() * sizeof(double) +
         (d.h.size() + d.h0.size() + d.rate.size() + d.frank_divergence.size() + d.normals.size()) * sizeof(Vec3) +
         (d.F_start.size() + d.grad_h.size() + d.frank_flux.size()) * sizeof(Mat3);
}

CoupledField BodyMaterial::coupled_field() {
  if (!director.frank) return {};
  CoupledField c;
  c.values = &director.h;
  c.gradient = &director.grad_h;
  if (director.frank_divergence_tracked) {
    c.flux = &director.frank_flux;
    c.divergence = &director.frank_divergence;
  }
  return c;
}

// The Frank divergence costs a scatter per row: made only for a reader in the step (a
// distributed body keeps it, for residual()'s sake).
void BodyMaterial::prepare(sim::Body& /*body*/, const StateDemand& demand) {
  director.frank_divergence_tracked = relaxes(*this) || demand.residual_every_step || demand.distributed;
}

// F at the start of the step, from which end_step takes the step's motion.
void BodyMaterial::begin_step(sim::Body& body) {
#pragma omp parallel for schedule(static)
  for (Index L = body.owned_begin(); L < body.owned_end(); ++L) director.F_start[L] = body.F[L];
}

// Work of the active stress (Eq. 1) at this rank's points along the motion from F_from
// (per point) to the current F, at the current director: -sum_L V_L int P_a : dF by the
// trapezoidal rule in F [J]. 0 without activity.
StateUpdate BodyMaterial::work_since(const sim::Body& body, const std::vector<Mat3>& F_from) const {
  StateUpdate result;
  if (model.zeta == 0.0) return result;
  double active = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : active)
  for (Index L = body.owned_begin(); L < body.owned_end(); ++L) {
    // The active stress is part of the internal force -sum_L V_L P_a b_I, so along a
    // motion it puts in -sum_L V_L int P_a : dF, here by the trapezoidal rule in F at the
    // current director (the one the motion's forces saw).
    const Mat3 P_a_sum =
        model.first_piola_active(F_from[L], director.h[L]) + model.first_piola_active(body.F[L], director.h[L]);
    active -= 0.5 * body.gradient.weight[L] * activity_at(L) * (P_a_sum.cwiseProduct(body.F[L] - F_from[L])).sum();
  }
  result.active_work = active;
  return result;
}

// Director evolution over dt (Eq. 5-8: Allen-Cahn relaxation, the co-rotational rate of
// Eq. 7 with the step's velocity gradient (F - F_start) / dt F^-1, renormalisation to
// unit length, and h = current outward normal on the surface when anchored).
// Distributed: at this rank's particles, and the update is this rank's share (the ghost
// layer holds the nodes of the boundary faces the normals need).
StateUpdate BodyMaterial::end_step(sim::Body& body, double dt) {
  DirectorField& dir = director;
  const Index begin = body.owned_begin(), end = body.owned_end();

  // The step's motion: F is linear in the displacements, so F - F_start = sum_I (d_I -
  // d_I,start) (x) b_I, the deformation the body made over the step (drift, the supports'
  // advance, a FIRE 2.0 step back), and (F - F_start) / dt its rate (the smoothed
  // velocity gradient in the reference frame). No gather over the rows: their sweep over
  // the velocities would be a second pass over the operator, the work of the force
  // pass's gather of F again (docs/verification/relaxation.md measures the saving).
  StateUpdate result = work_since(body, dir.F_start);
  result.energy_before = director_energy(body, *this);

  if (dir.evolve) {
#pragma omp parallel for schedule(static)
    for (Index I = begin; I < end; ++I) {
      const DirectorPoint p = director_point(dir, I);
      const Mat3 l = ((body.F[I] - dir.F_start[I]) / dt) * body.F[I].inverse();
      const Vec3 frank = dir.frank_divergence_tracked && dir.frank ? dir.frank_divergence[I] : Vec3::Zero();
      dir.rate[I] = model.director_rate(body.F[I], p, l, frank);
      const Vec3 h = dir.h[I] + dt * dir.rate[I];
      dir.h[I] = h / h.norm();  // Eq. 7 has a component along h: keep |h| = 1
    }
  }

  if (dir.anchored) {
    // Eq. 8: h = n on the surface. The director is nematic (h ~ -h), so keep the sign
    // closest to the current one: the inner wall of a shell, whose outward normal points
    // into the cavity, keeps the orientation continued from the outer surface.
    sim::current_boundary_normals(body, dir.normals);
    const auto& ids = body.cloud.boundary_particles;
    const auto nb = static_cast<Index>(ids.size());
#pragma omp parallel for schedule(static)
    for (Index k = 0; k < nb; ++k) {
      if (ids[k] < begin || ids[k] >= end) continue;  // another rank's particle
      const Vec3& nrm = dir.normals[k];
      Vec3& h = dir.h[ids[k]];
      h = h.dot(nrm) >= 0.0 ? nrm : Vec3(-nrm);
    }
  }
  result.energy_after = director_energy(body, *this);
  return result;
}

// The largest step at which the explicit director update (Eq. 5-7) is stable at the
// current state: min over this rank's particles of 2 / (L director_stiffness); infinity
// when the director does not evolve. A mobility high enough to bind here would otherwise
// make the director swing from step to step (its length is renormalised, so nothing
// diverges: the run just never settles).
double BodyMaterial::stable_dt(const sim::Body& body) const {
  double dt = std::numeric_limits<double>::infinity();
  if (!relaxes(*this)) return dt;
#pragma omp parallel for schedule(static) reduction(min : dt)
  for (Index I = body.owned_begin(); I < body.owned_end(); ++I)
    dt = std::min(dt, 2.0 / (model.mobility * model.director_stiffness(body.F[I], director.h0[I], body.spacing[I])));
  return dt;
}

bool BodyMaterial::evolves_in_time() const { return relaxes(*this); }

void BodyMaterial::frank_divergence(const sim::Body& body, std::vector<Vec3>& divergence) const {
  const auto n = static_cast<Index>(body.size());
  std::vector<Mat3> flux(body.size());
#pragma omp parallel for schedule(static)
  for (Index L = 0; L < n; ++L) flux[L] = model.frank_flux(body.F[L], director_point(director, L));
  // The same weak form as the force pass: sum_L V_L flux_L b_I(X_L) = -V_I Div_X(flux)(X_I).
  rk::internal_forces(body.gradient, flux, divergence);
#pragma omp parallel for schedule(static)
  for (Index I = 0; I < n; ++I) divergence[I] /= -body.cloud.volume[I];
}

// How far the director is from its own equilibrium, where Eq. 5 at rest asks that the
// part of dF/dh across h vanish: the largest |(I - h h^T) dF/dh| over mu at this rank's
// particles off the anchored surface, from the current state (the Frank divergence of
// the last force evaluation). Dimensionless (the molecular field over the shear
// modulus); at rest it is |dh/dt| / (L mu). Measured whatever L, a held director (L = 0)
// too.
double BodyMaterial::residual(const sim::Body& body) const {
  const DirectorField& dir = director;
  std::vector<Vec3> made;  // the Frank divergence, when the force pass does not track it
  if (dir.frank && !dir.frank_divergence_tracked) frank_divergence(body, made);
  const std::vector<Vec3>& divergence = dir.frank_divergence_tracked ? dir.frank_divergence : made;
  double largest = 0.0;
#pragma omp parallel for schedule(static) reduction(max : largest)
  for (Index I = body.owned_begin(); I < body.owned_end(); ++I) {
    // The anchored surface's director is set to the normal, not relaxed: its field is moot.
    if (dir.anchored && body.cloud.boundary_index[I] >= 0) continue;
    // From the state (F, h, Grad h and the Frank divergence of the last force
    // evaluation), so a held director is measured too.
    const Vec3 frank = dir.frank ? divergence[I] : Vec3::Zero();
    largest = std::max(largest, model.transverse_molecular_field(body.F[I], director_point(dir, I), frank).norm());
  }
  return largest / model.mu;
}

void BodyMaterial::save_state(sim::StateRecord& record, const std::string& prefix) const {
  record.put_vectors(prefix + "director", director.h);
}

void BodyMaterial::load_state(const sim::StateRecord& record, const std::string& prefix, const sim::Body& body) {
  director.h = record.vectors(prefix + "director", body.size());
  // The step keeps |h| = 1 (Eq. 7 renormalised): another length is a damaged file.
  for (std::size_t i = 0; i < body.size(); ++i)
    if (!(std::abs(director.h[i].norm() - 1.0) <= 1e-9))
      throw sim::StateError(fmt::format("body '{}' particle {} has a director of length {}, expected a unit vector",
                                        body.name, i, director.h[i].norm()));
}

std::vector<OutputField> BodyMaterial::output_fields() const {
  return {{"director", 3, director.h.empty() ? nullptr : director.h.front().data()}};
}

// The finer cloud's director from the coarser one's by the RK interpolation, made unit
// again. A director that interpolates to (nearly) nothing, where neighbours point
// opposite ways, keeps its initial value.
void BodyMaterial::transfer_state(const BodyMaterial& from, const VectorInterpolation& interpolate) {
  const std::vector<Vec3> h = interpolate(from.director.h);
  for (std::size_t J = 0; J < h.size(); ++J)
    if (h[J].norm() > 1e-3) director.h[J] = h[J].normalized();
}

}  // namespace rkpm::materials::lce
