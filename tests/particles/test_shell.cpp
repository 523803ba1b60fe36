#include "cloud_checks.hpp"

#include "rkpm/particles/element_geometry.hpp"
#include "rkpm/particles/generators.hpp"

#include <chrono>

namespace rkpm::particles {
namespace {

using testing::report;

// The requirement at the default resolution, for the seed's 0.5 um wall and a
// thinner one: volume within 0.5 %, area within 1 %, both surfaces' normals within
// 2 degrees. The inner rim (semi-axes 4.5, 4.5, 1.0 um) has a radius of curvature
// of only c^2/a = 0.22 um, which the meridian sampling refines (see
// MeridianSamplingRefinesTheRim).
struct ShellCase {
  double thickness;
};

class ShellTest : public ::testing::TestWithParam<ShellCase> {};

TEST_P(ShellTest, CountsVolumeAreaNormalsAndClosure) {
  ShellSpec spec;
  spec.center = Vec3(1e-6, -2e-6, 0.5e-6);
  spec.thickness = GetParam().thickness;
  const auto start = std::chrono::steady_clock::now();
  const Cloud cloud = make_shell(spec);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "shell, thickness " << spec.thickness << ":\n";
  report("shell generation time [s] (informative)", seconds);

  // The seed's count: 6 * 32^2 + 2 particles per layer, 5 layers.
  ASSERT_EQ(cloud.size(), 30730u);
  EXPECT_EQ(cloud.mesh.n_elements(), 6 * 32 * 32 * 4);
  EXPECT_EQ(cloud.boundary_particles.size(), 2u * 6146u);

  const Vec3 outer = spec.semi_axes;
  const Vec3 inner = (outer.array() - spec.thickness).matrix();
  const double volume_error = testing::relative_error(testing::sum(cloud.volume),
                                                      ellipsoid_volume(outer) - ellipsoid_volume(inner));
  report("shell volume relative error", volume_error);
  EXPECT_LE(volume_error, 5e-3);

  const double area_error = testing::relative_error(testing::boundary_area_sum(cloud),
                                                    ellipsoid_area(outer) + ellipsoid_area(inner));
  report("shell boundary area relative error (outer + inner)", area_error);
  EXPECT_LE(area_error, 1e-2);

  // Surface particles lie on their ellipsoids.
  double level_error = 0.0;
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(cloud.size()); ++i) {
    const Vec3 x = cloud.X[i] - spec.center;
    if (cloud.on_surface(i, "outer")) level_error = std::max(level_error, std::abs(x.cwiseQuotient(outer).norm() - 1));
    if (cloud.on_surface(i, "inner")) level_error = std::max(level_error, std::abs(x.cwiseQuotient(inner).norm() - 1));
  }
  EXPECT_LT(level_error, 1e-13);

  int n_outer = 0, n_inner = 0;
  const double outer_angle = testing::max_normal_angle_deg(
      cloud, [&](std::int32_t i) { return cloud.on_surface(i, "outer"); },
      [&](std::int32_t i) { return ellipsoid_normal(outer, cloud.X[i] - spec.center); }, n_outer);
  // The inner surface's outward normal points into the cavity.
  const double inner_angle = testing::max_normal_angle_deg(
      cloud, [&](std::int32_t i) { return cloud.on_surface(i, "inner"); },
      [&](std::int32_t i) { return Vec3(-ellipsoid_normal(inner, cloud.X[i] - spec.center)); }, n_inner);
  report("shell outer normal max angle [deg]", outer_angle);
  report("shell inner normal max angle [deg]", inner_angle);
  EXPECT_EQ(n_outer, 6146);
  EXPECT_EQ(n_inner, 6146);
  EXPECT_LE(outer_angle, 2.0);
  EXPECT_LE(inner_angle, 2.0);

  double min_quality = 1.0;
  for (int e = 0; e < cloud.mesh.n_elements(); ++e) min_quality = std::min(min_quality, element_min_scaled_jacobian(cloud, e));
  report("shell min scaled corner Jacobian", min_quality);
  EXPECT_GT(min_quality, 0.0);

