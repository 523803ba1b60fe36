// The row kernels of the single-precision operator (rk/row_kernels.hpp, namespace lanes), in their vector
// and their scalar form, against the one-entry loops they replace: the same bits, for
// rows of every length around the vector width; and the planar storage against the
// double-precision operator.
#include "clouds.hpp"
#include "rkpm/common/split_mix64.hpp"
#include "rkpm/rk/nodal_integration.hpp"
#include "rkpm/rk/row_kernels.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace rkpm;

namespace {

// A row of n entries: particle ids, planar components, and the fields they act on.
struct Row {
  std::vector<Index> col;
  std::vector<float> planar;  // x components, then y, then z
  std::vector<Vec3> value;    // v_I for I in [0, particles)
  Index own = 0;

  Vec3f entry(Index m) const {
    const auto n = static_cast<Index>(col.size());
    return Vec3f(planar[m], planar[n + m], planar[2 * n + m]);
  }
};

Row random_row(Index n, std::uint64_t seed) {
  SplitMix64 random(seed);
  const auto uniform = [&] { return random.symmetric_unit(); };
  Row row;
  const Index particles = 3 * n + 5;
  for (Index I = 0; I < particles; ++I) row.value.emplace_back(1e-6 * uniform(), 3e-6 * uniform(), uniform());
  for (Index m = 0; m < n; ++m) row.col.push_back(3 * m + 1);
  row.planar.resize(3 * static_cast<std::size_t>(n));
  for (auto& b : row.planar) b = static_cast<float>(1e6 * uniform());
  row.own = 3 * n + 2;
  return row;
}

}  // namespace

// The gather of rk/nodal_integration.hpp before the planar storage: one entry at a time,
// Vector3d arithmetic, in the row's order.
TEST(RowLanes, GatherHasTheBitsOfTheOneEntryLoop) {
  for (Index n = 0; n <= 13; ++n) {
    const Row row = random_row(n, 17 + n);
    const Vec3 vL = row.value[row.own];
    Vec3 g0 = Vec3::Zero(), g1 = Vec3::Zero(), g2 = Vec3::Zero();
    for (Index m = 0; m < n; ++m) {
      const Vec3 vk = row.value[row.col[m]] - vL;
      const Vec3f b = row.entry(m);
      g0 += vk * static_cast<double>(b(0));
      g1 += vk * static_cast<double>(b(1));
      g2 += vk * static_cast<double>(b(2));
    }
    Mat3 expected;
    expected << g0, g1, g2;
    const auto value = [&](Index I) { return row.value[I]; };
    const Mat3 vector = rk::lanes::row_gradient<true>(row.col.data(), row.planar.data(), n, value, vL);
    const Mat3 scalar = rk::lanes::row_gradient<false>(row.col.data(), row.planar.data(), n, value, vL);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        EXPECT_EQ(vector(i, j), expected(i, j)) << "vector form, n = " << n << ", (" << i << ", " << j << ")";
        EXPECT_EQ(scalar(i, j), expected(i, j)) << "scalar form, n = " << n << ", (" << i << ", " << j << ")";
      }
  }
}

// Two fields gathered in one sweep (the force pass's displacements and directors): each
// set of sums has the bits of its field gathered alone, in both forms.
TEST(RowLanes, GatherOfTwoFieldsHasTheBitsOfEachAlone) {
  for (Index n = 0; n <= 13; ++n) {
    const Row row = random_row(n, 29 + n), other = random_row(n, 41 + n);
    const auto a = [&](Index I) { return row.value[I]; };
    const auto b = [&](Index I) { return Vec3(other.value[I].reverse()); };
    const Vec3 aL = a(row.own), bL = b(row.own);
    for (const bool vector : {true, false}) {
      Mat3 ga, gb;
      if (vector)
        rk::lanes::row_gradients<true>(row.col.data(), row.planar.data(), n, a, aL, ga, b, bL, &gb);
      else
        rk::lanes::row_gradients<false>(row.col.data(), row.planar.data(), n, a, aL, ga, b, bL, &gb);
      const Mat3 alone_a = rk::lanes::row_gradient<false>(row.col.data(), row.planar.data(), n, a, aL);
      const Mat3 alone_b = rk::lanes::row_gradient<false>(row.col.data(), row.planar.data(), n, b, bL);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          EXPECT_EQ(ga(i, j), alone_a(i, j)) << (vector ? "vector" : "scalar") << " form, n = " << n;
          EXPECT_EQ(gb(i, j), alone_b(i, j)) << (vector ? "vector" : "scalar") << " form, n = " << n;
        }
      if (n > 0) {
        EXPECT_NE(ga, gb);  // two different fields were gathered
      }
    }
  }
}

