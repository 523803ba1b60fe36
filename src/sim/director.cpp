// Director evolution of liquid-crystal-elastomer bodies (seed Eq. 5-8).
#include "rkpm/sim/body.hpp"

#include "materials/lce/director_point.hpp"

#include <algorithm>
#include <limits>

namespace rkpm::sim {

namespace {
using materials::lce::director_point;

// The director's share of the passive energy, sum_L V_L W_h(F_L, h_L) over this rank's
// points (LiquidCrystalElastomer::director_energy): at fixed F and Grad h, the rest of
// sum_L V_L W does not change when the director does, so the difference of two of
// these is the update's change of the passive energy.
double director_energy(const Body& body, const materials::LiquidCrystalElastomer& model) {
  const DirectorField& dir = *body.director;
  ExactSum total;
#pragma omp parallel for schedule(static) reduction(+ : total)
  for (Index L = body.owned_begin(); L < body.owned_end(); ++L)
    total.add(body.gradient.weight[L] * model.director_energy(body.F[L], dir.h[L], dir.h0[L]));
  return total.value();
}
}  // namespace

void frank_divergence(const Body& body, std::vector<Vec3>& divergence) {
  const DirectorField& dir = *body.director;
  const auto& model = std::get<materials::lce::BodyMaterial>(body.material).model;
  const auto n = static_cast<Index>(body.size());
  std::vector<Mat3> flux(body.size());
#pragma omp parallel for schedule(static)
  for (Index L = 0; L < n; ++L) flux[L] = model.frank_flux(body.F[L], director_point(dir, L));
  // The same weak form as the force pass: sum_L V_L flux_L b_I(X_L) = -V_I Div_X(flux)(X_I).
  rk::internal_forces(body.gradient, flux, divergence);
#pragma omp parallel for schedule(static)
  for (Index I = 0; I < n; ++I) divergence[I] /= -body.cloud.volume[I];
}

double director_residual(const Body& body) {
  if (!body.director) return 0.0;
  const auto& model = std::get<materials::lce::BodyMaterial>(body.material).model;
  const DirectorField& dir = *body.director;
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

bool director_relaxes(const Body& body) {
  if (!body.director || !body.director->evolve) return false;
  return std::get<materials::lce::BodyMaterial>(body.material).model.mobility > 0.0;
}

double director_stable_dt(const Body& body) {
  double dt = std::numeric_limits<double>::infinity();
  if (!director_relaxes(body)) return dt;
  const auto& model = std::get<materials::lce::BodyMaterial>(body.material).model;
  const DirectorField& dir = *body.director;
#pragma omp parallel for schedule(static) reduction(min : dt)
  for (Index I = body.owned_begin(); I < body.owned_end(); ++I)
    dt = std::min(dt, 2.0 / (model.mobility * model.director_stiffness(body.F[I], dir.h0[I], body.spacing[I])));
  return dt;
}

void hold_step_start(Body& body) {
  DirectorField& dir = *body.director;
#pragma omp parallel for schedule(static)
  for (Index L = body.owned_begin(); L < body.owned_end(); ++L) dir.F_start[L] = body.F[L];
}

double active_work_since(const Body& body, const std::vector<Mat3>& F_from) {
  const auto& material = std::get<materials::lce::BodyMaterial>(body.material);
  const auto& model = material.model;
  if (model.zeta == 0.0) return 0.0;
  const DirectorField& dir = *body.director;
  double active = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : active)
  for (Index L = body.owned_begin(); L < body.owned_end(); ++L) {
    // The active stress is part of the internal force -sum_L V_L P_a b_I, so along a
    // motion it puts in -sum_L V_L int P_a : dF, here by the trapezoidal rule in F at the
    // current director (the one the motion's forces saw).
    const Mat3 P_a_sum = model.first_piola_active(F_from[L], dir.h[L]) + model.first_piola_active(body.F[L], dir.h[L]);
    active -= 0.5 * body.gradient.weight[L] * material.activity_at(L) * (P_a_sum.cwiseProduct(body.F[L] - F_from[L])).sum();
  }
  return active;
}

DirectorStep advance_director(Body& body, double dt) {
  // Only the LCE carries a director (its BodyMaterial::needs_director).
  const auto& material = std::get<materials::lce::BodyMaterial>(body.material);
  const auto& model = material.model;
  DirectorField& dir = *body.director;
  const Index begin = body.owned_begin(), end = body.owned_end();

  // The step's motion: F is linear in the displacements, so F - F_start = sum_I (d_I -
  // d_I,start) (x) b_I, the deformation the body made over the step (drift, the supports'
  // advance, a FIRE 2.0 step back), and (F - F_start) / dt its rate (the smoothed
  // velocity gradient in the reference frame). No gather over the rows: their sweep over
  // the velocities would be a second pass over the operator, the work of the force
  // pass's gather of F again (docs/verification/relaxation.md measures the saving).
  DirectorStep result;
  const double energy_before = director_energy(body, model);
  result.active_work = active_work_since(body, dir.F_start);

  if (dir.evolve) {
#pragma omp parallel for schedule(static)
    for (Index I = begin; I < end; ++I) {
      const materials::DirectorPoint p = director_point(dir, I);
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
    current_boundary_normals(body, dir.normals);
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
  result.energy_change = director_energy(body, model) - energy_before;
  return result;
}

}  // namespace rkpm::sim
