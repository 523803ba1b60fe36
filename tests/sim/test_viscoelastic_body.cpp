// The viscoelastic material (src/materials/viscoelastic) through the simulator: its
// per-point state reaches the force pass, the step, the energy ledger and the checkpoint
// through the material-state hooks alone (materials/state_hooks.hpp). The constitutive
// update itself is verified point by point in tests/materials/viscoelastic.
#include "sim_fixtures.hpp"

#include "rkpm/sim/body_state.hpp"
#include "rkpm/sim/run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

using namespace rkpm;
using namespace rkpm::sim;
using namespace rkpm::sim::testing;
namespace fs = std::filesystem;

namespace {

const char* kBlock = R"([scene]
name = "viscoelastic_block"
[integrator]
mode = "dynamic"
t_end = {t_end}
dt_safety = 0.1
[output]
every = {every}
checkpoint_every = 10
[[body]]
name = "gel"
density = 1000.0
[body.cloud]
generator = "block"
size = [4e-6, 4e-6, 4e-6]
cells = [4, 4, 4]
[body.material]
model = "viscoelastic"
mu = 1e3
lambda = 4e3
beta = {beta}
tau = {tau}
[body.initial]
stretch = {stretch}
random_velocity = {noise}
)";

std::string block(const std::string& beta, const std::string& tau, const std::string& stretch = "[1, 1, 1]",
                  const std::string& noise = "0", const std::string& t_end = "1e-4", const std::string& every = "1e-4") {
  return with(with(with(with(with(with(kBlock, "beta", beta), "tau", tau), "stretch", stretch), "noise", noise),
                   "t_end", t_end),
              "every", every);
}

// Mean of P_xz over the body's integration points, weighted by their volumes.
double mean_shear_stress(const Body& body) {
  double weighted = 0.0, volume = 0.0;
  for (Index L = 0; L < static_cast<Index>(body.size()); ++L) {
    weighted += body.gradient.weight[L] * first_piola_at(body, L)(0, 2);
    volume += body.gradient.weight[L];
  }
  return weighted / volume;
}

}  // namespace

// A step shear gamma held fixed: the stress the force pass sees relaxes as the linear
// closed form G(t) = mu (1 + sum_i beta_i exp(-t/tau_i)), because the RK gradient
// reproduces the homogeneous F exactly and each end_state_step is the exact flow at
// fixed F. The residual error is the model's own nonlinearity, O(gamma^2) relative.
TEST(ViscoelasticBody, StepShearRelaxesAsTheLinearClosedForm) {
  ScopedThreads one(1);
  const double mu = 1e3, beta[2] = {2.0, 0.5}, tau[2] = {1e-3, 2e-2}, gamma = 1e-4;
  auto sw = build_from_text(block("[2.0, 0.5]", "[1e-3, 2e-2]"));
  Body& body = *sw.world->bodies.front();
  for (std::size_t I = 0; I < body.size(); ++I) body.d[I] = Vec3(gamma * body.cloud.X[I].z(), 0.0, 0.0);
  compute_internal_forces(body);
  ASSERT_TRUE(has_material_state(body));
  ASSERT_TRUE(state_evolves_in_time(body));
  const double dt = 1e-3;  // any step: the update is the exact flow at fixed F
  const double V = 4e-6 * 4e-6 * 4e-6;
  const double round_off = 1e-15 * mu * V;  // of the stored energy, summed over the points
  double worst = 0.0, dissipated = 0.0;
  for (int n = 0; n <= 400; ++n) {
    const double t = n * dt;
    const double G = mu * (1.0 + beta[0] * std::exp(-t / tau[0]) + beta[1] * std::exp(-t / tau[1]));
    worst = std::max(worst, std::abs(mean_shear_stress(body) / gamma - G) / G);
    const materials::StateUpdate u = end_state_step(body, dt);
    EXPECT_LE(u.energy_change(), round_off) << "an update never raises the stored energy (step " << n << ")";
    EXPECT_EQ(u.active_work, 0.0);
    dissipated -= u.energy_change();
  }
  std::printf("step shear %g over 0.4 s: worst |P_xz / gamma - G(t)| / G(t) = %.3g\n", gamma, worst);
  EXPECT_LT(worst, 1e-6);
  // Everything the branches held at t = 0 is released by t = 20 tau_2 (up to exp(-40)):
  // V sum_i beta_i mu gamma^2 / 2 to first order in gamma.
  const double held = V * (beta[0] + beta[1]) * mu * gamma * gamma / 2.0;
  EXPECT_NEAR(dissipated, held, 1e-4 * held);
  // The branches' energy over mu, from about gamma^2 at the start to round-off.
  EXPECT_LT(state_residual(body), 1e-6 * gamma * gamma);
}

