// The contact pair list against a brute-force search: exactly the same pairs at a
// build, and no pair inside the cutoff missed while rebuilds are skipped (every
// particle moved less than skin/2 since the last build).
#include "contact_fixtures.hpp"

#include "terms/contact/contact.hpp"
#include "terms/contact/contact_pairs.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <utility>

namespace rkpm::sim {
namespace {

using PairSet = std::set<std::pair<Index, Index>>;

PairSet brute_force(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double radius) {
  PairSet s;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j)
      if ((a[i] - b[j]).norm() < radius) s.emplace(static_cast<Index>(i), static_cast<Index>(j));
  return s;
}

// Listed pairs within `radius` at the current positions.
PairSet listed_within(const ContactPairs& p, const std::vector<Vec3>& a, const std::vector<Vec3>& b, double radius) {
  PairSet s;
  for (Index i = 0; i + 1 < static_cast<Index>(p.row_offset().size()); ++i)
    for (Index k = p.row_offset()[i]; k < p.row_offset()[i + 1]; ++k)
      if ((a[i] - b[p.partner()[k]]).norm() < radius) s.emplace(i, p.partner()[k]);
  return s;
}

std::vector<Vec3> random_points(testing::Random& rng, std::size_t n, const Vec3& centre, double half) {
  std::vector<Vec3> x(n);
  for (auto& p : x) p = centre + half * rng.vector();
  return x;
}

TEST(ContactPairs, BuildFindsExactlyTheBruteForcePairsAndTheTransposeMatches) {
  testing::Random rng{7};
  const auto a = random_points(rng, 400, Vec3(0, 0, 0), 1.0);
  const auto b = random_points(rng, 500, Vec3(0.8, 0, 0.3), 1.0);
  ContactPairs pairs(0.3, 0.1);
  pairs.rebuild(a, b);
  const PairSet expected = brute_force(a, b, 0.4);
  PairSet listed;
  for (Index i = 0; i < 400; ++i)
    for (Index k = pairs.row_offset()[i]; k < pairs.row_offset()[i + 1]; ++k) {
      listed.emplace(i, pairs.partner()[k]);
      if (k > pairs.row_offset()[i]) {
        EXPECT_LT(pairs.partner()[k - 1], pairs.partner()[k]);  // sorted rows
      }
    }
  std::printf("build: %zu listed pairs, brute force %zu\n", listed.size(), expected.size());
  ASSERT_GT(expected.size(), 1000u);
  EXPECT_EQ(listed, expected);
  // Transpose: every entry appears once under its column, in increasing row order.
  std::size_t seen = 0;
  for (Index j = 0; j < 500; ++j)
    for (Index k = pairs.column_offset()[j]; k < pairs.column_offset()[j + 1]; ++k) {
      const Index e = pairs.column_entry()[k];
      EXPECT_EQ(pairs.partner()[e], j);
      if (k > pairs.column_offset()[j]) {
        EXPECT_LT(pairs.entry_row()[pairs.column_entry()[k - 1]], pairs.entry_row()[e]);
      }
      ++seen;
    }
  EXPECT_EQ(seen, pairs.size());
}

// A term's static filter (the wall contact's exclusion of reference neighbours): the
// list holds exactly the brute-force pairs the filter keeps, in the same sorted rows,
// and a list built without its transpose holds no column view.
TEST(ContactPairs, AFilteredListHoldsExactlyTheKeptPairsAndNoTransposeWhenNotAsked) {
  testing::Random rng{11};
  const auto a = random_points(rng, 400, Vec3(0, 0, 0), 1.0);
  const auto keep = [](Index i, Index j) { return (i + j) % 3 != 0; };
  ContactPairs all(0.3, 0.1), filtered(0.3, 0.1, keep, false);
  all.rebuild(a, a);
  filtered.rebuild(a, a);
  PairSet expected;
  for (const auto& [i, j] : brute_force(a, a, 0.4))
    if (keep(i, j)) expected.insert({i, j});
  PairSet listed;
  for (Index i = 0; i < 400; ++i)
    for (Index k = filtered.row_offset()[i]; k < filtered.row_offset()[i + 1]; ++k) {
      listed.emplace(i, filtered.partner()[k]);
      if (k > filtered.row_offset()[i]) {
        EXPECT_LT(filtered.partner()[k - 1], filtered.partner()[k]);
      }
    }
  ASSERT_GT(expected.size(), 1000u);
  EXPECT_EQ(listed, expected);
  EXPECT_LT(filtered.size(), all.size() * 3 / 4);  // about a third of the pairs dropped
  EXPECT_TRUE(filtered.column_offset().empty());
  EXPECT_TRUE(filtered.column_entry().empty());
  EXPECT_TRUE(filtered.entry_row().empty());
  EXPECT_EQ(all.entry_row().size(), all.size());
}

TEST(ContactPairs, SkippedRebuildsNeverMissAPairInsideTheCutoff) {
  testing::Random rng{11};
  auto a = random_points(rng, 300, Vec3(0, 0, 0), 1.0);
  auto b = random_points(rng, 300, Vec3(0.5, 0.2, 0), 1.0);
  const double cutoff = 0.3, skin = 0.1;
  ContactPairs pairs(cutoff, skin);
  int skipped = 0, steps = 200;
  for (int step = 0; step < steps; ++step) {
    // Random walk; the two bodies also drift through each other so pairs come and go.
    for (auto& p : a) p += 0.012 * rng.vector() + Vec3(0.004, 0, 0);
    for (auto& p : b) p += 0.012 * rng.vector() - Vec3(0.004, 0, 0);
    if (!pairs.update(a, b)) ++skipped;
    const PairSet expected = brute_force(a, b, cutoff);
    const PairSet found = listed_within(pairs, a, b, cutoff);
    ASSERT_EQ(found, expected) << "step " << step << ": the list missed a pair inside the cutoff";
  }
  std::printf("%d steps: %zu builds, %d skipped rebuilds\n", steps, pairs.builds(), skipped);
  EXPECT_GT(skipped, steps / 2);        // the skin saves most rebuilds ...
  EXPECT_GT(pairs.builds(), 10u);       // ... and the motion forces some
}

TEST(ContactPairs, TheContactTermCountsExactlyTheBruteForcePairsInsideItsCutoff) {
  testing::Random rng{3};
  const auto xa = random_points(rng, 200, Vec3(0, 0, 0), 1.0);
  const auto xb = random_points(rng, 250, Vec3(0, 0, 1.5), 1.0);
  auto a = testing::particle_body("a", xa, std::vector<double>(200, 1e-3));
  auto b = testing::particle_body("b", xb, std::vector<double>(250, 1e-3));
  ContactSettings s;
  s.epsilon = 1.0;
  s.s0 = 0.2;
  s.cutoff = 0.5;
  s.skin = 0.1;
  Contact contact(*a, *b, s);
  World world;
  contact.add_forces(world);
  const auto expected = brute_force(xa, xb, 0.5).size();
  EXPECT_EQ(contact.active_pairs(), expected);
  EXPECT_GT(expected, 100u);
}

}  // namespace
}  // namespace rkpm::sim
