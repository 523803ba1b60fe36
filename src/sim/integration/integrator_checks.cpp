// The integrator's checks after each step: a state that has gone wrong (non-finite,
// inverted, runaway, or a term's diagnosis) and the relaxation's convergence criteria.
#include "rkpm/sim/integrator.hpp"

#include "rkpm/sim/body_state.hpp"
#include "rkpm/sim/stable_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rkpm::sim {

// Blow-up (throws BlowUp with the diagnosis), then the relaxation measures.
void Integrator::check(double kinetic_of_motion) {
  check_state();
  update_convergence(kinetic_of_motion);
}

// The kinetic measure is taken from the velocities the step produced, before FIRE mixes
// or stops them: a FIRE stop (P <= 0) zeroes every velocity, and measured after it the
// kinetic criterion would hold at every stop, so a run creeping along a soft mode would
// be declared converged at the first stop where the residual happens to be below its
// tolerance (docs/theory/relaxation.md, "When the run stops").
void Integrator::update_convergence(double kinetic_of_motion) {
  double residual = 0.0;
  for (std::size_t k = 0; k < world_.bodies.size(); ++k) {
    const Body& b = *world_.bodies[k];
    const double mu = body_shear_modulus_[k];
#pragma omp parallel for schedule(static) reduction(max : residual)
    for (Index i = b.owned_begin(); i < b.owned_end(); ++i)
      residual = std::max(residual, b.force[i].norm() / (mu * std::cbrt(b.cloud.volume[i] * b.cloud.volume[i])));
  }
  residual_ = world_.comm->max(residual);
  kinetic_measure_ = kinetic_of_motion / reference_energy_;
  // A pass over the particles every step, only when the scene asks for the materials'
  // state in the stop.
  if (settings_.relax_state_tol > 0.0) state_measure_ = state_residual();
}

double Integrator::state_residual() const {
  double largest = 0.0;
  for (const auto& b : world_.bodies) largest = std::max(largest, sim::state_residual(*b));
  return world_.comm->max(largest);
}

bool Integrator::converged() const {
  if (!(residual_ < settings_.relax_force_tol && kinetic_measure_ < settings_.relax_velocity_tol)) return false;
  return !(settings_.relax_state_tol > 0.0) || state_measure_ < settings_.relax_state_tol;
}

// Every rank checks its own particles; the lowest rank that finds a failure states the
// diagnosis and every rank throws it (one voice, the same exit on every rank).
void Integrator::check_state() {
  enum Reason { None = 0, NonFinitePosition, NonFiniteVelocity, NonFiniteForce, Inverted, Runaway };
  const double limit2 = settings_.domain_size * settings_.domain_size;
  double min_J = std::numeric_limits<double>::infinity();
  std::string diagnosis;
  for (const auto& bp : world_.bodies) {
    const Body& b = *bp;
    Index first = std::numeric_limits<Index>::max();
#pragma omp parallel for schedule(static) reduction(min : first, min_J)
    for (Index i = b.owned_begin(); i < b.owned_end(); ++i) {
      const double J = b.F[i].determinant();
      min_J = std::min(min_J, J);
      const Vec3 x = nodal_position(b, i);
      // A force that overflowed (an extreme modulus, activity or load) is caught here,
      // before it reaches a position or any output.
      const bool bad = !x.allFinite() || !b.v[i].allFinite() || !b.force[i].allFinite() || !(J > 0.0) ||
                       (x - centre_).squaredNorm() > limit2;
      if (bad) first = std::min(first, i);
    }
    if (first == std::numeric_limits<Index>::max()) continue;
    const double J = b.F[first].determinant();
    const Vec3 x = nodal_position(b, first);
    const Reason why = !x.allFinite()                ? NonFinitePosition
                       : !b.v[first].allFinite()     ? NonFiniteVelocity
                       : !b.force[first].allFinite() ? NonFiniteForce
                       : !(J > 0.0)                  ? Inverted
                                                     : Runaway;
    const char* what[] = {"", "position is not finite", "velocity is not finite",
                          "the force is not finite (it overflowed: an extreme modulus, activity, load or state)",
                          "the deformation gradient is inverted or degenerate (J <= 0 or NaN)",
                          "the particle left the domain (runaway motion)"};
    const Vec3 X = b.cloud.X[first];
    // The particle's id in a one-rank run of the scene, whatever the rank count.
    const std::int64_t id = one_rank_id(b, first);
    diagnosis = fmt::format(
        "unstable at step {} (t = {:.6g} s, dt = {:.3g} s): body '{}', particle {} (reference position "
        "({:.4g}, {:.4g}, {:.4g}) m, current ({:.4g}, {:.4g}, {:.4g}) m): {}; J = {:.4g}, |v| = {:.4g} m/s. "
        "The stable step estimate is {:.3g} s.",
        world_.step, world_.time, dt(), b.name, id, X.x(), X.y(), X.z(), x.x(), x.y(), x.z(), what[why], J, b.v[first].norm(), stable_dt());
    break;
  }
  diagnosis = world_.comm->first_error(diagnosis);
  for (const auto& term : world_.terms) {
    if (!diagnosis.empty()) break;
    if (const std::string broken = term->diagnose(world_); !broken.empty())
      diagnosis = fmt::format("stopped at step {} (t = {:.6g} s): {}", world_.step, world_.time, broken);
  }
  if (!diagnosis.empty()) throw BlowUp(diagnosis);
  min_J_ = world_.comm->min(min_J);
}

}  // namespace rkpm::sim
