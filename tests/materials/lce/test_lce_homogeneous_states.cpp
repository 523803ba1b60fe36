// Homogeneous states of the liquid-crystal elastomer with closed forms
// (VERIFICATION section 3): stretch along the director, the soft-elastic
// plateau across it, and the free body driven by the active stress alone.
// Near-incompressibility is K = 1e4 mu throughout.
#include "lce_fixtures.hpp"
#include "support/solvers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace rkpm::materials {
namespace {

using testing::Vector;

constexpr double kPi = 3.14159265358979323846;

LiquidCrystalElastomer nearly_incompressible(double s) {
  auto m = testing::dimensionless_lce(s);
  m.K = 1e4 * m.mu;
  m.kappa = 0.0;  // homogeneous states: no director gradients
  m.zeta = 0.0;
  return m;
}

// Director relaxed to equilibrium at F (h0 = e1).
DirectorPoint relaxed(const LiquidCrystalElastomer& m, const Mat3& F) {
  return {m.equilibrium_director(F, Vec3::UnitX()), Vec3::UnitX(), Mat3::Zero()};
}

TEST(LceHomogeneous, StretchAlongDirectorIsNeoHookean) {
  const auto m = nearly_incompressible(2.0);
  // Compression below l = s^(-1/3) (0.79 for s = 2) would turn the relaxed
  // director across the axis; 0.85 is the mildest compression tested.
  for (const double l : {0.85, 1.2, 1.5, 2.0, 3.0}) {
    const auto F_of = [&](double t) -> Mat3 { return Vec3(l, t, t).asDiagonal(); };
    const auto lateral_stress = [&](double t) { return m.cauchy(F_of(t), relaxed(m, F_of(t)))(1, 1) / m.mu; };
    const double t = testing::solve_root(lateral_stress, 1.0 / std::sqrt(l), 1e-10);
    const DirectorPoint d = relaxed(m, F_of(t));
    EXPECT_LE((d.h - Vec3::UnitX()).norm(), 1e-12);  // the director stays along the stretch
    const double sigma = m.cauchy(F_of(t), d)(0, 0);
    const double expected = m.mu * (l * l - 1.0 / l);
    std::printf("stretch along h0, l = %.2f: sigma11 = %.6f, mu (l^2 - 1/l) = %.6f, rel. error %.1e (K = 1e4 mu)\n", l,
                sigma, expected, std::abs(sigma - expected) / std::abs(expected));
    EXPECT_NEAR(sigma, expected, 1e-3 * std::abs(expected));
  }
}

// Stretch l along e2, perpendicular to h0 = e1. The free components are the
// lateral stretches F11, F33 and one shear in the plane of h0 and the stretch:
// F21 (the VERIFICATION case, F12 = 0 as between clamps) or F12. The energy,
// with the director at its equilibrium for each F, is minimised over them; by
// the envelope theorem its gradient is (P11, P_shear, P33) at that director.
struct SoftModeState {
  Mat3 F;
  DirectorPoint d;
  double energy;
  double nominal_stress;  // P22
};

enum class FreeShear { StretchAlongDirector /* F21 */, DirectorAlongStretch /* F12 */ };

SoftModeState minimise_across_director(const LiquidCrystalElastomer& m, double l,
                                       FreeShear shear = FreeShear::StretchAlongDirector) {
  const int row = shear == FreeShear::StretchAlongDirector ? 1 : 0;
  const auto F_of = [l, row](const Vector& x) {
    Mat3 F = Mat3::Zero();
    F(0, 0) = x[0];
    F(row, 1 - row) = x[1];
    F(1, 1) = l;
    F(2, 2) = x[2];
    return F;
  };
  const auto energy = [&](const Vector& x) { return m.energy(F_of(x), relaxed(m, F_of(x))); };
  const auto gradient = [&](const Vector& x) {
    const Mat3 P = m.first_piola_passive(F_of(x), relaxed(m, F_of(x)));
    Vector g(3);
    g << P(0, 0), P(row, 1 - row), P(2, 2);
    return g;
  };
  Vector x0(3);
  x0 << 1.0 / std::sqrt(l), 0.2, 1.0 / std::sqrt(l);  // a small shear breaks the symmetry
  const auto minimum = testing::minimise(energy, gradient, x0, 1e-11 * m.mu);
  const Mat3 F = F_of(minimum.x);
  const DirectorPoint d = relaxed(m, F);
  return {F, d, minimum.value, m.first_piola_passive(F, d)(1, 1)};
}

TEST(LceHomogeneous, SoftElasticPlateauAcrossTheDirector) {
  const double s = 2.0;
  const auto m = nearly_incompressible(s);
  const double plateau_end = std::sqrt(s);
  for (const double l : {1.05, 1.1, 1.2, 1.3, 1.4}) {
    ASSERT_LT(l, plateau_end);
    const SoftModeState state = minimise_across_director(m, l);
    const double theta = std::acos(std::min(1.0, std::abs(state.d.h.x()))) * 180.0 / kPi;
    const double expected_theta = std::asin(std::sqrt(s / (s - 1.0) * (1.0 - 1.0 / (l * l)))) * 180.0 / kPi;
    std::printf("soft plateau l = %.2f: W/mu = %.1e, P22/mu = %.1e, theta = %.3f deg (closed form %.3f)\n", l,
                state.energy / m.mu, state.nominal_stress / m.mu, theta, expected_theta);
    EXPECT_LE(std::abs(state.energy), 1e-8 * m.mu);
    EXPECT_LE(std::abs(state.nominal_stress), 1e-5 * m.mu);
    EXPECT_NEAR(theta, expected_theta, 1.0);
    EXPECT_NEAR(state.F.determinant(), 1.0, 1e-6);
  }
  // The brief's spot value: 51.4 deg at l = 1.2 for s = 2.
  const SoftModeState at_1_2 = minimise_across_director(m, 1.2);
  EXPECT_NEAR(std::acos(std::abs(at_1_2.d.h.x())) * 180.0 / kPi, 51.4, 0.1);
}

TEST(LceHomogeneous, PlateauIsIndependentOfTheClampingButTheAngleIsNot) {
  // With F12 free instead of F21 the incompressible zero-energy state has
  // F = [[1/l, g], [0, l]], g^2 = (l^2 - 1)(s - l^2)/l^2, and the director
  // angle sin^2 theta = (l^2 - 1)/(s - 1) (derived in docs/theory/materials.md).
  const double s = 2.0;
  const auto m = nearly_incompressible(s);
  for (const double l : {1.1, 1.3}) {
    const SoftModeState state = minimise_across_director(m, l, FreeShear::DirectorAlongStretch);
    const double theta = std::acos(std::min(1.0, std::abs(state.d.h.x()))) * 180.0 / kPi;
    const double expected_theta = std::asin(std::sqrt((l * l - 1.0) / (s - 1.0))) * 180.0 / kPi;
    std::printf("soft plateau, F12 free, l = %.2f: W/mu = %.1e, P22/mu = %.1e, theta = %.3f deg (closed form %.3f)\n",
                l, state.energy / m.mu, state.nominal_stress / m.mu, theta, expected_theta);
    EXPECT_LE(std::abs(state.energy), 1e-8 * m.mu);
    EXPECT_LE(std::abs(state.nominal_stress), 1e-5 * m.mu);
    EXPECT_NEAR(theta, expected_theta, 1.0);
  }
}

TEST(LceHomogeneous, BeyondThePlateauNominalStressFollowsClosedForm) {
  const double s = 2.0;
  const auto m = nearly_incompressible(s);
  for (const double l : {1.5, 1.7, 2.0, 2.5}) {
    const SoftModeState state = minimise_across_director(m, l);
    const double expected = m.mu * (l / s - std::sqrt(s) / (l * l));
    std::printf("beyond plateau l = %.2f: P22 = %.6f, mu (l/s - sqrt(s)/l^2) = %.6f, rel. error %.1e\n", l,
                state.nominal_stress, expected, std::abs(state.nominal_stress - expected) / expected);
    EXPECT_NEAR(state.nominal_stress, expected, 1e-2 * expected);
    EXPECT_NEAR(std::abs(state.d.h.y()), 1.0, 1e-6);  // the director has turned onto the stretch axis
  }
}

// Free body, director fixed along h = h0 = e1, active stress only; F = diag(l, t, t).
// Total Cauchy stress zero <=> (compressible extension, derived in docs/theory/materials.md)
//   sigma_11: mu (l^2 - t^2) / J = zeta,   sigma_22: K ln J = mu (1 - t^2),   J = l t^2,
// and in the incompressible limit l^2 - 1/l = zeta / mu.
struct ActiveStretch {
  double l, t;
};

ActiveStretch solve_with_material(const LiquidCrystalElastomer& m) {
  const DirectorPoint d{Vec3::UnitX(), Vec3::UnitX(), Mat3::Zero()};
  const auto residual = [&](const Vector& x) {
    const Mat3 sigma = m.cauchy(Vec3(x[0], x[1], x[1]).asDiagonal(), d);
    Vector r(2);
    r << sigma(0, 0) / m.mu, sigma(1, 1) / m.mu;
    return r;
  };
  const Vector x = testing::solve_roots(residual, Vector::Ones(2), 1e-10);
  return {x[0], x[1]};
}

// The closed form solved independently: for a trial t, J = exp(mu (1 - t^2) / K)
// and l = J / t^2; bisect on t for mu (l^2 - t^2) / J = zeta.
ActiveStretch solve_closed_form(const LiquidCrystalElastomer& m) {
  const auto mismatch = [&](double t) {
    const double J = std::exp(m.mu * (1.0 - t * t) / m.K);
    const double l = J / (t * t);
    return m.mu * (l * l - t * t) / J - m.zeta;
  };
  double lo = 0.3, hi = 1.5;  // mismatch decreases with t
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mismatch(mid) > 0.0 ? lo : hi) = mid;
  }
  const double t = 0.5 * (lo + hi);
  return {std::exp(m.mu * (1.0 - t * t) / m.K) / (t * t), t};
}