// Released from a stretch with random velocities and no damping, the block rings and
// its Maxwell branches dissipate: the ledger's state column books the viscous
// dissipation (negative, nearly all the energy), and the balance closes to the
// integrator's error. A step's forces are those of the state before its update (as for
// the LCE director), so the imbalance is first order in dt / tau: halving the step halves
// it. Without branches nothing is booked there and the error is Verlet's alone.
TEST(ViscoelasticBody, TheLedgerClosesWithTheViscousDissipation) {
  ScopedThreads one(1);
  const auto ledger = [](const std::string& beta, const std::string& tau, double dt_safety) {
    std::string text = block(beta, tau, "[1.15, 0.92, 0.95]", "0.02");
    text.replace(text.find("dt_safety = 0.1"), 15, "dt_safety = " + std::to_string(dt_safety));
    auto sw = build_from_text(text);
    Integrator integrator(*sw.world, sw.settings);
    integrator.initialize();
    while (sw.world->time < 1e-4) integrator.step();
    const EnergyLedger e = integrator.measure_energy();
    std::printf("beta %s tau %s dt_safety %g: %lld steps, state work %.4g J of initial %.4g J, relative ledger "
                "error %.3g\n",
                beta.c_str(), tau.c_str(), dt_safety, static_cast<long long>(sw.world->step), e.state, e.initial,
                e.relative_error());
    return e;
  };
  const EnergyLedger coarse = ledger("[1.0]", "[2e-6]", 0.1);
  const EnergyLedger fine = ledger("[1.0]", "[2e-6]", 0.05);
  EXPECT_LT(coarse.state, -0.9 * coarse.initial) << "the branches dissipated nearly everything";
  EXPECT_LT(coarse.relative_error(), 5e-3);
  EXPECT_GT(coarse.relative_error() / fine.relative_error(), 1.6) << "first order in the step";
  const EnergyLedger elastic = ledger("[]", "[]", 0.1);
  EXPECT_EQ(elastic.state, 0.0);
  EXPECT_LT(elastic.relative_error(), 1e-3);
}

// The viscous strains are part of the checkpoint: a run resumed at step 20 ends at
// step 40 with the same bytes as the uninterrupted one.
TEST(ViscoelasticBody, ARestartContinuesBitForBit) {
  ScopedThreads two(2);
  const fs::path dir = fresh_dir("viscoelastic_restart");
  const std::string text = block("[1.0, 0.3]", "[2e-6, 1e-5]", "[1.1, 0.95, 0.97]", "0.01", "1e-3", "1e-7");
  const auto run = [&](const fs::path& out, std::int64_t steps, const fs::path& restart) {
    const scene::Scene scene = scene::parse_scene(text, (dir / "viscoelastic.toml").string());
    RunOptions options;
    options.out_dir = out;
    options.restart = restart;
    options.max_steps_override = steps;
    options.quiet = true;
    std::ostringstream log;
    const int code = run_scene(scene, options, log);
    EXPECT_EQ(code, kSuccess) << log.str();
  };
  run(dir / "whole", 40, {});
  run(dir / "split", 20, {});
  fs::copy_file(dir / "split" / "checkpoint.bin", dir / "step20.bin");
  run(dir / "split", 40, dir / "step20.bin");
  const std::string a = read_text(dir / "whole" / "checkpoint.bin"), b = read_text(dir / "split" / "checkpoint.bin");
  EXPECT_EQ(a, b);
  EXPECT_NE(a.find("viscous_state"), std::string::npos) << "the state is in the checkpoint";
  EXPECT_NE(a, read_text(dir / "step20.bin"));
  fs::remove_all(dir);
}
