// The wall_contact term (src/terms/wall_contact/): no force in the reference state, forces
// equal to minus the gradient of its energy (central differences), no net force, and
// a shell pressed flat keeps its two faces apart where without the term they pass
// through each other.
#include "sim_fixtures.hpp"

#include "rkpm/sim/history.hpp"
#include "terms/wall_contact/wall_contact.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

namespace rkpm::sim {
namespace {

using testing::build_from_text;

// A coarse thick shell of the seed's size (R x H x T = 5 x 3 x 0.5 um), Mooney-Rivlin,
// with `extra` appended (initial state, terms).
std::string shell_scene(const std::string& extra) {
  return R"([scene]
name = "walls"
[integrator]
mode = "relax"
relax_force_tol = 1e-4
relax_velocity_tol = 1e-8
[[body]]
name = "cell"
density = 1000.0
[body.cloud]
generator = "shell"
semi_axes = [5e-6, 5e-6, 1.5e-6]
thickness = 0.5e-6
face_cells = 8
layers = 3
[body.material]
model = "mooney_rivlin"
c1 = 1e3
c2 = 0
lambda = 1e4
)" + extra;
}

// distance 0.8 um, exclusion 1.2 um: the faces' inner sheets are 2 um apart in the
// reference shell, so they interact once pressed closer than 0.8 um.
// An outer pressure of 300 Pa, which flattens the shell until its faces meet.
const char* const kOuterPressure = R"(
[[term]]
type = "surface_pressure"
body = "cell"
surface = "outer"
pressure = 300
)";

const char* const kWallContact = R"(
[[term]]
type = "wall_contact"
body = "cell"
surface = "inner"
distance = 0.8e-6
pressure = 1e3
exclusion = 1.2e-6
)";

WallContact& wall_term(World& world) {
  for (auto& t : world.terms)
    if (auto* w = dynamic_cast<WallContact*>(t.get())) return *w;
  throw std::runtime_error("no wall_contact term");
}

// The term's own forces at the present state (body.force zeroed first).
double term_forces(World& world, WallContact& term) {
  Body& body = *world.bodies.front();
  for (auto& f : body.force) f.setZero();
  term.add_forces(world);
  return term.energy();
}

TEST(WallContact, ReferenceShellCarriesNoContactForce) {
  testing::ScopedThreads one(1);
  auto sw = build_from_text(shell_scene(kWallContact));
  WallContact& term = wall_term(*sw.world);
  EXPECT_EQ(term_forces(*sw.world, term), 0.0);
  EXPECT_EQ(term.active_pairs(), 0u);
  for (const auto& f : sw.world->bodies.front()->force) EXPECT_EQ(f.norm(), 0.0);
  // The exclusion is what keeps it at zero: neighbours on the inner surface (across its
  // tight equatorial fold and along it) are closer than the contact distance.
  const Body& body = *sw.world->bodies.front();
  int close_neighbours = 0;
  for (Index i : term.particles())
    for (Index j : term.particles())
      if (i != j && (body.cloud.X[i] - body.cloud.X[j]).norm() < 0.8e-6) ++close_neighbours;
  EXPECT_GT(close_neighbours, 100);
}

// Two facing walls at gap d: the pressure of each particle of the top sheet (its contact
// force over its area) against the continuum law p(d) = 2 pi p0 (d/s0) w(d/s0) of
// docs/theory/contact.md. The shell (surface spacing 0.2 um, s0 = 0.8 um, so each particle
// feels about 10 of the other wall) is squeezed until its inner sheets are 0.9 s0 apart
// on the axis; near the axis they are flat and parallel.
TEST(WallContact, FlatWallsPressWithTheContinuumLaw) {
  testing::ScopedThreads one(1);
  const double s0 = 0.8e-6, p0 = 1e3, lambda = 0.36;  // inner sheets at +-1.0 um * lambda
  std::string text = shell_scene(fmt::format("[body.initial]\nstretch = [1.0, 1.0, {}]\n", lambda) + kWallContact);
  text.replace(text.find("face_cells = 8"), 14, "face_cells = 24");
  text.replace(text.find("layers = 3"), 10, "layers = 2");
  auto sw = build_from_text(text);
  World& world = *sw.world;
  const Body& body = *world.bodies.front();
  WallContact& term = wall_term(world);
  term_forces(world, term);
  const auto law = [&](double d) {
    const double u6 = std::pow(s0 / d, 6);
    return 2.0 * M_PI * p0 * (d / s0) * (u6 * u6 - 2.0 * u6 + 1.0);
  };
  double worst = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < term.particles().size(); ++k) {
    const Index I = term.particles()[k];
    const Vec3& X = body.cloud.X[I];
    if (X.z() <= 0.0 || std::hypot(X.x(), X.y()) > 1.0e-6) continue;
    const std::size_t b = static_cast<std::size_t>(
        std::find(body.cloud.boundary_particles.begin(), body.cloud.boundary_particles.end(), I) -
        body.cloud.boundary_particles.begin());
    const double d = 2.0 * lambda * X.z();  // the bottom sheet is the top one's mirror image
    const double measured = term.point_force()[k].z() / body.cloud.boundary_area[b];
    worst = std::max(worst, std::abs(measured / law(d) - 1.0));
    ++count;
  }
  ASSERT_GT(count, 10);
  std::cout << "  " << count << " particles, largest deviation from p(d): " << worst << "\n";
  EXPECT_LT(worst, 0.10);
}

