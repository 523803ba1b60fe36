#include "sim/run/summary.hpp"

#include "rkpm/io/run_summary.hpp"
#include "rkpm/rk/row_scatter.hpp"
#include "rkpm/sim/run.hpp"
#include "rkpm/sim/history.hpp"

namespace rkpm::sim {

namespace {

// Per body and rank: the particles owned, the ghosts held, and the doubles a force
// evaluation exchanges (each ghost's displacement in, and out the force contributions
// the rank's rows make to its ghosts, one record each: rk/row_scatter.hpp).
// Collective: every rank calls it.
io::Json distribution_json(const World& world) {
  const par::Comm& comm = *world.comm;
  io::Json bodies = io::Json::array();
  for (const auto& b : world.bodies) {
    const auto owned = comm.gather(static_cast<std::int64_t>(b->owned_end() - b->owned_begin()));
    const auto ghosts = comm.gather(static_cast<std::int64_t>(b->ghosts.ghost_count()));
    const auto records = comm.gather(static_cast<std::int64_t>(b->force_scatter.records_sent()));
    io::Json j = io::Json::object();
    j.set("body", b->name);
    io::Json o = io::Json::array(), g = io::Json::array(), v = io::Json::array();
    for (std::size_t r = 0; r < owned.size(); ++r) {
      o.push_back(owned[r]);
      g.push_back(ghosts[r]);
      v.push_back(3 * ghosts[r] + 3 * records[r]);
    }
    j.set("owned", std::move(o));
    j.set("ghosts", std::move(g));
    j.set("doubles_received_and_returned_per_force_evaluation", std::move(v));
    bodies.push_back(std::move(j));
  }
  return bodies;
}

io::Json energy_json(const EnergyLedger& e) {
  io::Json j = io::Json::object();
  j.set("kinetic", e.kinetic);
  j.set("strain", e.strain);
  j.set("interface", e.interface);
  j.set("external_work", e.external);
  j.set("active_work", e.active);
  j.set("state_work", e.state);
  j.set("dissipated", e.dissipated);
  j.set("initial", e.initial);
  j.set("relative_error", e.relative_error());
  return j;
}

}  // namespace

io::Json run_summary(const scene::Scene& scene, const World& world, Integrator& integrator, bool relax,
                     const std::vector<LevelRun>& levels, const std::optional<NewtonKrylovReport>& finish,
                     const RunOutcome& outcome, const Body* shape_body, const std::filesystem::path& out_dir) {
  const par::Comm& comm = *world.comm;
  io::RunSummary summary;
  summary.scene = scene.file;
  for (const auto& b : world.bodies) summary.particle_counts.emplace_back(b->name, static_cast<std::int64_t>(b->size()));
  summary.steps = world.step;
  summary.simulated_time = world.time;
  summary.wall_time = outcome.wall_time;
  summary.frames_written = outcome.frames_written;
  summary.status = outcome.status;
  io::Json json = io::to_json(summary);
  json.set("threads", rk::RowScatter::team_threads());
  json.set("ranks", comm.size());
  if (comm.parallel()) json.set("distribution", distribution_json(world));
  json.set("dt", integrator.dt());
  json.set("stable_dt", integrator.stable_dt());
  json.set("force_evaluations", integrator.force_evaluations());
  if (!relax) json.set("motion_limited_steps", integrator.motion_limited_steps());
  if (relax) json.set("fire_step_backs", integrator.step_backs());
  if (integrator.measures_stable_step()) {
    json.set("stable_step_calibration", integrator.stable_step_calibration());
    json.set("stable_step_calibrations", integrator.calibrations());
  }
  json.set("pvd", outcome.pvd.string());
  if (!levels.empty()) {
    io::Json list = io::Json::array();
    for (const LevelRun& l : levels) {
      io::Json j = io::Json::object();
      j.set("factor", l.factor);
      j.set("particles", static_cast<std::int64_t>(l.particles));
      j.set("steps", l.steps);
      j.set("force_evaluations", l.force_evaluations);
      j.set("wall_time", l.wall_time);
      j.set("residual", l.residual);
      j.set("converged", l.converged);
      j.set("transfer_sweeps", static_cast<std::int64_t>(l.transfer_sweeps));
      j.set("transfer_mismatch", l.transfer_mismatch);
      list.push_back(std::move(j));
    }
    json.set("nested_levels", std::move(list));
  }
  if (finish) {
    io::Json j = io::Json::object();
    j.set("converged", finish->converged);
    j.set("stop", finish->stop);
    j.set("newton_steps", static_cast<std::int64_t>(finish->newton_steps));
    j.set("krylov_iterations", finish->krylov_iterations);
    j.set("force_evaluations", finish->force_evaluations);
    j.set("residual", finish->residual);
    io::Json residuals = io::Json::array();
    for (double r : finish->residuals) residuals.push_back(r);
    j.set("residual_after_each_newton_step", std::move(residuals));
    json.set("newton_krylov", std::move(j));
  }
  if (outcome.code != kUnstable && outcome.code != kOutputFailed) {
    json.set("energy", energy_json(integrator.measure_energy()));
    json.set("min_J", integrator.min_J());
    if (relax) {
      json.set("converged", integrator.converged() && (!finish || finish->converged));
      json.set("residual", integrator.residual());
      json.set("kinetic_measure", integrator.kinetic_measure());
      json.set("state_residual", integrator.state_residual());
    }
    for (const auto& t : world.terms) t->report(world, json);
    if (shape_body) {
      const ShapeReport shape = final_shape(*shape_body, comm);  // collective
      if (comm.root()) write_shape(shape, out_dir / "shape_profile.csv", json);
    }
  } else {
    json.set("diagnosis", outcome.diagnosis);
  }
  return json;
}

}  // namespace rkpm::sim
