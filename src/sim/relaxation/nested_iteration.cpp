#include "rkpm/sim/nested_iteration.hpp"

#include "clouds/catalog.hpp"
#include "rkpm/scene/resolution.hpp"
#include "rkpm/sim/body_state.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/integrator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <limits>
#include <ostream>

namespace rkpm::sim {

namespace {

// Sets the generalized displacements d of `body` so that its physical displacement
// sum_I Psi_I(X_J) d_I matches target[J] at every owned particle J. The RK shape
// functions do not interpolate (Psi_I(X_J) != delta_IJ), so d = target would give the
// finer cloud a smoothed copy of the coarser field: on the red-blood-cell scene that
// copy missed the field by percents of the largest displacement, moved the enclosed
// volume and the contact gaps with it, and the finer cloud spent a long time
// re-equilibrating (docs/theory/relaxation.md, "Nested levels"). Richardson's
// iteration d <- d + (target - N d) works because N is a sampled smoothing kernel that
// reproduces linear fields: the smooth part of the mismatch, which moves the shape,
// goes within a few sweeps (its eigenvalues of N are near 1); the rough part, which the
// kernel hardly sees, would take hundreds. So the sweeps stop when one of them removes
// less than a tenth of the largest mismatch (a sweep that makes it grow is undone), or
// when that is below 1e-6 of the largest target (a linear field: at once), or after
// `max_sweeps`. Then the supports' prescribed values are imposed, and the mismatch the
// body keeps is measured and returned (summary.json's transfer_sweeps and
// transfer_mismatch; docs/verification/relaxation.md gives them for the RBC ladder's
// levels).
Transfer match_physical_displacement(const par::Comm& comm, Body& body, const std::vector<Vec3>& target,
                                     int max_sweeps = 50) {
  const Index begin = body.owned_begin(), end = body.owned_end();
  const auto& N = body.interpolation;
  for (Index J = begin; J < end; ++J) body.d[J] = target[J];
  double largest = 0.0;
  for (Index J = begin; J < end; ++J) largest = std::max(largest, target[J].norm());
  largest = comm.max(largest);
  std::vector<Vec3> mismatch(body.size(), Vec3::Zero()), correction(body.size(), Vec3::Zero());
  // The largest |target - N d| over this rank's particles, all ranks' maximum; a particle
  // without an interpolation row keeps d = target (nothing to match).
  const auto measure = [&] {
    if (body.distributed()) body.ghosts.pull(body.d);
    double worst = 0.0;
#pragma omp parallel for schedule(static) reduction(max : worst)
    for (Index J = begin; J < end; ++J) {
      const bool has_row = N.row_offset.size() > static_cast<std::size_t>(J) + 1 && N.row_offset[J] < N.row_offset[J + 1];
      mismatch[J] = has_row ? Vec3(target[J] - rk::interpolate(N, body.d, J)) : Vec3::Zero();
      worst = std::max(worst, mismatch[J].norm());
    }
    return comm.max(worst);
  };
  Transfer done;
  double worst = measure();
  while (largest > 0.0 && worst > 1e-6 * largest && done.sweeps < max_sweeps) {
    for (Index J = begin; J < end; ++J) body.d[J] += (correction[J] = mismatch[J]);
    const double previous = worst;
    worst = measure();
    if (worst > previous) {  // a rough mode grew: keep the better d before this sweep
      for (Index J = begin; J < end; ++J) body.d[J] -= correction[J];
      break;
    }
    ++done.sweeps;
    if (worst > 0.9 * previous) break;  // stalled: what is left is the rough part
  }
  // The supports' prescribed values go on last, and the report is what the body keeps.
  std::fill(body.v.begin(), body.v.end(), Vec3::Zero());
  body.constraints.impose(body.d, body.v);
  if (largest > 0.0) done.mismatch = measure() / largest;
  return done;
}

// One body's state at the other body's particles (see carry_state). Distributed: every
// rank gathers the whole coarse state (a coarse level is small) and sets its own fine
// particles; the ghosts' values follow at the next force evaluation.
Transfer carry_body(const par::Comm& comm, const Body& from, Body& to) {
  const std::vector<Vec3> from_d = par::gather_owned(comm, from.d, from.owned_begin(), from.owned_end());
  const rk::RKApproximation from_rk = approximation(from);
  std::vector<Vec3> target(to.size(), Vec3::Zero());
  std::atomic<bool> failed{false};
#pragma omp parallel
  {
    rk::ShapeValues sv;
#pragma omp for schedule(dynamic, 256)
    for (Index J = to.owned_begin(); J < to.owned_end(); ++J) {
      if (!from_rk.evaluate(to.cloud.X[J], sv, false)) {
        failed = true;
        continue;
      }
      Vec3 u = Vec3::Zero();
      for (std::size_t k = 0; k < sv.ids.size(); ++k) u += sv.psi[k] * from_d[sv.ids[k]];
      target[J] = u;
      to.v[J] = Vec3::Zero();
    }
  }
  std::fill(to.v.begin(), to.v.end(), Vec3::Zero());
  // Every rank learns of a failure on any (the diagnosis is found again on each).
  if (comm.max(failed ? 1.0 : 0.0) > 0.0) {
    rk::ShapeValues sv;
    for (Index J = 0; J < static_cast<Index>(to.size()); ++J) try {
        from_rk.evaluate_or_throw(to.cloud.X[J], sv, false,
                                   fmt::format("particle {} of the finer cloud of body '{}'", J, to.name));
      } catch (const rk::ApproximationError& e) {
        throw SetupError(fmt::format("nested iteration: body '{}' ({} particles) cannot carry its state to the "
                                     "cloud of {} particles: {}",
                                     from.name, from.size(), to.size(), e.what()));
      }
  }
  // The material's state (the LCE's), interpolated the same way; the material
  // decides what it keeps of it. The shape functions are evaluated again: holding them
  // for every fine particle would cost more memory than the finest cloud itself.
  if (has_material_state(to)) {
    const materials::VectorInterpolation interpolate = [&](const std::vector<Vec3>& field) {
      const std::vector<Vec3> all = par::gather_owned(comm, field, from.owned_begin(), from.owned_end());
      std::vector<Vec3> values(to.size(), Vec3::Zero());
#pragma omp parallel
      {
        rk::ShapeValues sv;
#pragma omp for schedule(dynamic, 256)
        for (Index J = to.owned_begin(); J < to.owned_end(); ++J) {
          if (!from_rk.evaluate(to.cloud.X[J], sv, false)) continue;
          Vec3 value = Vec3::Zero();
          for (std::size_t k = 0; k < sv.ids.size(); ++k) value += sv.psi[k] * all[sv.ids[k]];
          values[J] = value;
        }
      }
      return values;
    };
    transfer_material_state(from, to, interpolate);
  }
  return match_physical_displacement(comm, to, target);
}

void log_transfer(std::ostream& log, const Transfer& done, std::size_t particles) {
  log << fmt::format("  state carried to {} particles in {} sweeps, mismatch {:.1e} of the largest displacement\n",
                     particles, done.sweeps, done.mismatch);
}

}  // namespace

Transfer carry_state(const World& from, World& to) {
  if (from.bodies.size() != to.bodies.size())
    throw std::logic_error("carry_state: the two worlds have different body lists");
  Transfer all;
  for (std::size_t b = 0; b < from.bodies.size(); ++b) {
    const Transfer one = carry_body(*to.comm, *from.bodies[b], *to.bodies[b]);
    all.sweeps = std::max(all.sweeps, one.sweeps);
    all.mismatch = std::max(all.mismatch, one.mismatch);
  }
  return all;
}

double level_particles(const scene::Scene& scene, double factor) {
  double n = 0.0;
  for (const auto& body : scene::at_resolution(scene, factor).bodies) n += clouds::estimate_cloud(body).particles;
  return n;
}

std::vector<double> nested_level_factors(const scene::Scene& scene) {
  std::vector<double> factors = scene.integrator.reals("nested_levels");
  if (factors.empty()) return factors;
  // A generator's smallest cloud ends the halving (its cell counts stop shrinking).
  for (double coarsest = level_particles(scene, factors.front()); coarsest > kCoarsestLevelParticles;) {
    const double coarser = level_particles(scene, 0.5 * factors.front());
    if (!(coarser < coarsest)) break;
    factors.insert(factors.begin(), 0.5 * factors.front());
    coarsest = coarser;
  }
  return factors;
}

std::vector<LevelRun> relax_coarse_levels(const scene::Scene& scene, World& world, std::ostream& log,
                                          const LevelStepCallback& after_step) {
  using Clock = std::chrono::steady_clock;
  const std::vector<double> factors = nested_level_factors(scene);
  std::vector<LevelRun> runs;
  std::unique_ptr<World> previous;
  for (std::size_t l = 0; l < factors.size(); ++l) {
    const auto start = Clock::now();
    const scene::Scene level_scene = scene::at_resolution(scene, factors[l]);
    std::unique_ptr<World> level = build_world(level_scene, *world.comm);
    if (previous) {
      const Transfer handed_on = carry_state(*previous, *level);
      runs.back().transfer_sweeps = handed_on.sweeps;
      runs.back().transfer_mismatch = handed_on.mismatch;
      log_transfer(log, handed_on, level->particle_count());
    }
    Integrator integrator(*level, integrator_settings(level_scene));
    const std::int64_t max_steps = level_scene.integrator.integer("max_steps");
    try {
      integrator.initialize();
      while (!(level->step > 0 && integrator.converged()) && level->step < max_steps) {
        integrator.step();
        if (after_step) after_step(l, *level, integrator, false);
      }
      if (after_step) after_step(l, *level, integrator, true);
    } catch (const BlowUp& e) {
      throw BlowUp(fmt::format("nested level {} (factor {}, {} particles): {}", l + 1, factors[l],
                               level->particle_count(), e.what()));
    }
    previous = std::move(level);
    LevelRun run;
    run.factor = factors[l];
    run.particles = previous->particle_count();
    run.steps = previous->step;
    run.force_evaluations = integrator.force_evaluations();
    run.residual = integrator.residual();
    run.converged = integrator.converged();
    if (l + 1 == factors.size()) {
      const Transfer handed_on = carry_state(*previous, world);
      run.transfer_sweeps = handed_on.sweeps;
      run.transfer_mismatch = handed_on.mismatch;
    }
    run.wall_time = std::chrono::duration<double>(Clock::now() - start).count();
    log << fmt::format("nested level {}/{}: factor {}, {} particles, {} after {} steps (residual {:.2e}), {:.1f} s\n",
                       l + 1, factors.size(), run.factor, run.particles,
                       run.converged ? "converged" : "not converged", run.steps, run.residual, run.wall_time);
    if (l + 1 == factors.size()) log_transfer(log, {run.transfer_sweeps, run.transfer_mismatch}, world.particle_count());
    runs.push_back(run);
  }
  return runs;
}

}  // namespace rkpm::sim
