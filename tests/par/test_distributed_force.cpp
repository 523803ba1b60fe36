// Run under mpirun with 2 ranks (tests/par/CMakeLists.txt), or any N >= 2 by hand. Each body is partitioned
// over the ranks and renumbered; the ghost layer pulls the owners' values and returns
// the force contributions, and the internal force at every owned particle equals a
// one-rank run of the same scene, built in the same process on Comm::self().
#include "rkpm/common/split_mix64.hpp"
#include "rkpm/par/comm.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/world.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <limits>
#include <string>

using namespace rkpm;
using namespace rkpm::sim;

namespace {

const char* kLceSphere = R"(
[scene]
name = "distributed_force"
[integrator]
mode = "dynamic"
t_end = 1e-6
[[body]]
name = "ball"
density = 1000.0
[body.cloud]
generator = "sphere"
radius = 2e-6
cells = 6
[body.rk]
gradient_precision = "double"
[body.material]
model = "lce"
mu = 1e4
bulk = 1e5
s = 2.0
kappa = 1e-11
zeta = -3e3
[body.director]
initial = "radial"
boundary = "free"
)";

const char* kMooneyRivlinBlock = R"(
[scene]
name = "distributed_force"
[integrator]
mode = "dynamic"
t_end = 1e-6
[[body]]
name = "block"
density = 1000.0
[body.cloud]
generator = "block"
size = [4e-6, 3e-6, 2e-6]
cells = [8, 6, 5]
jitter = 0.2
[body.material]
model = "mooney_rivlin"
c1 = 2.126e3
c2 = 1.7e2
lambda = 1.7e5
)";

// A cell on a substrate with every surface and contact term: the contact pairs of the
// two bodies, surface tension on each, a follower pressure on the substrate's sides.
const char* kCellOnSubstrate = R"(
[scene]
name = "distributed_terms"
[integrator]
mode = "dynamic"
t_end = 1e-6
[[body]]
name = "cell"
density = 1000.0
[body.cloud]
generator = "sphere"
center = [0.3e-6, -0.2e-6, 3.4e-6]
radius = 1.5e-6
cells = 6
[body.material]
model = "lce"
mu = 1e4
bulk = 1e5
s = 2.0
kappa = 1e-11
[body.director]
initial = "surface_normal"
boundary = "normal"
[[body]]
name = "substrate"
density = 1000.0
[body.cloud]
generator = "block"
origin = [-3e-6, -3e-6, 0.0]
size = [6e-6, 6e-6, 1.5e-6]
cells = [10, 10, 3]
[body.material]
model = "mooney_rivlin"
c1 = 2.126e3
c2 = 1.7e2
lambda = 1.7e5
[[term]]
type = "contact"
bodies = ["cell", "substrate"]
s0 = 0.5e-6
epsilon = 3e-15
beta = [1e18, 1e18]
stiffness_law = "linear"
substrate = "substrate"
report_surface = "zmax"
[[term]]
type = "surface_tension"
body = "cell"
gamma = 1e-3
[[term]]
type = "surface_tension"
body = "substrate"
surface = "zmax"
gamma = 1e-3
[[term]]
type = "surface_pressure"
body = "substrate"
surface = "xmin"
pressure = 20.0
)";

std::int64_t original(const Body& b, std::size_t i) {
  return b.original_id.empty() ? static_cast<std::int64_t>(i) : b.original_id[i];
}

// A unit-box random vector that depends only on the particle's one-rank id.
Vec3 noise(std::int64_t id, std::uint64_t salt) {
  SplitMix64 r(static_cast<std::uint64_t>(id) * 0x9e3779b97f4a7c15ULL + salt);
  return Vec3(r.symmetric_unit(), r.symmetric_unit(), r.symmetric_unit());
}

// A smooth finite deformation and a rough part the stabilization resists, and a
// perturbed director: the same physical state in either numbering.
void deform(Body& b, double amplitude = 1.0) {
  Mat3 A;
  A << 0.08, 0.03, -0.02, 0.01, -0.05, 0.04, 0.02, 0.0, 0.06;
  A *= amplitude;
  double volume = 0.0;  // the mean spacing: the same in either numbering
  for (double v : b.cloud.volume) volume += v;
  const double h = std::cbrt(volume / static_cast<double>(b.size()));
  for (std::size_t i = 0; i < b.size(); ++i) b.d[i] = A * b.cloud.X[i] + 0.05 * amplitude * h * noise(original(b, i), 1);
  if (materials::lce::material_of(b))
    for (std::size_t i = 0; i < b.size(); ++i)
      materials::lce::material_of(b)->director.h[i] = (materials::lce::material_of(b)->director.h[i] + 0.2 * noise(original(b, i), 2)).normalized();
}