TEST(LceHomogeneous, ActiveStressAloneDeformsAFreeBody) {
  for (const double K_over_mu : {2.0, 1e4}) {
    for (const double zeta : {0.5, -0.3}) {
      auto m = nearly_incompressible(2.0);
      m.K = K_over_mu * m.mu;
      m.zeta = zeta;
      const ActiveStretch numeric = solve_with_material(m);
      const ActiveStretch closed = solve_closed_form(m);
      std::printf("active free body K/mu = %.0e, zeta/mu = %+.1f: l = %.9f (closed form %.9f), t = %.9f (%.9f)\n",
                  K_over_mu, zeta, numeric.l, closed.l, numeric.t, closed.t);
      EXPECT_NEAR(numeric.l, closed.l, 1e-8);
      EXPECT_NEAR(numeric.t, closed.t, 1e-8);
      // Sign convention: zeta > 0 elongates along h (extensile), zeta < 0 contracts.
      EXPECT_EQ(numeric.l > 1.0, zeta > 0.0);
      if (K_over_mu >= 1e4) {
        const double lhs = numeric.l * numeric.l - 1.0 / numeric.l;
        std::printf("  incompressible limit: l^2 - 1/l = %.6f vs zeta/mu = %.6f\n", lhs, zeta / m.mu);
        EXPECT_NEAR(lhs, zeta / m.mu, 1e-3 * std::abs(zeta / m.mu));
      }
    }
  }
}

}  // namespace
}  // namespace rkpm::materials