  const auto closure = testing::closure_errors(cloud);
  report("shell closure: max |sum area| / sum |area|", closure.area_sum);
  report("shell closure: max |sum x area^T - V I| / V", closure.moment);
  EXPECT_LT(closure.area_sum, 1e-12);
  EXPECT_LT(closure.moment, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Thickness, ShellTest, ::testing::Values(ShellCase{0.5e-6}, ShellCase{0.3e-6}));

struct NormalAngles {
  double outer = 0.0, inner = 0.0;
};

NormalAngles max_normal_angles(int face_cells) {
  ShellSpec spec;
  spec.face_cells = face_cells;
  const Cloud cloud = make_shell(spec);
  const Vec3 outer = spec.semi_axes, inner = (outer.array() - spec.thickness).matrix();
  int n = 0;
  NormalAngles worst;
  worst.outer = testing::max_normal_angle_deg(
      cloud, [&](std::int32_t i) { return cloud.on_surface(i, "outer"); },
      [&](std::int32_t i) { return ellipsoid_normal(outer, cloud.X[i] - spec.center); }, n);
  worst.inner = testing::max_normal_angle_deg(
      cloud, [&](std::int32_t i) { return cloud.on_surface(i, "inner"); },
      [&](std::int32_t i) { return Vec3(-ellipsoid_normal(inner, cloud.X[i] - spec.center)); }, n);
  return worst;
}

// The normal error shrinks under refinement. Its largest values sit where the
// rows of the cubed sphere cross the vertical cube edges next to the rim, and
// there it falls at first order (halving h roughly halves it), so the bound on
// the ratio is that of a first-order error, not of the rim's second-order one.
TEST(Shell, NormalErrorConvergesUnderRefinement) {
  const NormalAngles coarse = max_normal_angles(32), fine = max_normal_angles(64);
  report("shell outer normal max angle, face_cells 32 [deg]", coarse.outer);
  report("shell inner normal max angle, face_cells 32 [deg]", coarse.inner);
  report("shell outer normal max angle, face_cells 64 [deg]", fine.outer);
  report("shell inner normal max angle, face_cells 64 [deg]", fine.inner);
  EXPECT_LT(fine.outer, 0.25);
  EXPECT_LT(fine.inner, 0.25);
  EXPECT_GT(coarse.outer / fine.outer, 1.8);
  EXPECT_GT(coarse.inner / fine.inner, 1.8);
}

// Along the meridian through the +x face centre the cubed sphere's colatitude
// steps are uniform, so the surface particles there show the meridian sampling
// itself: spacing graded from the flat caps to the rim, where the normal turns
// fastest, with a bounded ratio of longest to shortest step, and a bounded turn
// of the exact normal from one particle to the next. (Uniform arc length gives a
// spacing ratio of 1 but turns of 32 degrees per step at the inner rim and 20 at
// the outer one; the bounds below fail for it.)
struct MeridianSteps {
  double spacing_ratio = 0.0;      // longest / shortest chord
  double rim_to_pole = 0.0;        // chord at the equator / chord at the pole
  double max_turn_deg = 0.0;       // largest angle between neighbours' exact normals
};

MeridianSteps meridian_steps(const Cloud& cloud, const std::string& surface, const Vec3& axes) {
  std::vector<Vec3> meridian;  // particles with y = 0, x > 0, from the north pole down
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(cloud.size()); ++i) {
    if (cloud.on_surface(i, surface) && cloud.X[i].y() == 0.0 && cloud.X[i].x() >= 0.0) meridian.push_back(cloud.X[i]);
  }
  std::sort(meridian.begin(), meridian.end(), [](const Vec3& a, const Vec3& b) { return a.z() > b.z(); });
  EXPECT_EQ(meridian.size(), 2u * 32u + 1u);  // pole to pole, 64 steps
  MeridianSteps steps;
  double shortest = 1e300, longest = 0.0;
  for (std::size_t k = 0; k + 1 < meridian.size(); ++k) {
    const double d = (meridian[k + 1] - meridian[k]).norm();
    shortest = std::min(shortest, d);
    longest = std::max(longest, d);
    const double c = ellipsoid_normal(axes, meridian[k]).dot(ellipsoid_normal(axes, meridian[k + 1]));
    steps.max_turn_deg = std::max(steps.max_turn_deg, std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI);
  }
  const std::size_t mid = meridian.size() / 2;  // the equator particle
  steps.spacing_ratio = longest / shortest;
  steps.rim_to_pole = (meridian[mid + 1] - meridian[mid]).norm() / (meridian[1] - meridian[0]).norm();
  return steps;
}

TEST(Shell, MeridianSamplingRefinesTheRim) {
  const ShellSpec spec;
  const Cloud cloud = make_shell(spec);
  const Vec3 outer = spec.semi_axes, inner = (outer.array() - spec.thickness).matrix();
  struct Case {
    std::string surface;
    Vec3 axes;
    double turn_bound_deg;
  };
  for (const auto& [surface, axes, turn_bound_deg] : {Case{"outer", outer, 18.0}, Case{"inner", inner, 25.0}}) {
    const MeridianSteps steps = meridian_steps(cloud, surface, axes);
    report("shell " + surface + " meridian spacing longest/shortest", steps.spacing_ratio);
    report("shell " + surface + " meridian spacing rim/pole", steps.rim_to_pole);
    report("shell " + surface + " meridian max normal turn per step [deg]", steps.max_turn_deg);
    EXPECT_LT(steps.spacing_ratio, 2.0);
    EXPECT_LT(steps.rim_to_pole, 0.8);
    EXPECT_LT(steps.max_turn_deg, turn_bound_deg);
  }
}

TEST(Shell, IsDeterministic) {
  ShellSpec spec;
  spec.face_cells = 8;
  spec.layers = 3;
  testing::expect_identical(make_shell(spec), make_shell(spec));
}

TEST(Shell, TriaxialEllipsoidWorks) {
  ShellSpec spec;
  spec.semi_axes = Vec3(3.0, 2.0, 1.0);
  spec.thickness = 0.4;
  spec.face_cells = 16;
  spec.layers = 3;
  const Cloud cloud = make_shell(spec);
  const Vec3 inner = (spec.semi_axes.array() - spec.thickness).matrix();
  const double volume_error = testing::relative_error(
      testing::sum(cloud.volume), ellipsoid_volume(spec.semi_axes) - ellipsoid_volume(inner));
  report("triaxial shell volume relative error", volume_error);
  EXPECT_LT(volume_error, 1e-2);
  const auto closure = testing::closure_errors(cloud);
  EXPECT_LT(closure.area_sum, 1e-12);
  EXPECT_LT(closure.moment, 1e-12);
}

TEST(Shell, RejectsBadSpecs) {
  ShellSpec spec;
  spec.thickness = 2e-6;  // exceeds the 1.5 um polar semi-axis
  EXPECT_THROW(make_shell(spec), CloudError);
  spec = ShellSpec{};
  spec.layers = 1;
  EXPECT_THROW(make_shell(spec), CloudError);
  spec = ShellSpec{};
  spec.face_cells = 0;
  EXPECT_THROW(make_shell(spec), CloudError);
}

}  // namespace
}  // namespace rkpm::particles
