// The contact term's surface formulation (src/terms/contact/surface_contact.hpp):
// its law of two half-spaces against quadrature and the closed forms of the untruncated
// potential, and the term on clouds: the traction between two flat blocks, the balance
// of the forces, and the forces as the gradient of the energy.
#include "contact_fixtures.hpp"

#include "terms/contact/half_space_law.hpp"
#include "terms/contact/surface_contact.hpp"

#include <gtest/gtest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace rkpm::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Deliberately not 1: a wrong power of either changes every result.
constexpr double kS0 = 0.5, kEps = 2.0;

double potential(double r) {
  const double u6 = std::pow(kS0 / r, 6);
  return kEps * (u6 * u6 - 2.0 * u6);
}

// int_lo^hi f by 5-point Gauss-Legendre on `panels` geometrically graded panels (the
// integrands fall as r^-9 from lo): independent of the law's antiderivatives.
double integral(const std::function<double(double)>& f, double lo, double hi, int panels = 4000) {
  static const double x[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                              0.9061798459386640};
  static const double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                              0.2369268850561891};
  const double ratio = std::pow(hi / lo, 1.0 / panels);
  double sum = 0.0, a = lo;
  for (int p = 0; p < panels; ++p) {
    const double b = p + 1 == panels ? hi : a * ratio, mid = 0.5 * (a + b), half = 0.5 * (b - a);
    for (int k = 0; k < 5; ++k) sum += w[k] * half * f(mid + half * x[k]);
    a = b;
  }
  return sum;
}

TEST(SurfaceLaw, EnergyTractionAndSlopeMatchQuadratureOfTheShiftedPotential) {
  const double rc = 3.0 * kS0;
  const HalfSpaceLaw law(kEps, kS0, rc);
  const double shift = potential(rc);
  const auto phi_s = [&](double r) { return potential(r) - shift; };
  for (const double D : {0.3 * kS0, 0.55 * kS0, 0.6368 * kS0, 0.8 * kS0, 1.3 * kS0, 2.5 * kS0, 2.99 * kS0}) {
    const double energy = kPi * integral([&](double r) { return phi_s(r) * r * (r - D) * (r - D); }, D, rc);
    const double traction = 2.0 * kPi * integral([&](double r) { return phi_s(r) * r * (r - D); }, D, rc);
    const double slope = -2.0 * kPi * integral([&](double r) { return phi_s(r) * r; }, D, rc);
    // Scales: each term's size at D, so that a near-zero crossing is not judged relatively.
    const double scale = kEps * std::pow(kS0, 4) * (std::pow(kS0 / D, 8) + 1.0);
    std::printf("D = %.4f s0: W %.10e (quadrature %.10e), sigma %.10e (%.10e), sigma' %.10e (%.10e)\n", D / kS0,
                law.energy(D), energy, law.traction(D), traction, law.traction_slope(D), slope);
    EXPECT_NEAR(law.energy(D), energy, 1e-10 * scale);
    EXPECT_NEAR(law.traction(D), traction, 1e-10 * scale / kS0);
    EXPECT_NEAR(law.traction_slope(D), slope, 1e-10 * scale / (kS0 * kS0));
  }
  EXPECT_EQ(law.energy(rc), 0.0);
  EXPECT_EQ(law.traction(1.1 * rc), 0.0);
}

TEST(SurfaceLaw, TractionIsMinusTheEnergysDerivative) {
  const HalfSpaceLaw law(kEps, kS0, 3.0 * kS0);
  for (const double D : {0.5 * kS0, 0.7 * kS0, 1.5 * kS0}) {
    const double h = 1e-5 * kS0;
    const double fd = -(law.energy(D + h) - law.energy(D - h)) / (2.0 * h);
    const double fd_slope = (law.traction(D + h) - law.traction(D - h)) / (2.0 * h);
    EXPECT_NEAR(law.traction(D), fd, 1e-7 * std::abs(law.traction(D)) + 1e-9 * kEps * std::pow(kS0, 3));
    EXPECT_NEAR(law.traction_slope(D), fd_slope, 1e-6 * std::abs(law.traction_slope(D)));
  }
}