// Poisons every slot this rank does not own, so a missing ghost shows up as NaN.
void poison_unowned(Body& b) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (Index i = 0; i < static_cast<Index>(b.size()); ++i)
    if (i < b.owned_begin() || i >= b.owned_end()) {
      b.d[i] = Vec3::Constant(nan);
      if (materials::lce::material_of(b)) materials::lce::material_of(b)->director.h[i] = Vec3::Constant(nan);
    }
}

void check_distributed_force(const std::string& text) {
  const par::Comm& comm = par::Comm::world();
  ASSERT_GE(comm.size(), 2) << "run this test with mpirun -np N, N >= 2 (the suite uses 2)";
  const auto scene = scene::parse_scene(text, "distributed.toml");
  auto serial = build_world(scene, par::Comm::self());
  auto distributed = build_world(scene, comm);
  Body& s = *serial->bodies.front();
  Body& d = *distributed->bodies.front();
  ASSERT_TRUE(d.distributed());
  ASSERT_FALSE(s.distributed());
  ASSERT_EQ(d.size(), s.size());
  // Both ranks own a part, and the parts tile the body.
  const auto owned = comm.sum(static_cast<std::int64_t>(d.owned_end() - d.owned_begin()));
  EXPECT_EQ(owned, static_cast<std::int64_t>(d.size()));
  EXPECT_GT(d.owned_end(), d.owned_begin());
  EXPECT_GT(d.ghosts.ghost_count(), 0u);

  deform(s);
  deform(d);
  poison_unowned(d);
  compute_internal_forces(s);
  compute_internal_forces(d);

  double scale = 0.0, error = 0.0, div_scale = 0.0, div_error = 0.0;
  for (Index i = d.owned_begin(); i < d.owned_end(); ++i) {
    const auto j = static_cast<std::size_t>(original(d, static_cast<std::size_t>(i)));
    // The same particle: the reference positions moved with the renumbering.
    ASSERT_EQ((d.cloud.X[i] - s.cloud.X[j]).norm(), 0.0);
    scale = std::max(scale, s.force[j].norm());
    error = std::max(error, (d.force[i] - s.force[j]).norm());
    if (materials::lce::material_of(d) && materials::lce::material_of(d)->director.frank) {
      div_scale = std::max(div_scale, materials::lce::material_of(s)->director.frank_divergence[j].norm());
      div_error = std::max(div_error, (materials::lce::material_of(d)->director.frank_divergence[i] - materials::lce::material_of(s)->director.frank_divergence[j]).norm());
    }
  }
  scale = comm.max(scale);
  error = comm.max(error);
  if (comm.root())
    std::cout << "distributed against one rank: largest force difference " << error / scale << " of the largest force, "
              << d.ghosts.ghost_count() << " ghosts on rank 0 of " << d.size() << " particles\n";
  ASSERT_GT(scale, 0.0);
  // The same bits: each particle's sum in the one-process order (rk/row_scatter.hpp).
  EXPECT_EQ(error, 0.0);
  if (materials::lce::material_of(d) && materials::lce::material_of(d)->director.frank) {
    div_scale = comm.max(div_scale);
    div_error = comm.max(div_error);
    ASSERT_GT(div_scale, 0.0);
    EXPECT_EQ(div_error, 0.0);
  }
  // Rank 0 makes the first contributions at every particle it shares: with one thread
  // it adds them all in place and sends each ghost's sum as one record per channel (the
  // later ranks send every contribution).
  if (comm.rank() == 0 && omp_get_max_threads() == 1) {
    const std::size_t channels = materials::lce::material_of(d) && materials::lce::material_of(d)->director.frank ? 2 : 1;
    EXPECT_LE(d.force_scatter.records_sent(), channels * d.ghosts.ghost_count());
    EXPECT_GT(d.force_scatter.records_sent(), 0u);
  }
  // The stabilization energy: each rank's share of the rows.
  const double stab = comm.sum(d.stabilization_energy);
  EXPECT_GT(s.stabilization_energy, 0.0);
  EXPECT_NEAR(stab, s.stabilization_energy, 1e-12 * s.stabilization_energy);
}

