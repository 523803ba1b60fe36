// Measurements shared by the particle-cloud tests: each returns the number a
// test asserts on and prints, so a failure shows how far off the cloud is.
#pragma once

#include "rkpm/particles/cloud.hpp"
#include "rkpm/particles/dual_cells.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <numeric>
#include <string>

namespace rkpm::particles::testing {

inline double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

inline double relative_error(double measured, double exact) { return std::abs(measured - exact) / std::abs(exact); }

// Prints a measured quantity and records it in the test's XML output.
inline void report(const std::string& what, double value) {
  std::cout << "  [measured] " << what << " = " << value << "\n";
  ::testing::Test::RecordProperty(what, std::to_string(value));
}

// Worst violation over all cells of the closed-surface identities of SCNI:
//   sum_facets area = 0                       (relative to sum |area|)
//   sum_facets point area^T = volume * I      (relative to volume)
struct ClosureErrors {
  double area_sum = 0.0;
  double moment = 0.0;
};

inline ClosureErrors closure_errors(const Cloud& cloud) {
  const DualCells cells(cloud);
  std::vector<DualFacet> facets;
  ClosureErrors worst;
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(cloud.size()); ++i) {
    cells.facets(i, facets);
    Vec3 area_sum = Vec3::Zero();
    double area_abs = 0.0;
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    for (const DualFacet& f : facets) {
      area_sum += f.area;
      area_abs += f.area.norm();
      moment += f.point * f.area.transpose();
    }
    const double v = cloud.volume[i];
    worst.area_sum = std::max(worst.area_sum, area_sum.norm() / area_abs);
    worst.moment = std::max(worst.moment, (moment - v * Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() / v);
  }
  return worst;
}

// Largest angle [deg] between a boundary particle's normal and `exact(i)`, over
// the boundary particles for which `select(i)` holds; counts them in `n_checked`.
inline double max_normal_angle_deg(const Cloud& cloud, const std::function<bool(std::int32_t)>& select,
                                   const std::function<Vec3(std::int32_t)>& exact, int& n_checked) {
  double worst = 0.0;
  n_checked = 0;
  for (std::size_t b = 0; b < cloud.boundary_particles.size(); ++b) {
    const std::int32_t i = cloud.boundary_particles[b];
    if (!select(i)) continue;
    ++n_checked;
    const double c = std::clamp(cloud.boundary_normal[b].dot(exact(i).normalized()), -1.0, 1.0);
    worst = std::max(worst, std::acos(c) * 180.0 / M_PI);
  }
  return worst;
}

inline double boundary_area_sum(const Cloud& cloud) { return sum(cloud.boundary_area); }

inline void expect_identical(const Cloud& a, const Cloud& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.X[i], b.X[i]) << "particle " << i;
    ASSERT_EQ(a.volume[i], b.volume[i]) << "particle " << i;
  }
  EXPECT_EQ(a.mesh.nodes, b.mesh.nodes);
  EXPECT_EQ(a.boundary_particles, b.boundary_particles);
  EXPECT_EQ(a.boundary_area, b.boundary_area);
  EXPECT_EQ(a.boundary_normal, b.boundary_normal);
  EXPECT_EQ(a.surface_mask, b.surface_mask);
}

}  // namespace rkpm::particles::testing
