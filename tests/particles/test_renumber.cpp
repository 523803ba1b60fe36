// Morton renumbering (particles/renumber.hpp): the renumbered cloud is the same cloud
// (positions, volumes, surfaces, boundary) under a permutation, and its elements span
// much narrower id ranges than the generator's layer-by-layer numbering.
#include "rkpm/particles/generators.hpp"
#include "rkpm/particles/renumber.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

using namespace rkpm::particles;

namespace {

// Mean over elements of (largest - smallest node id): how far apart in memory the
// particles of one neighbourhood are.
double mean_element_span(const Cloud& c) {
  double total = 0.0;
  for (int e = 0; e < c.mesh.n_elements(); ++e) {
    const auto* nodes = c.mesh.element_nodes(e);
    const auto [lo, hi] = std::minmax_element(nodes, nodes + c.mesh.element_size(e));
    total += *hi - *lo;
  }
  return total / c.mesh.n_elements();
}

Cloud shell() {
  ShellSpec spec;
  spec.face_cells = 12;
  return make_shell(spec);
}

}  // namespace

TEST(Renumber, MortonOrderIsAPermutationAndTheCloudMovesWithIt) {
  const Cloud before = shell();
  Cloud after = before;
  const auto order = morton_order(before.X);
  renumber(after, order);
  ASSERT_EQ(after.size(), before.size());
  double total_before = 0.0, total_after = 0.0;
  for (std::size_t k = 0; k < after.size(); ++k) {
    const auto old = static_cast<std::size_t>(order[k]);
    EXPECT_EQ(after.X[k], before.X[old]);
    EXPECT_EQ(after.surface_mask[k], before.surface_mask[old]);
    EXPECT_NEAR(after.volume[k], before.volume[old], 1e-12 * before.volume[old]);
    EXPECT_EQ(after.boundary_index[k] >= 0, before.boundary_index[old] >= 0) << "particle " << k;
    if (after.boundary_index[k] >= 0) {
      const auto a = static_cast<std::size_t>(after.boundary_index[k]);
      const auto b = static_cast<std::size_t>(before.boundary_index[old]);
      EXPECT_NEAR(after.boundary_area[a], before.boundary_area[b], 1e-12 * before.boundary_area[b]);
      EXPECT_LE((after.boundary_normal[a] - before.boundary_normal[b]).norm(), 1e-12);
    }
    total_before += before.volume[k];
    total_after += after.volume[k];
  }
  EXPECT_NEAR(total_after, total_before, 1e-12 * total_before);
  EXPECT_EQ(after.boundary_faces.size(), before.boundary_faces.size());
  const double span_before = mean_element_span(before), span_after = mean_element_span(after);
  std::cout << "mean element id span: generator " << span_before << ", Morton " << span_after << "\n";
  EXPECT_LT(span_after, 0.5 * span_before);  // 0.30 measured: a Z-curve still jumps between octants
}

TEST(Renumber, IsDeterministicAndRefusesAnOrderThatIsNotAPermutation) {
  const Cloud c = shell();
  EXPECT_EQ(morton_order(c.X), morton_order(c.X));
  Cloud bad = c;
  auto order = morton_order(c.X);
  order[1] = order[0];
  EXPECT_THROW(renumber(bad, order), std::invalid_argument);
  order.pop_back();
  EXPECT_THROW(renumber(bad, order), std::invalid_argument);
}
