// [scene], [integrator], [output]: what the run is and how it steps and writes.
#include "tables/tables.hpp"

#include "rkpm/scene/param_set.hpp"

namespace rkpm::scene::tables {
namespace {

ParamTable scene_section() {
  ParamTable t;
  t.section = "scene";
  t.help = "What the scene is. The name is used for the output file names.";
  t.specs = {
      ParamSpec::text("name").mark_required().help("Short name of the scene; output files are named after it."),
      ParamSpec::text("description").defaults(std::string()).help("Free text describing the scene."),
  };
  // The name becomes a folder (out/<name>) when --out is not given.
  t.finish = [](ParamSet& p) {
    const std::string& name = p.text("name");
    if (name.empty() || name.find_first_of("/\\") != std::string::npos || name == "." || name == ".." ||
        name.find_first_not_of(" \t") == std::string::npos)
      throw p.error("name", "a non-empty name without slashes (it names the output folder out/<name>)");
  };
  return t;
}

void check_integrator(ParamSet& p) {
  if (p.choice("mode") == "dynamic" && !p.has("t_end")) {
    throw p.error("t_end", "a value when mode = \"dynamic\": the simulated end time [s]");
  }
  if (p.has("t_end") && p.real("dt") > p.real("t_end")) {
    throw p.error("dt", "a time step no larger than t_end = " + format_value(p.real("t_end")) + " s");
  }
  if (p.given("relax_method") && p.choice("mode") != "relax")
    throw p.error("relax_method", "no relax_method unless mode = \"relax\"");
  for (const char* key : {"relax_finish", "finish_force_tol", "finish_max_newton_steps"})
    if (p.given(key) && p.choice("mode") != "relax") throw p.error(key, "no " + std::string(key) + " unless mode = \"relax\"");
  for (const char* key : {"finish_force_tol", "finish_max_newton_steps"})
    if (p.given(key) && p.choice("relax_finish") == "none")
      throw p.error(key, "no " + std::string(key) + " unless relax_finish = \"newton_krylov\" (a setting of that finish)");
  for (const char* key : {"mass_scaling", "contact_mass_scaling"})
    if (p.flag(key) && p.choice("mode") != "relax")
      throw p.error(key, "false unless mode = \"relax\": a dynamic run's masses are physical");
  const auto& levels = p.reals("nested_levels");
  if (!levels.empty() && p.choice("mode") != "relax")
    throw p.error("nested_levels", "[] unless mode = \"relax\": coarse levels warm-start a relaxation");
  for (std::size_t i = 1; i < levels.size(); ++i)
    if (!(levels[i] > levels[i - 1])) throw p.error("nested_levels", "factors in increasing order, coarsest first");
}

ParamTable integrator_section() {
  ParamTable t;
  t.section = "integrator";
  t.help = "Explicit time stepping (velocity Verlet) or fast relaxation to equilibrium.";
  t.specs = {
      ParamSpec::choice("mode", {"dynamic", "relax"}).defaults(std::string("dynamic"))
          .help("dynamic: explicit dynamics up to t_end. relax: FIRE-style damped dynamics that "
                "stops at static equilibrium (see relax_force_tol, relax_velocity_tol)."),
      ParamSpec::real("t_end", "s").greater_than(0)
          .absent_means("required if dynamic")
          .help("Simulated end time. Required in dynamic mode; in relax mode it is an optional "
                "limit on the pseudo-time."),
      ParamSpec::real("dt", "s").at_least(0).defaults(0.0)
          .help("Time step; 0 = automatic, dt_safety times the stable step of the current state."),
      ParamSpec::real("dt_safety", "-").greater_than(0).at_most(1).defaults(0.5)
          .help("Fraction of the estimated stable time step that is taken when dt = 0."),
      ParamSpec::choice("stable_step", {"auto", "wave_speed", "measured"}).defaults(std::string("auto"))
          .help("How the stable step is estimated. auto: wave_speed, but measured when a body's essential "
                "boundary conditions amplify (their transformation moves a constrained coordinate by more "
                "than a free one moves: a coarse unstructured tetrahedral cloud with a fixed face, whose "
                "true stable step can be a third of the wave-speed step; docs/verification/stability.md). wave_speed: the shortest spacing over the material's "
                "wave speed at each particle, each term's own limit, and a material state's own (the LCE's, docs/verification/stability.md). measured: the bodies' wave-speed "
                "step calibrated by 2 / omega_max, the largest natural frequency of the discretisation and "
                "the terms, measured by power iteration at the start and every 1000 steps (a few tens of "
                "force evaluations each). On the RBC shell it is 1.9x the wave-speed step; where a term's own "
                "limit binds (contact) nothing changes (docs/theory/relaxation.md)."),
      ParamSpec::integer("stable_step_interval").at_least(1).at_most(1000).defaults(std::int64_t{10})
          .help("Steps between two estimates of the stable step (each one wave-speed pass over the "
                "particles). The default follows slow changes of the state; 1 follows a state that "
                "changes within a few steps, as in a release from stretch 3 or compression 0.3 along an "
                "axis, which at the default outruns the estimate and blows up after several hundred steps "
                "(docs/verification/stability.md). A step that changes in most steps conserves energy slightly worse "
                "(measured with a schedule that re-estimated in most steps)."),
      ParamSpec::real("damping", "1/s").at_least(0).defaults(0.0)
          .help("Mass-proportional damping coefficient c: force -c m v on every particle. With "
                "stable_step_interval = 1, c = 3e6 / s (measured: ten times an estimate pi c_s / L of the "
                "slowest angular frequency of a 10 um block with c_s = 1 m/s; 1e6 / s is not enough) "
                "carries releases from stretch 3 or compression 0.3, in all directions too, to rest "
                "(docs/verification/stability.md)."),
      ParamSpec::integer("max_steps").at_least(1).defaults(std::int64_t{10000000})
          .help("Hard limit on the number of steps; reaching it before t_end (or convergence) ends the run with exit code 4."),
      ParamSpec::real("relax_force_tol", "-").greater_than(0).defaults(1e-6)
          .help("relax mode: converged when the largest residual force on a particle, expressed as a "
                "stress (|f_I| / V_I^(2/3)), falls below this fraction of the body's shear modulus."),
      ParamSpec::real("relax_velocity_tol", "-").greater_than(0).defaults(1e-8)
          .help("relax mode: converged when, in addition, the kinetic energy falls below this fraction "
                "of mu V summed over the bodies (shear modulus times volume)."),
      ParamSpec::real("relax_state_tol", "-").at_least(0).defaults(0.0)
          .help("relax mode: converged only when, in addition, every material's per-point state is at its own "
                "equilibrium: its residual (summary.json's state_residual, in the material's own measure) "
                "falls below this. 0 = the state is not part of the stop (it is reported only; "
                "docs/theory/relaxation.md)."),
      ParamSpec::integer("seed").at_least(0).defaults(std::int64_t{1})
          .help("Seed of the random numbers used by the run (initial random velocities)."),
      ParamSpec::choice("relax_method", {"fire", "fire2"}).defaults(std::string("fire"))
          .help("relax mode: the FIRE variant. fire: Bitzek et al. 2006. fire2: FIRE 2.0 (Guenole et al. "
                "2020) with LAMMPS's defaults: 20 downhill steps before the step grows, alpha_start 0.25, a "
                "step floor of 0.02 dt_max, and an uphill step first moves the particles back by half a step "
                "(one extra force evaluation per stop). Both reach the same equilibrium; docs/theory/relaxation.md "
                "compares their cost."),
      ParamSpec::choice("relax_finish", {"none", "newton_krylov"}).defaults(std::string("none"))
          .help("relax mode: what follows FIRE's stop. newton_krylov: Newton steps on the static equilibrium "
                "f(d) = 0 from FIRE's end state, each linear system solved by GMRES with the tangent applied as a "
                "difference of two force evaluations (Jacobian-free Newton-Krylov) and a backtracking line search "
                "on the residual, until the residual measure of relax_force_tol falls below finish_force_tol. "
                "The materials' state is carried with each update (as the LCE's own update defines it); "
                "a state that relaxes in time by itself (an LCE with mobility > 0, a viscous material) and "
                "distributed runs are refused. docs/theory/relaxation.md, \"The Newton-Krylov finish\"."),
      ParamSpec::real("finish_force_tol", "-").greater_than(0).defaults(1e-8)
          .help("relax_finish = \"newton_krylov\": its target, the largest residual force on a particle as a "
                "stress over the body's shear modulus (the measure of relax_force_tol)."),
      ParamSpec::integer("finish_max_newton_steps").at_least(1).at_most(1000).defaults(std::int64_t{50})
          .help("relax_finish = \"newton_krylov\": Newton steps before the finish gives up (the run then ends "
                "not converged, exit code 4, with the state of its last accepted step)."),
      ParamSpec::boolean("mass_scaling").defaults(false)
          .help("relax mode: mass scaling. Particles whose own stable step (spacing over wave speed) is "
                "below the median over the scene's particles are made heavier until it reaches the median, "
                "so that a few short edges do not set the step of all (the equilibrium does not depend on "
                "the masses; docs/theory/relaxation.md says when it pays). Not allowed in dynamic mode, where the "
                "masses are physical."),
      ParamSpec::boolean("contact_mass_scaling").defaults(false)
          .help("relax mode: a wall_contact term makes the particles it presses heavier, until its own "
                "stable step (its stiffest pair's Gershgorin bound) reaches the bodies' step, instead of "
                "holding the whole relaxation at the contact's step; the velocities are kept (the energy "
                "ledger books the kinetic energy this adds), and the equilibrium does not depend on the "
                "masses. A raised inertia stays raised "
                "for the rest of the run. The two-body contact term keeps its own limit. Not allowed in "
                "dynamic mode, where the masses are physical (docs/theory/relaxation.md)."),
      ParamSpec::real_list("nested_levels", "-").greater_than(0).less_than(1).defaults(std::vector<double>{})
          .help("relax mode: nested iteration. Resolution factors of coarser clouds, coarsest first "
                "(0.5 = half the cells along each direction; a shell keeps its layers): the scene is "
                "relaxed on each in turn, each level starting from the one before carried over by the RK "
                "approximation, and the last starts the run on the scene's own cloud. Halves of the coarsest "
                "factor are put first while its level would hold more than 25,000 particles (a refined "
                "scene keeps a cheap start). Generated clouds only."),
  };
  t.finish = check_integrator;
  return t;
}

ParamTable output_section() {
  ParamTable t;
  t.section = "output";
  t.help = "Frames (VTU files collected by a PVD file) and checkpoints.";
  t.specs = {
      ParamSpec::real("every", "s").greater_than(0)
          .absent_means("t_end / 50")
          .help("Simulated time between frames. Without it and without t_end (relax mode) only "
                "the initial and final states are written."),
      ParamSpec::choice("cells", {"mesh", "points"}).defaults(std::string("mesh"))
          .help("mesh: write the particles with the cloud's mesh (surfaces render in ParaView). "
                "points: particles only (vertex cells)."),
      ParamSpec::integer("checkpoint_every").at_least(0).defaults(std::int64_t{0})
          .help("Steps between checkpoints from which a run can be restarted; 0 = never."),
      ParamSpec::text("shape_report").defaults(std::string(""))
          .help("Name of a shell body whose outer-surface shape is measured against the Evans-Fung red-blood-cell "
                "profile at every frame (history.csv) and at the end (summary.json, shape_profile.csv); "
                "\"\" = none."),
  };
  return t;
}

}  // namespace

std::vector<ParamTable> run_sections() { return {scene_section(), integrator_section(), output_section()}; }

}  // namespace rkpm::scene::tables
