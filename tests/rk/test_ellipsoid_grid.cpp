// The bucket grid that finds the particles whose ellipsoidal supports can reach points
// near a centre (rk/ellipsoid_grid.hpp), its grids per orientation (rk/oriented_grids.hpp),
// and RKApproximation::candidates built on them: nothing that reaches a point within
// `reach` of the centre may be missed, for centres inside and outside the cloud, on a
// tilted thin wall, on a refined one whose supports are needles and on a jittered block,
// and a reach the grids do not cover falls back to the tree with the same contract.
#include "clouds.hpp"
#include "rkpm/rk/ellipsoid_grid.hpp"
#include "rkpm/rk/oriented_grids.hpp"
#include "rkpm/rk/rk_approximation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

using namespace rkpm;
using namespace rkpm::rk;

namespace {

// A thin shell refined in its plane (layers 0.2 um apart, in-plane spacing about
// 0.1 um): its supports are long across the wall and turn with it all round.
particles::Cloud thin_shell() {
  particles::ShellSpec spec;
  spec.semi_axes = Vec3(3e-6, 3e-6, 1.5e-6);
  spec.thickness = 0.4e-6;
  spec.layers = 3;
  spec.face_cells = 24;
  return particles::make_shell(spec);
}

// The same wall refined in its plane until its supports are needles across it (median
// longest over shortest semi-axis about 6): the grids per orientation take over.
particles::Cloud needle_shell() {
  particles::ShellSpec spec;
  spec.semi_axes = Vec3(2e-6, 2e-6, 1e-6);
  spec.thickness = 0.6e-6;
  spec.layers = 3;
  spec.face_cells = 32;
  return particles::make_shell(spec);
}

double squared_q(const Mat3& G, const Vec3& r) { return r.dot(G * r); }

// Every particle whose support covers one of `samples` points within `reach` of c
// (the centre, points on the sphere of radius reach and inside it).
std::set<Index> reaching(const std::vector<Vec3>& X, const std::vector<Mat3>& G, const Vec3& c, double reach,
                         std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> points{c};
  for (int s = 0; s < 400; ++s) {
    const Vec3 direction = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    points.push_back(c + direction * reach * (s % 2 == 0 ? 1.0 : std::cbrt(unit(rng))));
  }
  std::set<Index> out;
  for (std::size_t j = 0; j < X.size(); ++j)
    for (const Vec3& p : points)
      if (squared_q(G[j], p - X[j]) < 1.0) {
        out.insert(static_cast<Index>(j));
        break;
      }
  return out;
}

std::set<Index> in_ranges(const EllipsoidGrid& grid, const Vec3& c, double reach, double ball) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;
  grid.ranges(c, reach, ball, ranges);
  std::set<Index> out;
  for (const auto& [first, last] : ranges)
    for (std::uint32_t k = first; k < last; ++k) out.insert(grid.order()[k]);
  return out;
}

// Centres at particles, between them, and outside the cloud's box.
std::vector<Vec3> centres(const std::vector<Vec3>& X, std::mt19937& rng, int count) {
  Vec3 lo = X.front(), hi = X.front();
  for (const Vec3& x : X) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  std::uniform_int_distribution<std::size_t> pick(0, X.size() - 1);
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  const Vec3 size = hi - lo;
  std::vector<Vec3> out;
  for (int k = 0; k < count; ++k) {
    const Vec3 jitter(unit(rng), unit(rng), unit(rng));
    if (k % 3 == 0) out.push_back(X[pick(rng)]);
    else if (k % 3 == 1) out.push_back(X[pick(rng)] + 0.05 * size.cwiseProduct(jitter));
    else out.push_back(0.5 * (lo + hi) + 1.2 * size.cwiseProduct(jitter) * 2.0);  // up to 0.7 size outside
  }
  return out;
}