// Far cutoff: the law of the untruncated 12-6 potential, W(D) = pi [C12 / (360 D^8) -
// C6 / (12 D^2)], whose zero-traction gap is 15^(-1/6) s0, work of adhesion
// (pi 15^(1/3) / 8) eps s0^4 and strength (2 sqrt(5) pi / 9) eps s0^3 at 5^(-1/6) s0
// (per unit rho1 rho2; scripts/lib/contact_theory.py derives them).
TEST(SurfaceLaw, FarCutoffGivesTheClosedFormsOfTheUntruncatedPotential) {
  const HalfSpaceLaw law(kEps, kS0, 1e4 * kS0);
  const double z0 = std::pow(15.0, -1.0 / 6.0) * kS0, peak = std::pow(5.0, -1.0 / 6.0) * kS0;
  const double w = kPi * std::cbrt(15.0) / 8.0 * kEps * std::pow(kS0, 4);
  const double sigma0 = 2.0 * std::sqrt(5.0) * kPi / 9.0 * kEps * std::pow(kS0, 3);
  std::printf("z0: traction %.3e (scale %.3e); w %.10e against %.10e; sigma0 %.10e against %.10e\n",
              law.traction(z0), sigma0, -law.energy(z0), w, -law.traction(peak), sigma0);
  EXPECT_NEAR(law.traction(z0), 0.0, 1e-7 * sigma0);  // the cutoff's tail: 1e-8 relative
  EXPECT_NEAR(-law.energy(z0), w, 1e-7 * w);
  EXPECT_NEAR(-law.traction(peak), sigma0, 1e-7 * sigma0);
  EXPECT_NEAR(law.traction_slope(peak), 0.0, 1e-6 * sigma0 / kS0);
}

// Two blocks of neo-Hookean material, the first above the second at gap D: the
// second extends more than a cutoff beyond the first on every side, so each particle of
// the first body's bottom face sees a half-space.
// With `graded`, the second block's moduli grow along x (seed Eq. 18) and the term's
// linear stiffness law takes eps from them.
std::string two_blocks(double gap, bool graded = false) {
  const std::string lower_material = graded ? "model = \"mooney_rivlin\"\nc1 = 4e4\nc2 = 1e4\nlambda = 4e5\n"
                                              "grade_axis = \"x\"\ngrade_a = 4.0\ngrade_b = 0.5"
                                            : "model = \"neo_hookean\"\nmu = 1e5\nlambda = 4e5";
  const std::string law = graded ? "stiffness_law = \"linear\"\nsubstrate = \"lower\"" : "";
  return fmt::format(R"([scene]
name = "surface_contact"
[integrator]
t_end = 1e-3
[[body]]
name = "upper"
density = 1000
[body.cloud]
generator = "block"
origin = [0, 0, {gap}]
size = [4e-6, 4e-6, 2e-6]
cells = [8, 8, 4]
[body.material]
model = "neo_hookean"
mu = 1e4
lambda = 4e4
[[body]]
name = "lower"
density = 1000
[body.cloud]
generator = "block"
origin = [-3e-6, -3e-6, -2e-6]
size = [10e-6, 10e-6, 2e-6]
cells = [20, 20, 4]
[body.material]
{lower_material}
[[term]]
type = "contact"
bodies = ["upper", "lower"]
s0 = 0.75e-6
epsilon = 3.265e-15
beta = [1e18, 2e18]
formulation = "surface"
{law}
)",
                     fmt::arg("gap", gap), fmt::arg("lower_material", lower_material), fmt::arg("law", law));
}

Vec3 total(const std::vector<Vec3>& forces) {
  Vec3 s = Vec3::Zero();
  for (const auto& f : forces) s += f;
  return s;
}

// Evaluates the term alone at the bodies' present state: its energy, with the
// generalized forces left in each body's force array.
double evaluate(World& world) {
  for (auto& b : world.bodies) std::fill(b->force.begin(), b->force.end(), Vec3::Zero());
  world.terms[0]->add_forces(world);
  return world.terms[0]->stored_energy(world);
}