// Every body's total force (material and every term) at every owned particle against
// one rank, and the terms' energies, powers and step limits, the same on every rank, at
// a deformed state `amplitude` (deform) after forces at the states `before`.
void check_distributed_world_forces(const std::string& text, double amplitude, const std::vector<double>& before) {
  const par::Comm& comm = par::Comm::world();
  const auto scene = scene::parse_scene(text, "distributed.toml");
  auto serial = build_world(scene, par::Comm::self());
  auto distributed = build_world(scene, comm);
  for (auto* w : {serial.get(), distributed.get()}) {
    std::vector<double> states = before;
    states.push_back(amplitude);
    for (double a : states) {
      for (auto& b : w->bodies) {
        deform(*b, a);
        b->inertia = b->mass;
        b->v = b->d;  // a velocity field for the powers
      }
      for (auto& b : w->bodies)
        if (b->distributed()) poison_unowned(*b);
      compute_forces(*w);
    }
  }
  for (std::size_t k = 0; k < serial->bodies.size(); ++k) {
    const Body& s = *serial->bodies[k];
    const Body& d = *distributed->bodies[k];
    double scale = 0.0, error = 0.0;
    for (Index i = d.owned_begin(); i < d.owned_end(); ++i) {
      const auto j = static_cast<std::size_t>(original(d, static_cast<std::size_t>(i)));
      scale = std::max(scale, s.force[j].norm());
      error = std::max(error, (d.force[i] - s.force[j]).norm());
    }
    scale = comm.max(scale);
    error = comm.max(error);
    if (comm.root())
      std::cout << "body " << d.name << " with every term, " << comm.size() << " ranks against one: " << error / scale
                << " of the largest force\n";
    ASSERT_GT(scale, 0.0);
    EXPECT_EQ(error, 0.0) << d.name;
  }
  for (std::size_t t = 0; t < serial->terms.size(); ++t) {
    const Term& s = *serial->terms[t];
    const Term& d = *distributed->terms[t];
    const double e = s.stored_energy(*serial), p = s.power(*serial), dt = s.stable_dt(*serial);
    // Exact sums and ordered scatters: the same bits as one process.
    EXPECT_EQ(d.stored_energy(*distributed), e) << s.name();
    EXPECT_EQ(d.power(*distributed), p) << s.name();
    EXPECT_EQ(d.stable_dt(*distributed), dt) << s.name();
    // One value on every rank.
    EXPECT_EQ(comm.max(d.stored_energy(*distributed)), comm.min(d.stored_energy(*distributed))) << s.name();
  }
  EXPECT_NE(serial->terms[0]->stored_energy(*serial), 0.0) << "the bodies are within the contact cutoff";
  EXPECT_NE(serial->terms[3]->power(*serial), 0.0) << "the pressure does work";
}

}  // namespace

TEST(DistributedForce, CellOnSubstrateWithEveryTermMatchesOneRank) {
  omp_set_num_threads(1);
  check_distributed_world_forces(kCellOnSubstrate, 0.2, {});
}

// The contact pair list (and each rank's ghosts of the other body) rebuilt after a
// move beyond skin / 2, and kept after a smaller one.
TEST(DistributedForce, CellOnSubstrateMatchesOneRankAfterThePairListIsRebuiltAndKept) {
  omp_set_num_threads(1);
  check_distributed_world_forces(kCellOnSubstrate, 0.41, {0.2, 0.4});
}

TEST(DistributedForce, LceBallWithFrankTermMatchesOneRank) {
  omp_set_num_threads(1);
  check_distributed_force(kLceSphere);
}

TEST(DistributedForce, JitteredMooneyRivlinBlockMatchesOneRank) {
  omp_set_num_threads(2);  // threads within a rank too
  check_distributed_force(kMooneyRivlinBlock);
}

