// The ordered scatter (rk/row_scatter.hpp): each column's sum is made in the
// one-thread order on any thread count, so the result has the same bits.
#include "rkpm/common/split_mix64.hpp"
#include "rkpm/rk/row_scatter.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

using namespace rkpm;

namespace {
// Rows with 1-40 columns each, drawn near the row (as kernel supports are) and some
// anywhere, and one contribution per entry of magnitudes over 12 decades: sums whose
// value depends on the grouping of their terms.
struct Rows {
  std::vector<Index> offset{0}, col;
  std::vector<Vec3> value;
};

Rows random_rows(Index n) {
  Rows r;
  SplitMix64 random(7);
  for (Index L = 0; L < n; ++L) {
    const auto count = 1 + static_cast<Index>(random.next() % 40);
    for (Index k = 0; k < count; ++k) {
      const bool far = random.next() % 8 == 0;
      const auto spread = far ? n : 30;
      Index I = L + static_cast<Index>(random.next() % static_cast<std::uint64_t>(2 * spread)) - spread;
      I = std::clamp<Index>(I, 0, n - 1);
      r.col.push_back(I);
      Vec3 v;
      for (int c = 0; c < 3; ++c) v[c] = (random.uniform() - 0.5) * std::pow(10.0, 12.0 * random.uniform());
      r.value.push_back(v);
    }
    r.offset.push_back(static_cast<Index>(r.col.size()));
  }
  return r;
}

// The reference: one loop over the rows in order, each column's sum from zero.
std::vector<Vec3> one_thread(const Rows& r, Index n) {
  std::vector<Vec3> out(static_cast<std::size_t>(n), Vec3::Zero());
  for (Index L = 0; L < n; ++L)
    for (Index k = r.offset[L]; k < r.offset[L + 1]; ++k) out[r.col[k]] += r.value[k];
  return out;
}

std::vector<Vec3> ordered(const Rows& r, Index n, int threads) {
  rk::RowScatter scatter;
  scatter.plan_ordered(0, n, n, threads, 1, [&](Index L, int, const std::function<void(Index)>& emit) {
    for (Index k = r.offset[L]; k < r.offset[L + 1]; ++k) emit(r.col[k]);
  });
  std::vector<Vec3> out(static_cast<std::size_t>(n), Vec3::Constant(-1.0));
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    scatter.clear(t);
    for (Index L = scatter.row_begin(t); L < scatter.row_end(t); ++L) {
      const auto sink = scatter.sink(t, 0, L);
      for (Index k = r.offset[L]; k < r.offset[L + 1]; ++k) sink(r.col[k], r.value[k]);
    }
#pragma omp barrier
    scatter.reduce(t, 0, 1.0, out);
  }
  scatter.fold(0, 1.0, out, false);
  return out;
}
}  // namespace

TEST(RowScatter, AnOrderedPlanGivesTheOneThreadBitsOnAnyThreadCount) {
  const Index n = 3000;
  const Rows r = random_rows(n);
  const std::vector<Vec3> reference = one_thread(r, n);
  for (int threads : {1, 2, 3, 4, 7}) {
    const std::vector<Vec3> got = ordered(r, n, threads);
    std::size_t differ = 0;
    for (Index I = 0; I < n; ++I) differ += got[static_cast<std::size_t>(I)] != reference[static_cast<std::size_t>(I)];
    EXPECT_EQ(differ, 0u) << threads << " threads";
  }
  // The sums do depend on grouping: adding two halves' partial sums changes some of them,
  // so the agreement above is not a property of the data.
  std::vector<Vec3> halves(static_cast<std::size_t>(n), Vec3::Zero()), second(static_cast<std::size_t>(n), Vec3::Zero());
  for (Index L = 0; L < n; ++L)
    for (Index k = r.offset[L]; k < r.offset[L + 1]; ++k) (L < n / 2 ? halves : second)[r.col[k]] += r.value[k];
  std::size_t grouped_differ = 0;
  for (Index I = 0; I < n; ++I)
    grouped_differ += Vec3(halves[static_cast<std::size_t>(I)] + second[static_cast<std::size_t>(I)]) !=
                      reference[static_cast<std::size_t>(I)];
  EXPECT_GT(grouped_differ, 0u);
}

TEST(RowScatter, ARowThatMakesOtherContributionsThanPlannedIsAnInternalError) {
  const Index n = 200;
  const Rows r = random_rows(n);
  rk::RowScatter scatter;
  scatter.plan_ordered(0, n, n, 2, 1, [&](Index L, int, const std::function<void(Index)>& emit) {
    for (Index k = r.offset[L]; k < r.offset[L + 1]; ++k) emit(r.col[k]);
  });
  ASSERT_GT(scatter.seam_count(), 0u);
  std::vector<Vec3> out(static_cast<std::size_t>(n), Vec3::Zero());
  for (int t = 0; t < 2; ++t) {
    scatter.clear(t);
    // Thread 1 skips its rows' contributions: its seams' records are missing.
    if (t == 1) continue;
    for (Index L = scatter.row_begin(t); L < scatter.row_end(t); ++L) {
      const auto sink = scatter.sink(t, 0, L);
      for (Index k = r.offset[L]; k < r.offset[L + 1]; ++k) sink(r.col[k], r.value[k]);
    }
  }
  EXPECT_THROW(scatter.fold(0, 1.0, out, false), std::logic_error);
}
