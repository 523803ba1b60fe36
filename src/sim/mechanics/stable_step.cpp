#include "rkpm/sim/stable_step.hpp"

#include "rkpm/common/split_mix64.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace rkpm::sim {

namespace {

// The forces of every body at its present displacement, transformed by its essential
// boundary conditions: what the integrator's force stage leaves in Body::force.
void transformed_forces(World& world) {
  compute_forces(world);
  for (auto& bp : world.bodies) bp->constraints.transform_forces(bp->force);
}

// sum over every body of |y_I|^2 at the particles this rank owns, each body's sum from
// zero, reduced over the ranks, and added in body order (see kinetic_energy in world.cpp).
double squared_norm(const World& world, const std::vector<std::vector<Vec3>>& y) {
  ExactSum total;  // exact: the same bits on any thread and rank count
  for (std::size_t b = 0; b < y.size(); ++b) {
    const Body& body = *world.bodies[b];
#pragma omp parallel for schedule(static) reduction(+ : total)
    for (Index i = body.owned_begin(); i < body.owned_end(); ++i) total.add(y[b][i].squaredNorm());
  }
  return world.comm->sum(total);
}

// Zeroes the components the essential boundary conditions hold.
void drop_constrained(const Body& body, std::vector<Vec3>& y) {
  if (body.constraints.empty()) return;
  for (std::size_t i = 0; i < y.size(); ++i)
    for (int axis = 0; axis < 3; ++axis)
      if (body.constraints.constrained(static_cast<Index>(i), axis)) y[i][axis] = 0.0;
}

}  // namespace

FrequencyEstimate largest_frequency(World& world, int max_iterations, double tolerance) {
  const std::size_t nb = world.bodies.size();
  std::vector<std::vector<Vec3>> d0(nb), kept_force(nb), f0(nb), y(nb);
  double shortest_spacing = std::numeric_limits<double>::infinity();
  SplitMix64 random(0x5eed);
  for (std::size_t b = 0; b < nb; ++b) {
    const Body& body = *world.bodies[b];
    d0[b] = body.d;
    kept_force[b] = body.force;
    // The start vector is drawn in the one-rank numbering: every rank count iterates alike.
    y[b].resize(body.size());
    for (Index i : one_rank_order(body))
      y[b][i] = Vec3(random.symmetric_unit(), random.symmetric_unit(), random.symmetric_unit());
    drop_constrained(body, y[b]);
    for (double h : body.spacing) shortest_spacing = std::min(shortest_spacing, h);
  }
  // A forward difference: a step of a millionth of the shortest spacing keeps the
  // truncation error (relative, of the order of the step over the spacing) and the
  // round-off (the force's round-off over the force change) both near 1e-6 and below.
  const double delta = 1e-6 * shortest_spacing;
  // The forces at the state itself, evaluated here rather than taken from Body::force:
  // within a step the materials' state moves after the forces (integrator.cpp), so the
  // kept forces belong to the previous state and their difference to the perturbed ones
  // would not be the tangent's.
  transformed_forces(world);
  for (std::size_t b = 0; b < nb; ++b) f0[b] = world.bodies[b]->force;

  FrequencyEstimate estimate;
  double previous = 0.0, norm_y = std::sqrt(squared_norm(world, y));
  std::vector<Vec3> scratch_velocity;
  for (int it = 0; it < max_iterations && norm_y > 0.0; ++it) {  // norm_y = 0: nothing can move
    // The displacement direction u = M^-1/2 y / |y|, scaled so that its largest
    // particle displacement is delta.
    // Distributed: over the owned particles (the forces pull the ghosts' d), reduced.
    double largest = 0.0;
    for (std::size_t b = 0; b < nb; ++b) {
      const Body& body = *world.bodies[b];
      for (Index i = body.owned_begin(); i < body.owned_end(); ++i)
        largest = std::max(largest, y[b][i].norm() / std::sqrt(body.inertia[i]));
    }
    const double scale = delta / world.comm->max(largest);
    for (std::size_t b = 0; b < nb; ++b) {
      Body& body = *world.bodies[b];
#pragma omp parallel for schedule(static)
      for (Index i = body.owned_begin(); i < body.owned_end(); ++i)
        body.d[i] = d0[b][i] + scale * y[b][i] / std::sqrt(body.inertia[i]);
      scratch_velocity.assign(body.size(), Vec3::Zero());
      body.constraints.impose(body.d, scratch_velocity);
    }
    transformed_forces(world);
    ++estimate.iterations;
    // A y = M^-1/2 K M^-1/2 y = -(f(d0 + scale M^-1/2 y) - f0) / (scale sqrt(m)).
    for (std::size_t b = 0; b < nb; ++b) {
      const Body& body = *world.bodies[b];
#pragma omp parallel for schedule(static)
      for (Index i = body.owned_begin(); i < body.owned_end(); ++i)
        y[b][i] = -(body.force[i] - f0[b][i]) / (scale * std::sqrt(body.inertia[i]));
      drop_constrained(body, y[b]);
    }
    // |A y| / |y| tends to the dominant |lambda| and is not below the Rayleigh quotient
    // of a symmetric tangent: the conservative of the two measures.
    const double norm_ay = std::sqrt(squared_norm(world, y));
    if (!(norm_ay > 0.0)) {  // no stiffness along y (or a force that is not finite)
      previous = 0.0;
      break;
    }
    const double lambda = norm_ay / norm_y;
    // The next direction, normalised (lambda^k would overflow within a few tens of
    // iterations).
    for (auto& body_y : y)
      for (auto& v : body_y) v /= norm_ay;
    norm_y = 1.0;
    if (it > 0 && std::abs(lambda - previous) <= tolerance * lambda) {
      previous = lambda;
      break;
    }
    previous = lambda;
  }
  estimate.omega_max = previous > 0.0 ? std::sqrt(previous) : 0.0;

  // Back to the state of the call: the displacements, and everything the forces
  // derive from them (positions, deformation gradients, the terms' own data).
  for (std::size_t b = 0; b < nb; ++b) world.bodies[b]->d = d0[b];
  transformed_forces(world);
  for (std::size_t b = 0; b < nb; ++b) world.bodies[b]->force = kept_force[b];
  return estimate;
}

}  // namespace rkpm::sim
