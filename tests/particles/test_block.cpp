#include "cloud_checks.hpp"

#include "rkpm/particles/generators.hpp"

namespace rkpm::particles {
namespace {

using testing::report;

BlockSpec spec_with_jitter(double jitter) {
  BlockSpec spec;
  spec.origin = Vec3(-0.5, 1.0, 2.0);
  spec.size = Vec3(2.0, 1.0, 0.5);
  spec.cells = {10, 6, 4};
  spec.jitter = jitter;
  spec.seed = 7;
  return spec;
}

// A face particle belongs to exactly one named face (not an edge or corner).
bool on_one_face(const Cloud& cloud, std::int32_t i) {
  const std::uint32_t m = cloud.surface_mask[i];
  return m != 0 && (m & (m - 1)) == 0;
}

Vec3 face_normal(std::uint32_t mask) {
  for (int bit = 0; bit < 6; ++bit) {
    if (mask == (1u << bit)) {
      Vec3 n = Vec3::Zero();
      n[bit / 2] = bit % 2 == 0 ? -1.0 : 1.0;
      return n;
    }
  }
  return Vec3::Zero();
}

class BlockTest : public ::testing::TestWithParam<double> {};

TEST_P(BlockTest, CountsVolumesAreasNormalsAndClosure) {
  const BlockSpec spec = spec_with_jitter(GetParam());
  const Cloud cloud = make_block(spec);
  std::cout << "block, jitter " << spec.jitter << ":\n";

  ASSERT_EQ(cloud.size(), 11u * 7u * 5u);
  EXPECT_EQ(cloud.mesh.n_elements(), 10 * 6 * 4);
  // Surface nodes of an 11 x 7 x 5 grid: all minus the 9 x 5 x 3 interior.
  EXPECT_EQ(cloud.boundary_particles.size(), 11u * 7u * 5u - 9u * 5u * 3u);
  EXPECT_EQ(cloud.boundary_faces.size(), 2u * (10 * 6 + 6 * 4 + 10 * 4));

  // Planar faces: the dual cells tile the box exactly, jittered or not.
  const double exact_volume = spec.size.prod();
  const double volume_error = testing::relative_error(testing::sum(cloud.volume), exact_volume);
  report("block volume relative error", volume_error);
  EXPECT_LT(volume_error, 1e-12);

  const Vec3& s = spec.size;
  const double exact_area = 2.0 * (s.x() * s.y() + s.y() * s.z() + s.z() * s.x());
  const double area_error = testing::relative_error(testing::boundary_area_sum(cloud), exact_area);
  report("block boundary area relative error", area_error);
  EXPECT_LT(area_error, 1e-12);

  // Jitter never moves a particle off its face.
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(cloud.size()); ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      if (cloud.surface_mask[i] & (1u << (2 * axis))) {
        EXPECT_EQ(cloud.X[i][axis], spec.origin[axis]);
      }
      if (cloud.surface_mask[i] & (2u << (2 * axis))) {
        EXPECT_EQ(cloud.X[i][axis], spec.origin[axis] + s[axis]);
      }
    }
  }

  int n_checked = 0;
  const double angle = testing::max_normal_angle_deg(
      cloud, [&](std::int32_t i) { return on_one_face(cloud, i); },
      [&](std::int32_t i) { return face_normal(cloud.surface_mask[i]); }, n_checked);
  report("block face-interior normal max angle [deg]", angle);
  EXPECT_EQ(n_checked, 2 * (9 * 5 + 5 * 3 + 9 * 3));
  EXPECT_LT(angle, 1e-10);

  const auto closure = testing::closure_errors(cloud);
  report("block closure: max |sum area| / sum |area|", closure.area_sum);
  report("block closure: max |sum x area^T - V I| / V", closure.moment);
  EXPECT_LT(closure.area_sum, 1e-12);
  EXPECT_LT(closure.moment, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Jitter, BlockTest, ::testing::Values(0.0, 0.25));

TEST(Block, RegularCellsHaveEqualInteriorVolumes) {
  const Cloud cloud = make_block(spec_with_jitter(0.0));
  const double h3 = 0.2 * (1.0 / 6.0) * 0.125;
  // Interior particle (5, 3, 2): a full cell; corner particle 0: an eighth.
  EXPECT_NEAR(cloud.volume[5 + 11 * (3 + 7 * 2)], h3, 1e-15);
  EXPECT_NEAR(cloud.volume[0], h3 / 8, 1e-16);
}

TEST(Block, JitterIsDeterministicAndSeeded) {
  const Cloud a = make_block(spec_with_jitter(0.25));
  const Cloud b = make_block(spec_with_jitter(0.25));
  testing::expect_identical(a, b);
  BlockSpec other = spec_with_jitter(0.25);
  other.seed = 8;
  EXPECT_NE(make_block(other).X, a.X);
  EXPECT_NE(make_block(spec_with_jitter(0.0)).X, a.X);
}

TEST(Block, SurfaceMasks) {
  const Cloud cloud = make_block(spec_with_jitter(0.0));
  EXPECT_TRUE(cloud.on_surface(0, "xmin"));
  EXPECT_TRUE(cloud.on_surface(0, "ymin"));
  EXPECT_TRUE(cloud.on_surface(0, "zmin"));
  EXPECT_FALSE(cloud.on_surface(0, "xmax"));
  EXPECT_EQ(cloud.surface_bit("nonexistent"), 0u);
  EXPECT_FALSE(cloud.on_surface(0, "nonexistent"));
  int on_xmax = 0;
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(cloud.size()); ++i) on_xmax += cloud.on_surface(i, "xmax");
  EXPECT_EQ(on_xmax, 7 * 5);
}

TEST(Block, RejectsBadSpecs) {
  BlockSpec spec;
  spec.jitter = 0.4;
  EXPECT_THROW(make_block(spec), CloudError);
  spec = BlockSpec{};
  spec.cells = {0, 1, 1};
  EXPECT_THROW(make_block(spec), CloudError);
  spec = BlockSpec{};
  spec.size = Vec3(1.0, -1.0, 1.0);
  EXPECT_THROW(make_block(spec), CloudError);
}

}  // namespace
}  // namespace rkpm::particles
