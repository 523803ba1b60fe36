// The crawling study's uniform control (docs/verification/crawling.md) must not drift: its
// substrate and loading are symmetric under x -> -x and y -> -y about the cell's
// axis, so its clouds must be too. These tests build the cell and the block as
// examples/crawling/crawling.toml declares them (and at the study's coarse
// resolution) and check that each reflection maps every particle, volume, boundary
// area and normal and every dual-cell facet onto a partner, to round-off.
// The initial director, which the clouds alone do not fix, is checked in
// tests/sim/test_crawling_director.cpp.
#include "crawling_scene.hpp"
#include "mirror_checks.hpp"
#include "tet_mesh.hpp"

#include "rkpm/particles/generators.hpp"
#include "clouds/block/spec.hpp"
#include "clouds/sphere/spec.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <variant>

namespace rkpm::particles {
namespace {

struct CrawlingClouds {
  SphereSpec cell;
  BlockSpec substrate;
};

CrawlingClouds crawling_clouds(bool coarse) {
  const scene::Scene s = rkpm::testing::crawling_scene(coarse);
  return {clouds::sphere::spec(*s.find_body("cell")), clouds::block::spec(*s.find_body("substrate"))};
}

// Round-off bounds: positions come from a handful of operations on exactly
// mirrored inputs; volumes, areas and facets from sums whose order differs between
// a particle and its partner. A wrong diagonal or an off-centre node moves them by
// a sizeable fraction of a spacing, many orders above these bounds.
void expect_mirror_symmetric(const Cloud& cloud, const Vec3& centre, const char* what) {
  for (int axis = 0; axis < 2; ++axis) {
    const testing::MirrorErrors e = testing::mirror_errors(cloud, centre, axis);
    const char* plane = axis == 0 ? "x -> -x" : "y -> -y";
    std::cout << "  " << what << ", " << plane << ": position " << e.position << ", volume " << e.volume
              << ", area " << e.area << ", normal " << e.normal << ", facet point " << e.facet_point
              << ", facet area " << e.facet_area << "\n";
    EXPECT_EQ(e.unmatched, 0) << what << ", " << plane;
    EXPECT_LT(e.position, 1e-14) << what << ", " << plane;
    EXPECT_LT(e.volume, 1e-12) << what << ", " << plane << ": " << e.worst_volume;
    EXPECT_EQ(e.boundary_mismatch, 0) << what << ", " << plane;
    EXPECT_LT(e.area, 1e-12) << what << ", " << plane;
    EXPECT_LT(e.normal, 1e-12) << what << ", " << plane;
    EXPECT_EQ(e.facet_count_mismatch, 0) << what << ", " << plane;
    EXPECT_LT(e.facet_point, 1e-14) << what << ", " << plane;
    EXPECT_LT(e.facet_area, 1e-10) << what << ", " << plane;
  }
}

// The two mirror planes of the uniform control are the cell's axis; the block's
// must be the same planes, or the cell sits off the substrate's centre.
void expect_cell_centred_over_block(const CrawlingClouds& c) {
  const Vec3 block_centre = c.substrate.origin + 0.5 * c.substrate.size;
  EXPECT_NEAR(c.cell.center.x(), block_centre.x(), 1e-12 * c.substrate.size.x());
  EXPECT_NEAR(c.cell.center.y(), block_centre.y(), 1e-12 * c.substrate.size.y());
}

// The check has teeth: splitting every hexahedron of a symmetric block around the
// same diagonal keeps the particles mirror-symmetric but not their cells.
TEST(CrawlingSymmetry, CheckCatchesAnAsymmetricDiagonal) {
  BlockSpec spec;
  spec.origin = Vec3(-2.0, -2.0, 0.0);
  spec.size = Vec3(4.0, 4.0, 1.0);
  spec.cells = {4, 4, 1};
  const Cloud cloud = testing::tet_block(spec);
  for (int axis = 0; axis < 2; ++axis) {
    const testing::MirrorErrors e = testing::mirror_errors(cloud, Vec3::Zero(), axis);
    std::cout << "  Kuhn tet block, axis " << axis << ": position " << e.position << ", volume " << e.volume
              << ", facet count mismatches " << e.facet_count_mismatch << "\n";
    EXPECT_EQ(e.unmatched, 0);
    EXPECT_LT(e.position, 1e-14);
    EXPECT_GT(e.volume, 0.1);
    EXPECT_GT(e.facet_count_mismatch, 0);
  }
}

TEST(CrawlingSymmetry, CellCentredOverBlock) {
  expect_cell_centred_over_block(crawling_clouds(false));
  expect_cell_centred_over_block(crawling_clouds(true));
}

TEST(CrawlingSymmetry, CellCloudIsMirrorSymmetric) {
  const SphereSpec spec = crawling_clouds(false).cell;
  expect_mirror_symmetric(make_sphere(spec), spec.center, "cell");
}

TEST(CrawlingSymmetry, BlockCloudIsMirrorSymmetric) {
  const BlockSpec spec = crawling_clouds(false).substrate;
  expect_mirror_symmetric(make_block(spec), spec.origin + 0.5 * spec.size, "substrate");
}

TEST(CrawlingSymmetry, CoarseCloudsAreMirrorSymmetric) {
  const CrawlingClouds c = crawling_clouds(true);
  expect_mirror_symmetric(make_sphere(c.cell), c.cell.center, "coarse cell");
  expect_mirror_symmetric(make_block(c.substrate), c.substrate.origin + 0.5 * c.substrate.size, "coarse substrate");
}

}  // namespace
}  // namespace rkpm::particles
