// The partition of a cloud over ranks (par/partition.hpp), both methods: a permutation
// with one contiguous, balanced range per part, deterministic, and a cut of the
// mesh-edge graph close to the best plane's on a structured block. The curve partition
// keeps the numbering (the identity permutation) and cuts a Morton-ordered 2:1 block
// across its long side.
#include "rkpm/par/partition.hpp"
#include "rkpm/particles/generators.hpp"
#include "rkpm/particles/renumber.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

using namespace rkpm;

namespace {
particles::Cloud block(int nx, int ny, int nz) {
  particles::BlockSpec s;
  s.size = Vec3(1e-6 * nx, 1e-6 * ny, 1e-6 * nz);
  s.cells = {nx, ny, nz};
  return particles::make_block(s);
}
}  // namespace

TEST(Partition, OnePartIsTheIdentity) {
  const auto cloud = block(3, 3, 3);
  const auto p = par::partition_cloud(cloud, 1);
  ASSERT_EQ(p.offset, (std::vector<Index>{0, static_cast<Index>(cloud.size())}));
  for (std::size_t i = 0; i < p.order.size(); ++i) EXPECT_EQ(p.order[i], static_cast<std::int32_t>(i));
}

TEST(Partition, PartsAreBalancedContiguousRangesOfAPermutationWithAFewCutEdges) {
  const auto cloud = block(19, 19, 19);  // 20^3 particles, 3 x 20 x 20 x 19 hex edges
  const auto n = static_cast<Index>(cloud.size());
  for (const auto method : {par::PartitionMethod::kCurve, par::PartitionMethod::kMetis})
  for (int parts : {2, 4}) {
    const auto p = par::partition_cloud(cloud, parts, method);
    std::vector<std::int32_t> sorted = p.order;
    std::sort(sorted.begin(), sorted.end());
    for (Index i = 0; i < n; ++i) ASSERT_EQ(sorted[static_cast<std::size_t>(i)], i);
    ASSERT_EQ(p.offset.size(), static_cast<std::size_t>(parts) + 1);
    EXPECT_EQ(p.offset.front(), 0);
    EXPECT_EQ(p.offset.back(), n);
    for (int r = 0; r < parts; ++r) {
      const Index size = p.offset[r + 1] - p.offset[r];
      EXPECT_LE(size, 1.04 * n / parts) << "part " << r;  // METIS k-way's default 3 % imbalance
      EXPECT_GE(size, 0.96 * n / parts) << "part " << r;
    }
    // A plane through a 20 x 20 x 20 grid cuts 400 edges; two planes 800. A random
    // split would cut about half of the 22,800.
    auto renumbered = cloud;
    particles::renumber(renumbered, p.order);
    const std::int64_t cut = par::cut_edges(renumbered, p.offset);
    const std::int64_t planes = parts == 2 ? 400 : 800;
    std::cout << parts << " parts: " << cut << " cut edges (planes: " << planes << ")\n";
    EXPECT_LE(cut, 2 * planes);
    EXPECT_GE(cut, planes / 2);
    // Deterministic.
    const auto again = par::partition_cloud(cloud, parts, method);
    EXPECT_EQ(again.order, p.order);
    EXPECT_EQ(again.offset, p.offset);
  }
}

TEST(Partition, TheCurveKeepsTheNumberingAndCutsAMortonBlockAcrossItsLongSide) {
  auto cloud = block(39, 19, 19);  // 40 x 20 x 20 particles
  particles::renumber(cloud, particles::morton_order(cloud.X));
  const auto p = par::partition_cloud(cloud, 2);
  for (std::size_t i = 0; i < p.order.size(); ++i) ASSERT_EQ(p.order[i], static_cast<std::int32_t>(i));
  // One plane of 20 x 20 particles across x: 400 cut edges; a slab cut along x would
  // cut 800.
  EXPECT_EQ(par::cut_edges(cloud, p.offset), 400);
  for (Index i = 0; i < p.offset[1]; ++i) EXPECT_LT(cloud.X[static_cast<std::size_t>(i)].x(), 20e-6) << i;
}

TEST(Partition, MorePartsThanParticlesIsAClearError) {
  const auto cloud = block(1, 1, 1);  // 8 particles
  try {
    par::partition_cloud(cloud, 9);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("8 particles"), std::string::npos) << what;
    EXPECT_NE(what.find("9 parts"), std::string::npos) << what;
  }
}