// Squeezed to 0.3 along the axis, the inner sheets sit 0.6 um apart: inside the contact
// distance. The generalized forces are minus the energy gradient with respect to d.
TEST(WallContact, ForcesAreMinusTheEnergyGradient) {
  testing::ScopedThreads one(1);
  auto sw = build_from_text(shell_scene(std::string("[body.initial]\nstretch = [1.0, 1.0, 0.3]\n") + kWallContact));
  World& world = *sw.world;
  Body& body = *world.bodies.front();
  WallContact& term = wall_term(world);
  const double e0 = term_forces(world, term);
  ASSERT_GT(term.active_pairs(), 20u);
  ASSERT_GT(e0, 0.0);
  const std::vector<Vec3> force = body.force;
  double largest = 0.0;
  Vec3 total = Vec3::Zero();
  for (const auto& f : force) {
    largest = std::max(largest, f.norm());
    total += f;
  }
  // Pair forces are equal and opposite and the RK functions reproduce constants.
  EXPECT_LT(total.norm(), 1e-10 * largest);
  // Central differences on the particles with the largest forces, every axis.
  std::vector<std::size_t> order(force.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::partial_sort(order.begin(), order.begin() + 6, order.end(),
                    [&](std::size_t a, std::size_t b) { return force[a].norm() > force[b].norm(); });
  const double h = 1e-5 * 0.8e-6;
  for (int n = 0; n < 6; ++n) {
    const std::size_t I = order[static_cast<std::size_t>(n)];
    for (int axis = 0; axis < 3; ++axis) {
      const double d0 = body.d[I][axis];
      body.d[I][axis] = d0 + h;
      const double ep = term_forces(world, term);
      body.d[I][axis] = d0 - h;
      const double em = term_forces(world, term);
      body.d[I][axis] = d0;
      EXPECT_NEAR(force[I][axis], -(ep - em) / (2.0 * h), 1e-6 * largest) << "particle " << I << " axis " << axis;
    }
  }
}

// An outer pressure of 300 Pa flattens the shell (no enclosed fluid). Without the term
// the top face passes through the bottom one; with it the faces stop near the contact
// distance.
TEST(WallContact, ShellPressedFlatKeepsItsFacesApart) {
  testing::ScopedThreads two(2);
  for (const bool with_term : {false, true}) {
    auto sw = build_from_text(shell_scene(std::string(kOuterPressure) + (with_term ? kWallContact : "")));
    Integrator integrator(*sw.world, sw.settings);
    integrator.initialize();
    for (int step = 0; step < 20000 && !integrator.converged(); ++step) integrator.step();
    ASSERT_TRUE(integrator.converged()) << "with_term = " << with_term;
    const ShapeReport s = final_shape(*sw.world->bodies.front());
    EXPECT_EQ(s.walls_crossed, !with_term) << "gap " << s.inner_gap_centre << " min " << s.inner_gap_min << " h_min " << s.h_min;
    if (with_term) {
      // The walls stop where the contact pressure carries the load: a little inside s0.
      EXPECT_GT(s.inner_gap_centre, 0.6e-6);
      EXPECT_LT(s.inner_gap_centre, 0.8e-6);
      EXPECT_GT(wall_term(*sw.world).active_pairs(), 0u);
    } else {
      EXPECT_LT(s.inner_gap_centre, -1e-6);
    }
  }
}

// contact_mass_scaling: on the squeezed shell, with random velocities, raising the
// pressed particles' inertia to a step four times the contact's own brings the contact's
// limit to that step (within 1 %), makes no particle lighter, leaves the particles without a pair
// alone, keeps every velocity, and does nothing when asked for a step the contact
// already allows.
TEST(WallContact, ContactMassScalingRaisesTheContactsStep) {
  testing::ScopedThreads two(2);
  auto sw = build_from_text(shell_scene("[body.initial]\nstretch = [1.0, 1.0, 0.3]\nrandom_velocity = 1e-3\n" +
                                        std::string(kWallContact)));
  World& world = *sw.world;
  Body& body = *world.bodies.front();
  WallContact& term = wall_term(world);
  term_forces(world, term);
  ASSERT_GT(term.active_pairs(), 0u);
  const double own = term.stable_dt(world);
  ASSERT_TRUE(std::isfinite(own));
  const std::vector<double> inertia_before = body.inertia;
  const std::vector<Vec3> v_before = body.v;

  term.scale_inertia_to(world, 0.5 * own);  // already allowed: nothing changes
  EXPECT_EQ(body.inertia, inertia_before);
  EXPECT_EQ(body.v, v_before);

  const double target = 4.0 * own;
  term.scale_inertia_to(world, target);
  // The facing walls' particles are raised alike, so the passes bring the stiffest row
  // to the bound: the contact's limit lands on the step asked for, not far past it (that
  // would mean particles made heavier than needed).
  EXPECT_NEAR(term.stable_dt(world) / target, 1.0, 0.01);
  std::vector<char> on_surface(body.size(), 0);
  for (Index I : term.particles()) on_surface[static_cast<std::size_t>(I)] = 1;
  EXPECT_EQ(body.v, v_before);
  int raised = 0;
  for (std::size_t I = 0; I < body.size(); ++I) {
    EXPECT_GE(body.inertia[I], inertia_before[I]);
    if (!on_surface[I]) {
      EXPECT_EQ(body.inertia[I], inertia_before[I]);
    }
    if (body.inertia[I] > inertia_before[I]) ++raised;
  }
  EXPECT_GT(raised, 0);
  EXPECT_LT(raised, static_cast<int>(term.particles().size()));  // only the pressed ones
}

// The same equilibrium with and without contact_mass_scaling: the shell pressed flat
// (surface pressure and wall contact), relaxed to a tight residual both ways; the final
// displacements agree to 1e-3 of the largest (the relaxation study's criterion for a
// faster route), the scaled run made the contact heavier, and its energy ledger, which
// books the kinetic energy the heavier particles gained, balances as well as the plain
// run's.
TEST(WallContact, ContactMassScalingReachesTheSameEquilibrium) {
  testing::ScopedThreads two(2);
  std::vector<std::vector<Vec3>> finals;
  std::vector<std::int64_t> steps;
  std::vector<double> ledger_error;
  for (const bool scaled : {false, true}) {
    std::string text = shell_scene(std::string(kOuterPressure) + kWallContact);
    text.replace(text.find("relax_force_tol = 1e-4"), 22,
                 std::string("relax_force_tol = 1e-6") + (scaled ? "\ncontact_mass_scaling = true" : ""));
    auto sw = build_from_text(text);
    ASSERT_EQ(sw.settings.contact_mass_scaling, scaled);
    Integrator integrator(*sw.world, sw.settings);
    integrator.initialize();
    for (int step = 0; step < 40000 && !integrator.converged(); ++step) integrator.step();
    ASSERT_TRUE(integrator.converged()) << "scaled = " << scaled;
    const Body& body = *sw.world->bodies.front();
    if (scaled) {
      double heaviest = 0.0;
      for (std::size_t I = 0; I < body.size(); ++I) heaviest = std::max(heaviest, body.inertia[I] / body.mass[I]);
      EXPECT_GT(heaviest, 1.0);
    }
    finals.push_back(body.d);
    ledger_error.push_back(integrator.measure_energy().relative_error());
    steps.push_back(sw.world->step);
  }
  double largest = 0.0, difference = 0.0;
  for (std::size_t I = 0; I < finals[0].size(); ++I) {
    largest = std::max(largest, finals[0][I].norm());
    difference = std::max(difference, (finals[1][I] - finals[0][I]).norm());
  }
  std::cout << "  steps " << steps[0] << " plain, " << steps[1] << " with contact_mass_scaling; difference "
            << difference / largest << " of the largest displacement; ledger errors " << ledger_error[0] << ", "
            << ledger_error[1] << "\n";
  EXPECT_LT(difference, 1e-3 * largest);
  EXPECT_LT(ledger_error[1], 2.0 * ledger_error[0] + 1e-3);
}

}  // namespace
}  // namespace rkpm::sim