// A cloud's ellipsoidal supports (2 spacings), the grid over them and their largest
// semi-axis: what both checks below query.
struct GridOfSupports {
  explicit GridOfSupports(const particles::Cloud& cloud)
      : supports(ellipsoidal_supports(cloud, 2.0)),
        grid(cloud.X, entries(supports), supports.radius, supports.min_axis),
        a_max(*std::max_element(supports.radius.begin(), supports.radius.end())) {}
  static std::vector<SymmetricEntries> entries(const SupportEllipsoids& s) {
    std::vector<SymmetricEntries> metric;
    for (const Mat3& G : s.metric) metric.push_back(symmetric_entries(G));
    return metric;
  }
  SupportEllipsoids supports;
  EllipsoidGrid grid;
  double a_max;
};

void expect_no_particle_missed(const particles::Cloud& cloud, double reach_fraction) {
  const GridOfSupports g(cloud);
  const auto& supports = g.supports;
  const EllipsoidGrid& grid = g.grid;
  const double a_max = g.a_max;
  const double reach = reach_fraction * a_max;
  ASSERT_TRUE(grid.covers(reach));
  std::mt19937 rng(7);
  std::size_t needed = 0, visited = 0;
  for (const Vec3& c : centres(cloud.X, rng, 60)) {
    const auto must = reaching(cloud.X, supports.metric, c, reach, rng);
    const auto got = in_ranges(grid, c, reach, (a_max + reach) * (1.0 + 1e-9));
    for (Index j : must) EXPECT_TRUE(got.count(j)) << "particle " << j << " reaches within " << reach << " of ("
                                                   << c.transpose() << ") but is not in the grid's ranges";
    needed += must.size();
    visited += got.size();
  }
  EXPECT_GT(needed, 0u);  // the centres do meet supports
  std::cout << "needed " << needed << ", visited " << visited << "\n";
}

// As expect_no_particle_missed, for points in a box of half-widths `half` (per axis)
// around each centre: the query of a cell that is flat along some axes.
void expect_no_particle_missed_in_box(const particles::Cloud& cloud, const Vec3& half_fraction) {
  const GridOfSupports g(cloud);
  const auto& supports = g.supports;
  const EllipsoidGrid& grid = g.grid;
  const double a_max = g.a_max;
  const Vec3 half = half_fraction * a_max;
  ASSERT_TRUE(grid.covers(half.maxCoeff()));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t needed = 0, visited = 0, visited_by_radius = 0;
  for (const Vec3& c : centres(cloud.X, rng, 60)) {
    std::vector<Vec3> points{c};  // the box's corners and points inside it
    for (int k = 0; k < 8; ++k) points.push_back(c + Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1).cwiseProduct(half));
    for (int s = 0; s < 300; ++s) points.push_back(c + Vec3(unit(rng), unit(rng), unit(rng)).cwiseProduct(half));
    std::set<Index> must;
    for (std::size_t j = 0; j < cloud.X.size(); ++j)
      for (const Vec3& p : points)
        if (squared_q(supports.metric[j], p - cloud.X[j]) < 1.0) {
          must.insert(static_cast<Index>(j));
          break;
        }
    const double ball = (a_max + half.norm()) * (1.0 + 1e-9);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;
    grid.ranges(c, half, ball, ranges);
    std::set<Index> got;
    for (const auto& [first, last] : ranges)
      for (std::uint32_t k = first; k < last; ++k) got.insert(grid.order()[k]);
    for (Index j : must) EXPECT_TRUE(got.count(j)) << "particle " << j << " reaches the box around ("
                                                   << c.transpose() << ") but is not in the grid's ranges";
    needed += must.size();
    visited += got.size();
    visited_by_radius += in_ranges(grid, c, half.norm(), ball).size();
  }
  EXPECT_GT(needed, 0u);
  EXPECT_LT(visited, visited_by_radius) << "a flat box should visit fewer particles than its radius";
}

}  // namespace

TEST(EllipsoidGrid, MissesNoSupportOnATiltedThinWall) {
  expect_no_particle_missed(thin_shell(), 0.0);
  expect_no_particle_missed(thin_shell(), 0.3);
}

TEST(EllipsoidGrid, MissesNoSupportReachingAFlatBox) {
  expect_no_particle_missed_in_box(thin_shell(), Vec3(0.3, 0.05, 0.02));
  expect_no_particle_missed_in_box(test::jittered_block(6, 0.25), Vec3(0.02, 0.4, 0.1));
}

