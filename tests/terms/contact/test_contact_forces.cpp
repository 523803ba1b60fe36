// The contact term on real particle clouds: forces are the exact gradient of the
// stored energy, pair forces cancel (linear and angular momentum), the shifted
// energy is continuous at the cutoff, the stiffness law scales eps by the substrate's
// local shear modulus, the stable step is the critical step of the pair springs, and
// the term is built from a scene's [[term]] table.
#include "contact_fixtures.hpp"

#include "rkpm/particles/generators.hpp"
#include "rkpm/scene/scene_error.hpp"
#include "rkpm/sim/build.hpp"
#include "terms/contact/contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace rkpm::sim {
namespace {

// Two jittered blocks 0.1 apart in z, randomly displaced: an irregular contact state.
struct TwoBlocks {
  std::unique_ptr<Body> lower, upper;
  std::unique_ptr<Contact> contact;
  World world;
  TwoBlocks() {
    particles::BlockSpec s;
    s.size = Vec3(1.0, 1.0, 0.4);
    s.cells = {6, 6, 3};
    s.jitter = 0.2;
    const auto a = particles::make_block(s);
    s.origin = Vec3(0.1, -0.05, 0.5);
    s.seed = 2;
    const auto b = particles::make_block(s);
    lower = testing::particle_body("lower", a.X, a.volume, 1000.0);
    upper = testing::particle_body("upper", b.X, b.volume, 1000.0);
    testing::Random rng{5};
    std::vector<Vec3> d(upper->size());
    for (auto& v : d) v = 0.02 * rng.vector();
    testing::move_to(*upper, d);
    ContactSettings c;
    c.epsilon = 1e-3;
    c.s0 = 0.15;
    c.cutoff = 0.45;
    c.skin = 0.05;
    c.beta = {50.0, 80.0};
    contact = std::make_unique<Contact>(*lower, *upper, c);
  }
  double energy() {
    for (auto* b : {lower.get(), upper.get()}) std::fill(b->force.begin(), b->force.end(), Vec3::Zero());
    contact->add_forces(world);
    return contact->energy();
  }
};

TEST(ContactForces, AreMinusTheGradientOfTheEnergy) {
  TwoBlocks t;
  t.energy();
  ASSERT_GT(t.contact->active_pairs(), 1000u);
  const std::vector<Vec3> f_lower = t.lower->force, f_upper = t.upper->force;
  // Every component of the 49 top-surface particles of the lower block and of the
  // 49 bottom particles of the upper block, by central differences.
  double worst = 0.0, scale = 0.0;
  for (auto* body : {t.lower.get(), t.upper.get()}) {
    const auto& f = body == t.lower.get() ? f_lower : f_upper;
    for (std::size_t i = 0; i < body->size(); ++i) {
      const bool at_interface = body == t.lower.get() ? body->cloud.X[i].z() > 0.39 : body->cloud.X[i].z() < 0.51;
      if (!at_interface) continue;
      for (int k = 0; k < 3; ++k) {
        const double h = 1e-6;
        const double d0 = body->d[i][k];
        body->d[i][k] = d0 + h;
        const double e_plus = t.energy();
        body->d[i][k] = d0 - h;
        const double e_minus = t.energy();
        body->d[i][k] = d0;
        worst = std::max(worst, std::abs(-(e_plus - e_minus) / (2.0 * h) - f[i][k]));
        scale = std::max(scale, std::abs(f[i][k]));
      }
    }
  }
  std::printf("largest |f + dE/dx| = %.2e of the largest force component %.2e\n", worst, scale);
  EXPECT_LE(worst, 1e-6 * scale);
}

TEST(ContactForces, CancelInTotalForceAndTorque) {
  TwoBlocks t;
  t.energy();
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  double magnitude = 0.0, arm = 0.0;
  for (auto* b : {t.lower.get(), t.upper.get()})
    for (std::size_t i = 0; i < b->size(); ++i) {
      force += b->force[i];
      torque += nodal_position(*b, i).cross(b->force[i]);
      magnitude = std::max(magnitude, b->force[i].norm());
      arm = std::max(arm, nodal_position(*b, i).norm());
    }
  Vec3 on_upper = Vec3::Zero();
  for (const auto& f : t.upper->force) on_upper += f;
  std::printf("force on upper block %+.4e %+.4e %+.4e; |sum F| = %.1e, |sum x x F| = %.1e\n", on_upper.x(),
              on_upper.y(), on_upper.z(), force.norm(), torque.norm());
  EXPECT_GT(on_upper.norm(), 0.1 * magnitude);  // a real resultant, not noise
  EXPECT_LE(force.norm(), 1e-12 * on_upper.norm());
  EXPECT_LE(torque.norm(), 1e-12 * on_upper.norm() * arm);
}

TEST(ContactEnergy, IsContinuousWhenAPairCrossesTheCutoff) {
  auto a = testing::particle_body("a", {Vec3::Zero()}, {1.0});
  auto b = testing::particle_body("b", {Vec3(0.3 - 1e-9, 0, 0)}, {1.0});
  ContactSettings s;
  s.epsilon = 1.0;
  s.s0 = 0.1;
  s.cutoff = 0.3;
  s.beta = {1.0, 1.0};
  Contact c(*a, *b, s);
  World w;
  c.add_forces(w);
  EXPECT_EQ(c.active_pairs(), 1u);
  EXPECT_NEAR(c.energy(), 0.0, 1e-10);  // phi(rc - 1e-9) - phi(rc)
  EXPECT_GT(a->force[0].x(), 0.0);       // still attracted toward b (at +x)
}

TEST(ContactStiffnessLaw, ScalesEpsByTheSubstrateShearModulus) {
  // Substrate: two particles with shear moduli 1000 and 3000 Pa (mean 2000).
  auto probe = testing::particle_body("probe", {Vec3(0, 0, 0.12)}, {1.0});
  auto sub = testing::particle_body("substrate", {Vec3::Zero(), Vec3(5, 0, 0)}, {1.0, 1.0});
  auto& mr = std::get<materials::mooney_rivlin::BodyMaterial>(sub->material).at_point;
  mr[1].c1 *= 3.0;
  mr[1].c2 *= 3.0;
  ContactSettings s;
  s.epsilon = 1.0;
  s.s0 = 0.1;
  s.cutoff = 0.4;
  s.beta = {1.0, 1.0};
  Contact uniform(*probe, *sub, s);
  s.law = StiffnessLaw::linear;
  s.substrate = "substrate";
  Contact graded(*probe, *sub, s);
  EXPECT_DOUBLE_EQ(graded.molecules(1)[0], 0.5);  // 1000 / 2000
  EXPECT_DOUBLE_EQ(graded.molecules(1)[1], 1.5);
  World w;
  uniform.add_forces(w);
  graded.add_forces(w);
  EXPECT_NEAR(graded.energy(), 0.5 * uniform.energy(), 1e-14 * std::abs(uniform.energy()));
  s.stiffness_reference = 500.0;
  Contact referenced(*probe, *sub, s);
  EXPECT_DOUBLE_EQ(referenced.molecules(1)[1], 6.0);
}

// Two particles at the potential minimum form a spring k = n n phi''(s0) = 72 eps/s0^2;
// equal masses m: omega^2 = 2k/m, critical Verlet step 2/omega. The estimate must be
// that step, and Verlet must indeed be stable just below and unstable just above it.
TEST(ContactStableStep, IsTheCriticalStepOfThePairSpring) {
  const double s0 = 0.1, eps = 1e-3, m = 2.0;
  auto run = [&](double dt_factor, double& amplitude, double& estimate) {
    auto a = testing::particle_body("a", {Vec3::Zero()}, {1.0}, m);
    auto b = testing::particle_body("b", {Vec3(s0, 0, 0)}, {1.0}, m);
    a->v[0] = Vec3(-1e-5, 0, 0);  // a small symmetric oscillation about the minimum
    b->v[0] = Vec3(1e-5, 0, 0);
    ContactSettings s;
    s.epsilon = eps;
    s.s0 = s0;
    s.cutoff = 3 * s0;
    s.beta = {1.0, 1.0};
    Contact c(*a, *b, s);
    World w;
    auto forces = [&] {
      a->force[0].setZero();
      b->force[0].setZero();
      c.add_forces(w);
    };
    forces();
    estimate = c.stable_dt(w);
    const double dt = dt_factor * estimate;
    amplitude = 0.0;
    for (int step = 0; step < 400; ++step) {
      for (auto* p : {a.get(), b.get()}) {
        p->v[0] += 0.5 * dt * p->force[0] / m;
        p->d[0] += dt * p->v[0];
      }
      forces();
      for (auto* p : {a.get(), b.get()}) p->v[0] += 0.5 * dt * p->force[0] / m;
      amplitude = std::max(amplitude, std::abs((nodal_position(*b, 0) - nodal_position(*a, 0)).norm() - s0));
    }
  };
  double stable_amp = 0.0, unstable_amp = 0.0, estimate = 0.0;
  run(0.98, stable_amp, estimate);
  run(1.02, unstable_amp, estimate);
  const double exact = 2.0 / std::sqrt(2.0 * 72.0 * eps / (s0 * s0) / m);
  std::printf("stable step %.6e (exact %.6e); amplitude after 400 steps: %.2e at 0.98 dt, %.2e at 1.02 dt\n",
              estimate, exact, stable_amp, unstable_amp);
  EXPECT_NEAR(estimate, exact, 1e-3 * exact);
  EXPECT_LT(stable_amp, 1e-3 * s0);
  EXPECT_GT(unstable_amp, 1e-2 * s0);
}

const std::string kScene = R"([scene]
name = "contact"
[integrator]
t_end = 1e-3
[[body]]
name = "cell"
density = 1000
[body.cloud]
generator = "block"
origin = [0, 0, 0.21]
size = [0.5, 0.5, 0.2]
cells = [3, 3, 2]
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 2000
[[body]]
name = "substrate"
density = 1000
[body.cloud]
generator = "block"
size = [1, 1, 0.2]
cells = [4, 4, 2]
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 2000
grade_axis = "x"
grade_a = 4.0
grade_b = 0.5
[[term]]
type = "contact"
bodies = ["cell", "substrate"]
epsilon = 1e-6
s0 = 0.2               # holds both clouds: their widest surface hollows are 0.12 and 0.18
stiffness_law = "linear"
substrate = "{substrate}"
)";