TEST(SurfaceContact, FlatBlocksFeelTheHalfSpaceTractionAndBalance) {
  const double s0 = 0.75e-6, gap = 0.55e-6;
  auto w = testing::world_from_text(two_blocks(gap));
  World& world = *w.world;
  auto* term = dynamic_cast<SurfaceContact*>(world.terms[0].get());
  ASSERT_NE(term, nullptr) << "formulation = \"surface\" did not build the surface term";
  const double energy = evaluate(world);
  const Body& upper = *world.bodies[0];
  const HalfSpaceLaw law(3.265e-15, s0, 3.0 * s0);
  const double rho2 = 1e18 * 2e18, h = 0.5e-6;
  // Each particle of the bottom face away from its edges carries h^2 of the surface.
  const auto fields = term->output_fields(upper);
  ASSERT_EQ(fields.size(), 1u);
  const double* values = fields[0].values;
  const auto f = [&](std::size_t i) { return Vec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]); };
  int interior = 0;
  for (std::size_t i = 0; i < upper.size(); ++i) {
    const Vec3& X = upper.cloud.X[i];
    if (std::abs(X.z() - gap) > 1e-12 || X.x() < 0.1e-6 || X.x() > 3.9e-6 || X.y() < 0.1e-6 || X.y() > 3.9e-6)
      continue;
    ++interior;
    const double expected = h * h * rho2 * law.traction(gap);
    EXPECT_NEAR(f(i).z(), expected, 1e-12 * std::abs(expected));
    EXPECT_NEAR(f(i).x(), 0.0, 1e-12 * std::abs(expected));
    EXPECT_NEAR(f(i).y(), 0.0, 1e-12 * std::abs(expected));
  }
  EXPECT_EQ(interior, 7 * 7);
  // Equal and opposite on the two bodies' generalized coordinates (the RK functions
  // reproduce constants).
  const Vec3 fa = total(world.bodies[0]->force), fb = total(world.bodies[1]->force);
  std::printf("force on upper %.6e %.6e %.6e N, on lower %.6e %.6e %.6e N, energy %.6e J\n", fa.x(), fa.y(), fa.z(),
              fb.x(), fb.y(), fb.z(), energy);
  EXPECT_LT((fa + fb).norm(), 1e-12 * fa.norm());
  EXPECT_LT(energy, 0.0);  // 0.55 um lies beyond the zero-traction gap: adhesive
  EXPECT_LT(fa.z(), 0.0);
}

// A random smooth displacement of the first body and an in-plane one of the second
// (its top face stays flat, where the forces are the energy's exact gradient): the
// change of the energy against the work of the term's generalized forces (central
// differences).
// Without the stiffness law, and with it on a graded second body, where the pull along
// the face toward stronger adhesion (the gradient of eps) is part of the forces.
void check_gradient(bool graded) {
  auto w = testing::world_from_text(two_blocks(0.6e-6, graded));
  World& world = *w.world;
  testing::Random random(7);
  std::vector<std::vector<Vec3>> direction;
  for (auto& b : world.bodies) {
    direction.emplace_back(b->size());
    const Vec3 wave = random.vector();
    for (std::size_t i = 0; i < b->size(); ++i) {
      const Vec3& X = b->cloud.X[i];
      // Smooth in space (the clouds' spacing is 0.5 um), plus a rigid part.
      const Vec3 smooth(std::sin(2e6 * X.x()), std::cos(1.7e6 * X.y()), std::sin(1.3e6 * (X.x() + X.y())));
      direction.back()[i] = wave + (direction.size() == 1 ? smooth : Vec3(smooth.x(), smooth.y(), 0.0));
    }
  }
  const auto set = [&](double t) {
    for (std::size_t k = 0; k < world.bodies.size(); ++k) {
      Body& b = *world.bodies[k];
      std::vector<Vec3> d(b.size());
      for (std::size_t i = 0; i < b.size(); ++i) d[i] = t * direction[k][i];
      testing::move_to(b, d);
    }
  };
  for (const double t0 : {0.0, 2e-8, -3e-8}) {
    set(t0);
    evaluate(world);
    double work = 0.0;
    for (std::size_t k = 0; k < world.bodies.size(); ++k)
      for (std::size_t i = 0; i < world.bodies[k]->size(); ++i) work += world.bodies[k]->force[i].dot(direction[k][i]);
    const double dt = 1e-12;
    set(t0 + dt);
    const double ep = evaluate(world);
    set(t0 - dt);
    const double em = evaluate(world);
    const double slope = (ep - em) / (2.0 * dt);
    std::printf("%s, t = %.1e m: dE/dt %.10e, -work %.10e\n", graded ? "graded" : "uniform", t0, slope, -work);
    EXPECT_NEAR(slope, -work, 1e-6 * std::abs(work));
  }
}