TEST(EllipsoidGrid, MissesNoSupportInAJitteredBlock) {
  expect_no_particle_missed(test::jittered_block(6, 0.25), 0.0);
  expect_no_particle_missed(test::jittered_block(6, 0.25), 0.4);
}

// On needles across a refined wall the grids per orientation miss nothing that reaches,
// and test fewer particles than the one grid's box holds (the reason they exist).
TEST(OrientedGrids, MissNoNeedleAndTestFewerThanOneGrid) {
  const particles::Cloud cloud = needle_shell();
  const auto supports = ellipsoidal_supports(cloud, 2.0);
  const auto metric = GridOfSupports::entries(supports);
  const OrientedGrids grids(cloud.X, metric, supports.radius, supports.min_axis);
  const EllipsoidGrid one(cloud.X, metric, supports.radius, supports.min_axis);
  ASSERT_GT(grids.classes(), 10u);  // the oriented path, not one class
  const double a_max = *std::max_element(supports.radius.begin(), supports.radius.end());
  std::mt19937 rng(5);
  std::vector<Index> kept;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;
  std::size_t tested = 0, visited_by_one = 0, needed = 0;
  for (double reach : {0.0, 0.3 * a_max}) {
    ASSERT_TRUE(grids.covers(reach));
    for (const Vec3& c : centres(cloud.X, rng, 24)) {
      const double ball = (a_max + reach) * (1.0 + 1e-9);
      kept.clear();
      tested += grids.candidates(c, reach, ball, 1.0 + 1e-9, kept, ranges);
      visited_by_one += in_ranges(one, c, reach, ball).size();
      const std::set<Index> got(kept.begin(), kept.end());
      EXPECT_EQ(got.size(), kept.size()) << "a particle listed twice";
      for (Index j : reaching(cloud.X, supports.metric, c, reach, rng)) {
        EXPECT_TRUE(got.count(j)) << "reach " << reach << ": particle " << j << " reaches (" << c.transpose()
                                  << ") but is not a candidate";
        ++needed;
      }
    }
  }
  EXPECT_GT(needed, 0u);
  EXPECT_LT(tested, visited_by_one / 2) << "tested " << tested << ", one grid's box " << visited_by_one;
}