// A term that has not said it runs distributed (Term::distributed) stops a run on more
// than one rank at its [[term]] line, and passes on one rank.
// The Newton-Krylov finish runs on one process: on more ranks the run is refused at
// the key's line.
TEST(DistributedForce, TheNewtonKrylovFinishIsRefusedOnMoreThanOneRank) {
  std::string text = kMooneyRivlinBlock;
  const std::string dynamic = "mode = \"dynamic\"\nt_end = 1e-6\n";
  const auto at = text.find(dynamic);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, dynamic.size(), "mode = \"relax\"\nrelax_finish = \"newton_krylov\"\n");
  const auto scene = scene::parse_scene(text, "distributed.toml");
  for (const par::Comm* comm : {&par::Comm::self(), &par::Comm::world()}) {
    auto world = build_world(scene, *comm);
    if (!comm->parallel()) {
      EXPECT_NO_THROW(check_newton_krylov_finish(scene, *world));
      continue;
    }
    try {
      check_newton_krylov_finish(scene, *world);
      ADD_FAILURE() << "not refused";
    } catch (const SetupError& e) {
      EXPECT_NE(std::string(e.what()).find("[integrator] relax_finish = \"newton_krylov\": it runs on one process"),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(DistributedForce, ATermThatIsNotDistributedIsRefusedAtItsLine) {
  struct OneProcessTerm final : Term {
    std::string name() const override { return "one_process"; }
    void add_forces(World&) override {}
  };
  const std::string text = std::string(kMooneyRivlinBlock) +
                           "[[term]]\ntype = \"body_force\"\nbody = \"block\"\nacceleration = [0.0, 0.0, -1.0]\n";
  const auto scene = scene::parse_scene(text, "distributed.toml");
  for (const par::Comm* comm : {&par::Comm::self(), &par::Comm::world()}) {
    auto world = build_world(scene, *comm);
    EXPECT_NO_THROW(check_distributable_terms(scene, *world));  // body_force runs distributed
    world->terms[0] = std::make_unique<OneProcessTerm>();
    if (!comm->parallel()) {
      EXPECT_NO_THROW(check_distributable_terms(scene, *world));
      continue;
    }
    try {
      check_distributable_terms(scene, *world);
      ADD_FAILURE() << "not refused";
    } catch (const SetupError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("distributed.toml:20: [[term]] type = \"body_force\" does not run on more than one rank"),
                std::string::npos)
          << what;
    }
  }
}

// Pull copies the owner's value to every ghost; push adds each ghost's value to its owner once.
TEST(GhostExchange, PullCopiesOwnersValuesAndPushAddsEachGhostToItsOwnerOnce) {
  const par::Comm& comm = par::Comm::world();
  const auto world = build_world(scene::parse_scene(kMooneyRivlinBlock, "distributed.toml"), comm);
  const Body& b = *world->bodies.front();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Vec3> field(b.size(), Vec3::Constant(nan));
  for (Index i = b.owned_begin(); i < b.owned_end(); ++i) field[i] = noise(original(b, static_cast<std::size_t>(i)), 3);
  b.ghosts.pull(field);
  std::size_t checked = 0;
  for (const auto& group : b.ghosts.ghosts_by_owner())
    for (Index g : group) {
      EXPECT_EQ(field[g], noise(original(b, static_cast<std::size_t>(g)), 3)) << "ghost " << g;
      ++checked;
    }
  EXPECT_EQ(checked, b.ghosts.ghost_count());

  std::vector<Vec3> ones(b.size(), Vec3::Zero());
  for (Index i = b.owned_begin(); i < b.owned_end(); ++i) ones[i] = Vec3::Ones();
  for (const auto& group : b.ghosts.ghosts_by_owner())
    for (Index g : group) ones[g] = Vec3::Ones();
  b.ghosts.push_add(ones);
  double extra = 0.0;
  for (Index i = b.owned_begin(); i < b.owned_end(); ++i) extra += ones[i].x() - 1.0;
  // Every ghost on any rank came back to its owner exactly once.
  EXPECT_EQ(comm.sum(extra), static_cast<double>(comm.sum(static_cast<std::int64_t>(b.ghosts.ghost_count()))));
  EXPECT_EQ(static_cast<std::size_t>(extra), b.ghosts.send_count());
}

int main(int argc, char** argv) {
  rkpm::par::Session mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