TEST(SurfaceContact, ForcesAreTheGradientOfTheEnergyOverAFlatFace) { check_gradient(false); }

TEST(SurfaceContact, ForcesAreTheGradientOfTheEnergyUnderTheStiffnessLaw) { check_gradient(true); }

// On the graded block the lateral force on the first body points up the gradient of
// eps (toward the stiffer side, +x): the pull that moves a cell in durotaxis.
TEST(SurfaceContact, StiffnessLawPullsTowardStrongerAdhesion) {
  auto w = testing::world_from_text(two_blocks(0.6e-6, true));
  World& world = *w.world;
  evaluate(world);
  const Vec3 f = total(world.bodies[0]->force);
  std::printf("force on the upper block on the graded one: %.4e %.4e %.4e N\n", f.x(), f.y(), f.z());
  EXPECT_LT(f.z(), 0.0);                      // adhesive at 0.6 um
  EXPECT_GT(f.x(), 1e-3 * std::abs(f.z()));   // toward larger eps
  EXPECT_LT(std::abs(f.y()), 1e-9 * std::abs(f.z()));
}

// The second body's top face bent into a wave (slope up to 0.05) and the first body
// slid across it in steps of 1/50 of a particle spacing: the lateral force on it
// changes smoothly. With the distance's own gradient as the direction, the force on a
// particle over the valley between two facets flips with its side; the bottom
// particles of the first body cross such valleys in rows here, and the largest second
// difference of the lateral force was 1.7e-3 of the normal force with that direction
// (measured), 3.4e-5 with the corners' normals.
TEST(SurfaceContact, ForceTurnsSmoothlyOverABentFace) {
  auto w = testing::world_from_text(two_blocks(0.6e-6));
  World& world = *w.world;
  Body& upper = *world.bodies[0];
  Body& lower = *world.bodies[1];
  const double amplitude = 0.05e-6, length = 2.0 * kPi * amplitude / 0.05;
  std::vector<Vec3> bent(lower.size());
  for (std::size_t i = 0; i < lower.size(); ++i)
    bent[i] = Vec3(0.0, 0.0, amplitude * std::sin(2.0 * kPi * lower.cloud.X[i].x() / length));
  testing::move_to(lower, bent);
  std::vector<double> lateral, normal;
  for (int k = 0; k <= 50; ++k) {
    testing::move_to(upper, std::vector<Vec3>(upper.size(), Vec3(0.5e-6 * k / 50.0, 0.0, 0.0)));
    evaluate(world);
    const Vec3 f = total(upper.force);
    lateral.push_back(f.x());
    normal.push_back(f.z());
  }
  double largest_jump = 0.0;
  for (std::size_t k = 1; k + 1 < lateral.size(); ++k)
    largest_jump = std::max(largest_jump, std::abs(lateral[k + 1] - 2.0 * lateral[k] + lateral[k - 1]) /
                                              std::abs(normal[k]));
  std::printf("lateral force %.4e to %.4e N, normal %.4e N; largest second difference %.3e of the normal force\n",
              *std::min_element(lateral.begin(), lateral.end()), *std::max_element(lateral.begin(), lateral.end()),
              normal[0], largest_jump);
  EXPECT_LT(largest_jump, 1e-4);
}

}  // namespace
}  // namespace rkpm::sim