// Given the points themselves (a cell's corners, elongated across the wall as the
// refined shell's are), the grids keep every particle that reaches one of them, and no
// more than the test by their distance alone keeps.
TEST(OrientedGrids, KeepEverySupportThatReachesOneOfThePoints) {
  const particles::Cloud cloud = needle_shell();
  const RKSettings settings = [] {
    RKSettings s;
    s.shape = SupportShape::Ellipsoid;
    return s;
  }();
  const RKApproximation rk(cloud, settings);
  const auto supports = ellipsoidal_supports(cloud, 2.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  CandidateSet by_points, by_reach;
  std::size_t needed = 0, kept_by_points = 0, kept_by_reach = 0;
  // Centres at particles, and (from centres()) between them and outside the cloud, where
  // a class's box in its frame decides whether its grid is asked at all.
  std::vector<Vec3> at;
  for (std::size_t i = 0; i < cloud.size(); i += cloud.size() / 40) at.push_back(cloud.X[i]);
  for (const Vec3& c : centres(cloud.X, rng, 30)) at.push_back(c);
  for (std::size_t i = 0; i < at.size(); ++i) {
    const Vec3 c = at[i];
    // Eight points in a box 0.3 um along the radius and 0.05 um across it.
    const Vec3 along = c.norm() > 0.0 ? Vec3(c.normalized()) : Vec3::UnitZ();
    const Vec3 across = along.unitOrthogonal(), third = along.cross(across);
    std::vector<Vec3> points;
    for (int k = 0; k < 8; ++k) points.push_back(c + 0.15e-6 * unit(rng) * along + 0.025e-6 * (unit(rng) * across + unit(rng) * third));
    rk.candidates(c, points.data(), points.size(), by_points);
    double reach = 0.0;
    for (const Vec3& p : points) reach = std::max(reach, (p - c).norm());
    rk.candidates(c, reach, by_reach);
    const std::set<Index> got(by_points.id.begin(), by_points.id.end());
    for (std::size_t j = 0; j < cloud.size(); ++j)
      for (const Vec3& p : points)
        if (squared_q(supports.metric[j], p - cloud.X[j]) < 1.0) {
          EXPECT_TRUE(got.count(static_cast<Index>(j))) << "particle " << j << " reaches a point near centre " << i;
          ++needed;
          break;
        }
    kept_by_points += by_points.size();
    kept_by_reach += by_reach.size();
  }
  EXPECT_GT(needed, 0u);
  EXPECT_LT(kept_by_points, kept_by_reach) << "the points' extents should keep fewer than their distance alone";
}

// The thin shells' ellipsoidal supports and their approximation.
class EllipsoidGridOnAThinWall : public ::testing::TestWithParam<bool> {
 protected:
  static RKSettings ellipsoids() {
    RKSettings settings;
    settings.shape = SupportShape::Ellipsoid;
    return settings;
  }
  const particles::Cloud cloud = GetParam() ? needle_shell() : thin_shell();
  const SupportEllipsoids supports = ellipsoidal_supports(cloud, 2.0);
  const RKApproximation rk{cloud, ellipsoids()};
  const double a_max = *std::max_element(supports.radius.begin(), supports.radius.end());
};

// The contract of RKApproximation::candidates, through the grid and (for a reach the
// grid does not cover) through the tree: every particle that reaches a point within
// `reach` of the centre is a candidate, once, and the ids are sorted.
TEST_P(EllipsoidGridOnAThinWall, CandidatesHoldEverySupportThatReaches) {
  std::mt19937 rng(11);
  CandidateSet set;
  for (double reach : {0.0, 0.25 * a_max, 3.0 * a_max}) {
    for (const Vec3& c : centres(cloud.X, rng, 30)) {
      rk.candidates(c, reach, set);
      ASSERT_TRUE(std::is_sorted(set.id.begin(), set.id.end()));
      ASSERT_TRUE(std::adjacent_find(set.id.begin(), set.id.end()) == set.id.end());
      const std::set<Index> got(set.id.begin(), set.id.end());
      for (Index j : reaching(cloud.X, supports.metric, c, reach, rng))
        EXPECT_TRUE(got.count(j)) << "reach " << reach << ": particle " << j << " missing";
      for (std::size_t k = 0; k < set.size(); ++k) {
        const Vec3& X = cloud.X[static_cast<std::size_t>(set.id[k])];
        EXPECT_EQ(set.x[k], X.x());
        EXPECT_EQ(set.g[0][k], supports.metric[static_cast<std::size_t>(set.id[k])](0, 0));
      }
    }
  }
}

// The grid and the tree must give the same shape functions bit for bit: a candidate
// list may hold extra particles, but their kernel is zero and the sums run over the
// same particles in the same (id) order. The tree answers a reach beyond the grid's.
TEST_P(EllipsoidGridOnAThinWall, ShapeFunctionsAreTheTreesBitForBit) {
  CandidateSet by_grid, by_tree;
  ShapeValues a, b;
  std::size_t compared = 0;
  for (std::size_t i = 0; i < cloud.size(); i += cloud.size() / 1500 + 1) {
    const Vec3 x = cloud.X[i] + Vec3(0.01, -0.02, 0.015) * a_max;
    rk.candidates(x, 0.0, by_grid);
    rk.candidates(x, 3.0 * a_max, by_tree);
    ASSERT_GT(by_tree.size(), by_grid.size());  // the tree's list is the longer one
    ASSERT_TRUE(rk.evaluate_among(x, by_grid, a, true));
    ASSERT_TRUE(rk.evaluate_among(x, by_tree, b, true));
    ASSERT_EQ(a.ids, b.ids) << "particle " << i;
    for (std::size_t k = 0; k < a.ids.size(); ++k) {
      EXPECT_EQ(a.psi[k], b.psi[k]);
      EXPECT_EQ(a.grad[k], b.grad[k]);
    }
    ++compared;
  }
  EXPECT_GT(compared, 100u);
}

// false: the tilted wall (one grid); true: the needles (grids per orientation).
INSTANTIATE_TEST_SUITE_P(OneGridAndOrientedGrids, EllipsoidGridOnAThinWall, ::testing::Bool());
