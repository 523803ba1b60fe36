// Nested iteration for relaxation (docs/verification/relaxation.md): the scene is relaxed on
// coarser clouds first, each level warm-starting the next, so that the fine cloud
// starts near its equilibrium and its own relaxation only has to settle what the
// coarse clouds could not resolve.
#pragma once

#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <vector>

namespace rkpm::sim {

// What one coarse level cost and where it stopped.
struct LevelRun {
  double factor = 0.0;          // resolution factor of [integrator] nested_levels
  std::size_t particles = 0;
  std::int64_t steps = 0;       // relaxation steps
  std::int64_t force_evaluations = 0;  // Integrator::force_evaluations at the level's end
  double wall_time = 0.0;       // set-up, the transfer into it, relaxation (and for the last
                                // level the transfer to the scene's own cloud) [s]
  double residual = 0.0;        // at the level's end (the relaxation's force measure)
  bool converged = false;
  int transfer_sweeps = 0;      // the sweeps that carried this level's state to the next cloud
  double transfer_mismatch = 0.0;  // what they left, over the largest displacement (carry_state)
};

// How closely a carried state arrived: the largest sweeps over the bodies, and the largest
// mismatch |u(X_J) - u_h(X_J)| left, over the largest carried displacement (0 for a body
// at rest).
struct Transfer {
  int sweeps = 0;
  double mismatch = 0.0;
};

// Carries the state of `from` to `to` (the same scene at another resolution; bodies
// matched by position in the list): the physical displacement of `to` at each of its
// particles becomes u_h(X_J) = sum_I Psi_I(X_J) d_I of the body it corresponds to, its
// RK approximation evaluated at the particle's reference position (the generalized
// displacements of `to` are solved for it by a few sweeps), and the material's state
// interpolated the same way (transfer_material_state); velocities are zero. The supports'
// prescribed values are imposed afterwards. Throws SetupError when a particle of `to`
// lies outside the reach of `from`'s approximation.
Transfer carry_state(const World& from, World& to);

// The resolution factors of the levels a relaxation runs, coarsest first: [integrator]
// nested_levels, with halves of its coarsest factor put before it while that level's
// clouds would hold more than kCoarsestLevelParticles particles. The coarsest level
// relaxes from the reference state, and its steps grow with its resolution (the stable
// step follows the spacing, the shape modes do not), while a level that starts from the
// one before it takes a few hundred: so a scene refined with its factors unchanged keeps
// a cheap start (the RBC example at face_cells = 182: factors 0.375 and 0.625 alone
// leave 138,730 particles to relax from the start, over 8,000 steps; with 0.09375 and
// 0.1875 before them, its first two levels take 899 and 687 steps). Empty without
// nested_levels.
constexpr double kCoarsestLevelParticles = 25000.0;
std::vector<double> nested_level_factors(const scene::Scene& scene);
// The particles of the scene's clouds at a resolution factor, from the generators' size
// estimates (no cloud is made).
double level_particles(const scene::Scene& scene, double factor);

// Relaxes the scene on each level of nested_level_factors(scene), coarsest first, and
// carries the last level's state into `world` (built from the scene itself). Returns
// one record per level; writes one line per level and one per transfer to `log`. A level that does not
// converge within max_steps still hands on its state (the fine run decides
// convergence); a level that blows up throws BlowUp, its message naming the level.
// `after_step`, when given, is called after every step of a level with the level's
// index (0 = coarsest), its world and its integrator, and once more with `done` set
// when the level ends, before its line is logged: the program's progress line.
class Integrator;
using LevelStepCallback = std::function<void(std::size_t level, const World&, const Integrator&, bool done)>;
std::vector<LevelRun> relax_coarse_levels(const scene::Scene& scene, World& world, std::ostream& log,
                                          const LevelStepCallback& after_step = {});

}  // namespace rkpm::sim