// (w M) b as the scatter associates it.
Vec3 product(const Mat3& wM, const Vec3& b) {
  double m[3][3], out[3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = wM(i, j);
  rk::lanes::product(m, b(0), b(1), b(2), out);
  return Vec3(out[0], out[1], out[2]);
}

#ifndef __FMA__
// The force pass formed w M b with Eigen before the row kernels; they keep its bits. A
// build with FMA (RKPM_NATIVE) lets Eigen fuse two components of its products, so there
// the kernels round as the portable build does, and this does not hold.
TEST(RowLanes, TheScattersAssociationIsEigensProduct) {
  SplitMix64 random(3);
  for (int t = 0; t < 10000; ++t) {
    Mat3 M;
    for (int i = 0; i < 9; ++i) M(i) = random.symmetric_unit();
    const Vec3 b(random.symmetric_unit(), random.symmetric_unit(), random.symmetric_unit());
    const double w = random.symmetric_unit();
    const Mat3 wM = w * M;
    const Vec3 eigen = w * (M * b), ours = product(wM, b);
    for (int c = 0; c < 3; ++c) ASSERT_EQ(ours(c), eigen(c)) << "trial " << t << ", component " << c;
  }
}
#endif

TEST(RowLanes, ScatterHasTheBitsOfTheOneEntryLoopInTheRowsOrder) {
  SplitMix64 random(5);
  for (Index n = 0; n <= 13; ++n) {
    const Row row = random_row(n, 101 + n);
    Mat3 M;
    for (int i = 0; i < 9; ++i) M(i) = 1e4 * random.symmetric_unit();
    const double w = 1.7e-19;
    const Mat3 wM = w * M;
    std::vector<std::pair<Index, Vec3>> expected, made;
    Vec3 row_sum = Vec3::Zero();
    for (Index m = 0; m < n; ++m) {
      const Vec3 b = row.entry(m).cast<double>();
      expected.emplace_back(row.col[m], product(wM, b));
      row_sum += b;
    }
    expected.emplace_back(row.own, Vec3(-product(wM, row_sum)));
    for (const bool vector : {true, false}) {
      made.clear();
      const auto record = [&](Index I, const Vec3& c) { made.emplace_back(I, c); };
      if (vector)
        rk::lanes::scatter_row<true>(row.col.data(), row.planar.data(), n, row.own, w, M, record);
      else
        rk::lanes::scatter_row<false>(row.col.data(), row.planar.data(), n, row.own, w, M, record);
      const char* form = vector ? "vector form" : "scalar form";
      ASSERT_EQ(made.size(), expected.size()) << form << ", n = " << n;
      for (std::size_t k = 0; k < made.size(); ++k) {
        EXPECT_EQ(made[k].first, expected[k].first) << form << ", n = " << n << ", contribution " << k;
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(made[k].second(c), expected[k].second(c)) << form << ", n = " << n << ", contribution " << k;
      }
    }
  }
}

// The planar rows hold, entry by entry, the double-precision operator's values rounded
// to float, with the same columns: on a cloud of more than one build block (1,024 rows),
// with every row and with every other row only (as a rank of a distributed run builds
// its own rows, the others empty).
TEST(RowLanes, PlanarStorageHoldsTheDoubleOperatorsEntries) {
  const auto cloud = test::jittered_block(11, 0.15);
  const auto n = static_cast<Index>(cloud.size());
  ASSERT_GT(n, 1024);
  const rk::RKApproximation rk(cloud, rk::RKSettings{});
  const auto exact = rk::build_gradient_operator(cloud, rk, rk::Integration::SCNI, rk::GradientPrecision::Double);
  std::vector<char> every_other(static_cast<std::size_t>(n), 0);
  for (Index L = 0; L < n; L += 2) every_other[static_cast<std::size_t>(L)] = 1;
  for (const auto& rows : {std::vector<char>{}, every_other}) {
    const auto stored =
        rk::build_gradient_operator(cloud, rk, rk::Integration::SCNI, rk::GradientPrecision::Float, rows);
    ASSERT_TRUE(stored.single_precision());
    ASSERT_EQ(stored.n_rows(), n);
    std::size_t mismatches = 0, entries = 0;
    for (Index L = 0; L < n; ++L) {
      const bool built = rows.empty() || rows[static_cast<std::size_t>(L)] != 0;
      const Index length = stored.row_offset[L + 1] - stored.row_offset[L];
      ASSERT_EQ(length, built ? exact.row_offset[L + 1] - exact.row_offset[L] : 0) << "row " << L;
      for (Index m = 0; m < length; ++m) {
        const Index k = stored.row_offset[L] + m, e = exact.row_offset[L] + m;
        if (stored.col[k] != exact.col[e] || stored.entry(L, k) != exact.grad[e].cast<float>().cast<double>())
          ++mismatches;
        ++entries;
      }
    }
    EXPECT_EQ(mismatches, 0u) << (rows.empty() ? "every row" : "every other row");
    EXPECT_EQ(3 * entries, stored.grad_float.size());
  }
}
