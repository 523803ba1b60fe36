// ExactSum (common/exact_sum.hpp): the sum of doubles rounded once from the exact
// value, whatever the order of the terms and however they are split and merged.
#include "rkpm/common/exact_sum.hpp"
#include "rkpm/common/split_mix64.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace rkpm;

namespace {
double exact(const std::vector<double>& terms) {
  ExactSum s;
  for (double x : terms) s.add(x);
  return s.value();
}
}  // namespace

TEST(ExactSum, CancellationThatAPlainSumLosesIsKept) {
  EXPECT_EQ(exact({1e100, 1.0, -1e100}), 1.0);  // a plain sum gives 0
  EXPECT_EQ(exact({1.0, 1e-30, -1.0}), 1e-30);
  // Ten times the double nearest 0.1 is 1 + 5.55e-17 exactly, which rounds to 1; the
  // plain sum drifts to 0.9999999999999999.
  EXPECT_EQ(exact(std::vector<double>(10, 0.1)), 1.0);
  EXPECT_EQ(exact({}), 0.0);
  EXPECT_EQ(exact({-2.5, 0.5}), -2.0);
}

TEST(ExactSum, TheWholeDoubleRangeAndItsEnds) {
  const double tiny = std::numeric_limits<double>::denorm_min(), huge = std::numeric_limits<double>::max();
  EXPECT_EQ(exact({tiny, tiny, tiny}), 3 * tiny);
  EXPECT_EQ(exact({huge, huge, -huge}), huge);
  EXPECT_EQ(exact({huge, tiny, -huge}), tiny);
  EXPECT_EQ(exact({huge, huge}), std::numeric_limits<double>::infinity());  // overflows as a double sum would
  EXPECT_EQ(exact({-huge, -huge}), -std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(exact({1.0, std::nan("")})));
  EXPECT_EQ(exact({1.0, std::numeric_limits<double>::infinity()}), std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(exact({std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()})));
}

TEST(ExactSum, AnyOrderAndAnySplitGiveTheSameBitsAsLongDoubleToItsPrecision) {
  SplitMix64 random(11);
  std::vector<double> terms(20000);
  for (auto& x : terms) x = random.symmetric_unit() * std::pow(10.0, 30.0 * random.uniform() - 15.0);
  const double reference = exact(terms);
  long double wide = 0.0L;
  for (double x : terms) wide += x;
  EXPECT_NEAR(reference, static_cast<double>(wide), 1e-12 * std::abs(reference));
  bool plain_sums_differ = false;
  double first_plain = 0.0;
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<double> shuffled = terms;
    for (std::size_t i = shuffled.size() - 1; i > 0; --i)
      std::swap(shuffled[i], shuffled[static_cast<std::size_t>(random.next() % (i + 1))]);
    // Split into `parts` sums merged in reverse order, through the transported form.
    const std::size_t parts = 1 + static_cast<std::size_t>(trial);
    ExactSum merged;
    for (std::size_t p = parts; p-- > 0;) {
      ExactSum part;
      for (std::size_t i = p; i < shuffled.size(); i += parts) part.add(shuffled[i]);
      merged += ExactSum::from_words(part.words());
    }
    EXPECT_EQ(merged.value(), reference) << "trial " << trial;
    double plain = 0.0;
    for (double x : shuffled) plain += x;
    if (trial == 0) first_plain = plain;
    plain_sums_differ = plain_sums_differ || plain != first_plain;
  }
  EXPECT_TRUE(plain_sums_differ) << "the terms are chosen so that the order matters to a plain sum";
}

TEST(ExactSum, ManyTermsCarryWithoutOverflow) {
  // More terms than a word takes between carries (2^29), each spanning two digits.
  ExactSum s;
  const double term = std::ldexp(static_cast<double>((std::uint64_t{1} << 23) - 1), -7);
  const std::int64_t count = (std::int64_t{1} << 29) + 12345;
  for (std::int64_t i = 0; i < count; ++i) s.add(term);
  // 23 significant bits times a 30-bit count: the product is a double exactly.
  EXPECT_EQ(s.value(), term * static_cast<double>(count));
}
