#include "cloud_checks.hpp"

#include "rkpm/particles/element_geometry.hpp"
#include "rkpm/particles/generators.hpp"

namespace rkpm::particles {
namespace {

using testing::report;

// Default resolution, moved and scaled.
SphereSpec off_centre_sphere() {
  SphereSpec spec;
  spec.center = Vec3(0.3, -0.2, 1.5);
  spec.radius = 2.0;
  return spec;
}

TEST(Sphere, CountsVolumeAreaNormalsAndClosure) {
  const SphereSpec spec = off_centre_sphere();
  const Cloud cloud = make_sphere(spec);
  std::cout << "sphere, " << spec.cells << " cells across:\n";
  ASSERT_EQ(spec.cells, 16);
  ASSERT_EQ(cloud.size(), 17u * 17u * 17u);
  EXPECT_EQ(cloud.boundary_particles.size(), 17u * 17u * 17u - 15u * 15u * 15u);

  const double volume_error =
      testing::relative_error(testing::sum(cloud.volume), ellipsoid_volume(Vec3::Constant(spec.radius)));
  report("sphere volume relative error", volume_error);
  // The dual cells fill the inscribed polyhedron: an O(h^2) deficit, 0.75 % at
  // 12 cells across, which is why the default is 16 (see VolumeConvergesAtSecondOrder).
  EXPECT_LE(volume_error, 5e-3);

  const double area_error = testing::relative_error(testing::boundary_area_sum(cloud),
                                                    4.0 * M_PI * spec.radius * spec.radius);
  report("sphere boundary area relative error", area_error);
  EXPECT_LT(area_error, 1e-2);

  // Surface particles lie exactly on the sphere.
  double radius_error = 0.0;
  for (const std::int32_t i : cloud.boundary_particles) {
    EXPECT_TRUE(cloud.on_surface(i, "surface"));
    radius_error = std::max(radius_error, std::abs((cloud.X[i] - spec.center).norm() - spec.radius));
  }
  EXPECT_LT(radius_error, 1e-14 * spec.radius);

  int n_checked = 0;
  const double angle = testing::max_normal_angle_deg(
      cloud, [](std::int32_t) { return true; }, [&](std::int32_t i) { return cloud.X[i] - spec.center; },
      n_checked);
  report("sphere normal max angle [deg]", angle);
  EXPECT_EQ(n_checked, static_cast<int>(cloud.boundary_particles.size()));
  EXPECT_LT(angle, 2.0);

  const auto closure = testing::closure_errors(cloud);
  report("sphere closure: max |sum area| / sum |area|", closure.area_sum);
  report("sphere closure: max |sum x area^T - V I| / V", closure.moment);
  EXPECT_LT(closure.area_sum, 1e-12);
  EXPECT_LT(closure.moment, 1e-12);
}

double volume_error(int cells) {
  SphereSpec spec;
  spec.cells = cells;
  const Cloud cloud = make_sphere(spec);
  return testing::relative_error(testing::sum(cloud.volume), 4.0 / 3.0 * M_PI);
}

TEST(Sphere, VolumeConvergesAtSecondOrder) {
  const double coarse = volume_error(16), fine = volume_error(32);
  report("sphere volume relative error, 32 cells", fine);
  EXPECT_LT(fine, 1.5e-3);
  EXPECT_NEAR(coarse / fine, 4.0, 0.5);
}

// The cells at the cube's corners keep three faces on the sphere, so their
// surface corner flattens as the mesh is refined (scaled Jacobian O(h)): the
// bound on the corner quality is loose, the one on volume uniformity is not.
TEST(Sphere, ElementQuality) {
  const SphereSpec spec = off_centre_sphere();
  const Cloud cloud = make_sphere(spec);
  double min_volume = 1e300, max_volume = 0.0, min_quality = 1.0;
  for (int e = 0; e < cloud.mesh.n_elements(); ++e) {
    min_volume = std::min(min_volume, element_volume(cloud, e));
    max_volume = std::max(max_volume, element_volume(cloud, e));
    min_quality = std::min(min_quality, element_min_scaled_jacobian(cloud, e));
  }
  report("sphere min element volume / max", min_volume / max_volume);
  report("sphere min scaled corner Jacobian", min_quality);
  EXPECT_GT(min_volume, 0.0);
  EXPECT_GT(min_volume / max_volume, 0.3);
  EXPECT_GT(min_quality, 0.7 / spec.cells);  // 0.066 at 12 cells, 0.047 at 16
}

TEST(Sphere, IsDeterministic) {
  testing::expect_identical(make_sphere(off_centre_sphere()), make_sphere(off_centre_sphere()));
}

TEST(Sphere, OddCellCountsWork) {
  SphereSpec spec;
  spec.cells = 7;
  const Cloud cloud = make_sphere(spec);
  EXPECT_EQ(cloud.size(), 8u * 8u * 8u);
  EXPECT_LT(testing::relative_error(testing::sum(cloud.volume), 4.0 / 3.0 * M_PI), 0.03);
}

TEST(Sphere, RejectsBadSpecs) {
  SphereSpec spec;
  spec.cells = 1;
  EXPECT_THROW(make_sphere(spec), CloudError);
  spec = SphereSpec{};
  spec.radius = 0.0;
  EXPECT_THROW(make_sphere(spec), CloudError);
}

}  // namespace
}  // namespace rkpm::particles
