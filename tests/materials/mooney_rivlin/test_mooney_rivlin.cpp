// Modified Mooney-Rivlin (seed Eq. 9-11): stress is the energy's derivative,
// objectivity, the Cauchy formula of VERIFICATION section 2 and its table.
#include "materials/mooney_rivlin/mooney_rivlin.hpp"

#include "support/finite_differences.hpp"
#include "support/random_tensors.hpp"
#include "support/solvers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace rkpm::materials {
namespace {

using testing::Rng;

const MooneyRivlin kVerificationMaterial{1.3, 0.7, 5.0};  // VERIFICATION section 2

// Deformations the FD and objectivity tests sweep: random ones plus the
// extremes the brief names (stretch 3, compression 0.3, J far from 1, shear).
std::vector<Mat3> sample_deformations(Rng& rng, int random_count) {
  std::vector<Mat3> Fs;
  Fs.push_back(Mat3::Identity());
  Fs.push_back(Vec3(3.0, 1.0, 1.0).asDiagonal());
  Fs.push_back(Vec3(0.3, 1.0, 1.0).asDiagonal());
  Fs.push_back(3.0 * Mat3::Identity());   // J = 27
  Fs.push_back(0.3 * Mat3::Identity());   // J = 0.027
  Mat3 shear = Mat3::Identity();
  shear(0, 1) = 2.0;
  Fs.push_back(shear);
  for (int i = 0; i < random_count; ++i) Fs.push_back(testing::random_deformation(rng, 0.3, 3.0, 1.0));
  return Fs;
}

TEST(MooneyRivlin, FirstPiolaIsEnergyGradient) {
  Rng rng(101);
  const MooneyRivlin m = kVerificationMaterial;
  double worst = 0.0;
  const auto Fs = sample_deformations(rng, 60);
  for (const Mat3& F : Fs) {
    const Mat3 P = m.first_piola(F);
    const Mat3 P_fd = testing::gradient([&](const Mat3& G) { return m.energy(G); }, F, 1e-4);
    const double error = (P - P_fd).norm() / std::max(P.norm(), m.shear_modulus());
    worst = std::max(worst, error);
    EXPECT_LE(error, 1e-6) << "F =\n" << F;
  }
  std::printf("Mooney-Rivlin |P - dW/dF|_fd / |P| over %zu deformations: max %.2e\n", Fs.size(), worst);
}

TEST(MooneyRivlin, CauchyMatchesPushForwardOfFirstPiola) {
  Rng rng(102);
  const MooneyRivlin m = kVerificationMaterial;
  double worst = 0.0;
  for (const Mat3& F : sample_deformations(rng, 50)) {
    const Mat3 sigma = m.cauchy(F);
    const Mat3 pushed = m.first_piola(F) * F.transpose() / F.determinant();
    const double error = (sigma - pushed).norm() / std::max(sigma.norm(), m.shear_modulus());
    worst = std::max(worst, error);
    EXPECT_LE(error, 1e-12);
    EXPECT_LE((sigma - sigma.transpose()).norm(), 1e-12 * sigma.norm());
  }
  std::printf("Mooney-Rivlin |sigma - P F^T / J| / |sigma|: max %.2e\n", worst);
}

TEST(MooneyRivlin, ReferenceStateIsStressFree) {
  const MooneyRivlin m = kVerificationMaterial;
  EXPECT_LE(m.first_piola(Mat3::Identity()).norm(), 1e-14 * m.shear_modulus());
  EXPECT_NEAR(m.energy(Mat3::Identity()), 0.0, 1e-14);
}

TEST(MooneyRivlin, Objectivity) {
  Rng rng(103);
  const MooneyRivlin m = kVerificationMaterial;
  double worst_energy = 0.0, worst_stress = 0.0;
  for (const Mat3& F : sample_deformations(rng, 50)) {
    const Mat3 Q = testing::random_rotation(rng);
    const double W = m.energy(F);
    const double energy_error = std::abs(m.energy(Q * F) - W) / std::max(std::abs(W), m.shear_modulus());
    const Mat3 sigma = m.cauchy(F);
    const double stress_error = (m.cauchy(Q * F) - Q * sigma * Q.transpose()).norm() /
                                std::max(sigma.norm(), m.shear_modulus());
    worst_energy = std::max(worst_energy, energy_error);
    worst_stress = std::max(worst_stress, stress_error);
    EXPECT_LE(energy_error, 1e-12);
    EXPECT_LE(stress_error, 1e-12);
  }
  std::printf("Mooney-Rivlin objectivity: energy %.2e, Cauchy %.2e (relative)\n", worst_energy, worst_stress);
}

TEST(MooneyRivlin, SmallStrainModuli) {
  const MooneyRivlin m{2.126e3, 1.7e2, 1.7e5};  // the seed's substrate (section 4.2)
  const double e = 1e-7;
  // Simple shear: sigma_12 = mu gamma; pure dilation: pressure = -K dV/V.
  Mat3 shear = Mat3::Identity();
  shear(0, 1) = e;
  EXPECT_NEAR(m.cauchy(shear)(0, 1) / e, m.shear_modulus(), 1e-5 * m.shear_modulus());
  const Mat3 dilation = (1.0 + e) * Mat3::Identity();
  EXPECT_NEAR(m.cauchy(dilation).trace() / 3.0 / (3.0 * e), m.bulk_modulus(), 1e-5 * m.bulk_modulus());
}

// Uniaxial stress along e1 (or equibiaxial in e1, e2): find the free stretch t
// with sigma_22 = 0 (sigma_33 = 0) by Newton on the material's own Cauchy stress.
double free_lateral_stretch(const MooneyRivlin& m, double l, bool equibiaxial) {
  const auto F_of = [&](double t) -> Mat3 { return equibiaxial ? Vec3(l, l, t).asDiagonal() : Vec3(l, t, t).asDiagonal(); };
  const int free_axis = equibiaxial ? 2 : 1;
  return testing::solve_root([&](double t) { return m.cauchy(F_of(t))(free_axis, free_axis); }, 1.0, 1e-13);
}

TEST(MooneyRivlin, VerificationTable) {
  const MooneyRivlin m = kVerificationMaterial;
  struct Row {
    bool equibiaxial;
    double l, t, sigma11;
  };
  const Row rows[] = {{false, 1.1, 0.961283, 1.095302},
                      {false, 1.5, 0.836391, 5.288772},
                      {false, 2.0, 0.724709, 11.033278},
                      {true, 1.2, 0.770036, 3.526128}};
  for (const Row& row : rows) {
    const double t = free_lateral_stretch(m, row.l, row.equibiaxial);
    const Mat3 F = row.equibiaxial ? Mat3(Vec3(row.l, row.l, t).asDiagonal()) : Mat3(Vec3(row.l, t, t).asDiagonal());
    const double sigma11 = m.cauchy(F)(0, 0);
    std::printf("MR %s l = %.1f: t = %.7f (table %.6f), sigma11 = %.7f (table %.6f)\n",
                row.equibiaxial ? "equibiaxial" : "uniaxial", row.l, t, row.t, sigma11, row.sigma11);
    // The table is rounded to 6 decimals.
    EXPECT_NEAR(t, row.t, 1e-6);
    EXPECT_NEAR(sigma11, row.sigma11, 1e-6);
    if (!row.equibiaxial) {
      // VERIFICATION's uniaxial closed form sigma_11 = (2/J)(l^2 - t^2)(c1 + c2 t^2).
      const double J = row.l * t * t;
      EXPECT_NEAR(sigma11, 2.0 / J * (row.l * row.l - t * t) * (m.c1 + m.c2 * t * t), 1e-12 * sigma11);
    }
  }
}

TEST(MooneyRivlin, ValidationNamesTheBadParameter) {
  EXPECT_NO_THROW(kVerificationMaterial.validate());
  try {
    MooneyRivlin{1.0, 1.0, -2.0}.validate();
    FAIL() << "negative lambda accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("lambda = -2"), std::string::npos) << e.what();
  }
  EXPECT_THROW((MooneyRivlin{-1.0, 0.5, 1.0}.validate()), std::invalid_argument);
}

}  // namespace
}  // namespace rkpm::materials