std::string scene_with_substrate(const std::string& name) {
  std::string text = kScene;
  return text.replace(text.find("{substrate}"), 11, name);
}

TEST(ContactScene, BuildsTheTermWithItsStiffnessLaw) {
  auto w = testing::world_from_text(scene_with_substrate("substrate"));
  ASSERT_EQ(w.world->terms.size(), 1u);
  auto* contact = dynamic_cast<Contact*>(w.world->terms[0].get());
  ASSERT_NE(contact, nullptr);
  // Graded substrate: the weights follow the local modulus, their volume mean is 1.
  const Body& sub = *w.world->bodies[1];
  double mean = 0.0, volume = 0.0, lo = 1e300, hi = 0.0;
  const double beta = static_cast<double>(sub.size()) / [&] {
    double v = 0.0;
    for (double x : sub.cloud.volume) v += x;
    return v;
  }();
  for (std::size_t i = 0; i < sub.size(); ++i) {
    const double wgt = contact->molecules(1)[i] / (beta * sub.cloud.volume[i]);
    mean += wgt * sub.cloud.volume[i];
    volume += sub.cloud.volume[i];
    lo = std::min(lo, wgt);
    hi = std::max(hi, wgt);
  }
  std::printf("substrate eps weights from %.3f to %.3f, volume mean %.6f\n", lo, hi, mean / volume);
  EXPECT_NEAR(mean / volume, 1.0, 1e-12);
  EXPECT_GT(hi / lo, 2.0);
  compute_forces(*w.world);
  EXPECT_GT(contact->active_pairs(), 0u);
}

TEST(ContactScene, RejectsASubstrateThatIsNotOneOfTheBodies) {
  try {
    testing::world_from_text(scene_with_substrate("nowhere"));
    FAIL() << "expected an error";
  } catch (const scene::SceneError& e) {
    std::printf("%s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("substrate"), std::string::npos);
  }
}

}  // namespace
}  // namespace rkpm::sim
