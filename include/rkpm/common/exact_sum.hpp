// An exact sum of doubles, whose value does not depend on the order of the additions.
//
// Why: a floating-point sum depends on the order of its terms, and that order changes
// with the thread count and with how the particles are split over the ranks. A
// relaxation carries such round-off differences along its soft modes for thousands of
// steps (docs/verification/distributed.md), so the global sums that steer it (FIRE's P = F.v, |v|,
// |F|, the enclosed volume, energies) are accumulated exactly here: every double is a
// 53-bit integer times a power of two, and it is added into a fixed-point number that
// spans the whole double range (2,098 bits in 32-bit digits held in 64-bit words, so a
// word takes 2^29 additions before its carries are propagated). Adding and merging
// are integer operations, hence associative and commutative; `value()` rounds the
// exact result once. The same terms in any order, split over any number of threads or
// ranks, give the same bits.
//
// Cost: a few integer operations per term, without a branch on its sign, a few times a
// floating-point addition (docs/verification/distributed.md measures it); the sums that
// use it run a few times per step over the particles, so the step hardly sees it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace rkpm {

class ExactSum {
 public:
  static constexpr int kDigits = 67;  // 66 digits reach 2^1024 x 2^31 terms; one more for the carry out
  // The transported form (par::Comm sums it over the ranks): the digits, then the counts
  // of NaN, +inf and -inf terms.
  static constexpr int kWords = kDigits + 3;
  using Words = std::array<std::int64_t, kWords>;

  void add(double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const auto biased = static_cast<int>((bits >> 52) & 0x7ff);
    const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
    const bool negative = (bits >> 63) != 0;
    if (biased == 0x7ff) {  // NaN or infinity: counted, so the result is NaN or inf as a plain sum's would be
      ++words_[static_cast<std::size_t>(fraction != 0 ? kDigits : negative ? kDigits + 2 : kDigits + 1)];
      return;
    }
    // x = mantissa * 2^(position - 1074): subnormals share the smallest exponent.
    const std::uint64_t mantissa = biased == 0 ? fraction : fraction | (std::uint64_t{1} << 52);
    if (mantissa == 0) return;
    const int position = biased == 0 ? 0 : biased - 1;
    // mantissa << shift spans 85 bits: its low 64 and the bits shifted out above.
    const int shift = position & 31;
    const std::uint64_t low = mantissa << shift;
    const std::uint64_t high = shift == 0 ? 0 : mantissa >> (64 - shift);  // < 2^21
    const auto digit = static_cast<std::size_t>(position >> 5);
    // The sign applied without a branch (terms of either sign are equally likely):
    // (d ^ -1) + 1 = -d.
    const std::int64_t flip = negative ? -1 : 0;
    const auto signed_digit = [flip](std::int64_t d) { return (d ^ flip) - flip; };
    words_[digit] += signed_digit(static_cast<std::int64_t>(low & 0xffffffffu));
    words_[digit + 1] += signed_digit(static_cast<std::int64_t>(low >> 32));
    words_[digit + 2] += signed_digit(static_cast<std::int64_t>(high));
    if (++pending_ == kCarryEvery) propagate_carries();
  }

  ExactSum& operator+=(const ExactSum& other) {
    if (pending_ + other.pending_ + 1 >= kCarryEvery) propagate_carries();
    for (std::size_t w = 0; w < words_.size(); ++w) words_[w] += other.words_[w];
    pending_ += other.pending_ + 1;
    if (pending_ >= kCarryEvery) propagate_carries();
    return *this;
  }

  // The exact sum rounded to a double (to within one unit in the last place, the same
  // bits for the same exact sum). NaN if a term was NaN or +inf and -inf were both
  // added; +-inf if one of them was, or if the sum overflows.
  double value() const {
    const std::int64_t nan = words_[kDigits], pos_inf = words_[kDigits + 1], neg_inf = words_[kDigits + 2];
    if (nan > 0 || (pos_inf > 0 && neg_inf > 0)) return std::numeric_limits<double>::quiet_NaN();
    if (pos_inf > 0) return std::numeric_limits<double>::infinity();
    if (neg_inf > 0) return -std::numeric_limits<double>::infinity();
    ExactSum copy = *this;
    copy.propagate_carries();
    // After the carries every digit but the top one is in [0, 2^32), so the top digit's
    // sign is the sum's. Work on the magnitude, whose leading digits then carry it.
    const bool negative = copy.words_[kDigits - 1] < 0;
    if (negative) {
      for (int d = 0; d < kDigits; ++d) copy.words_[static_cast<std::size_t>(d)] *= -1;
      copy.propagate_carries();
    }
    int top = kDigits - 1;
    while (top >= 0 && copy.words_[static_cast<std::size_t>(top)] == 0) --top;
    if (top < 0) return 0.0;
    // The three leading digits hold at least 65 significant bits: the rest is below
    // the double's precision.
    double magnitude = 0.0;
    for (int d = std::max(top - 2, 0); d <= top; ++d)
      magnitude += std::ldexp(static_cast<double>(copy.words_[static_cast<std::size_t>(d)]), 32 * d - 1074);
    return negative ? -magnitude : magnitude;
  }

  const Words& words() const { return words_; }
  // A sum from its transported words (another rank's).
  static ExactSum from_words(const Words& words) {
    ExactSum s;
    s.words_ = words;
    s.pending_ = kCarryEvery - 1;  // unknown: carry before the next addition
    return s;
  }

 private:
  // A word moves by less than 2^32 per addition: 2^29 additions keep it below 2^61, so
  // two such sums can be merged before carrying.
  static constexpr std::int64_t kCarryEvery = std::int64_t{1} << 29;

  // Brings every digit below the top into [0, 2^32), moving the excess up.
  void propagate_carries() {
    for (int d = 0; d + 1 < kDigits; ++d) {
      auto& w = words_[static_cast<std::size_t>(d)];
      const std::int64_t carry = w >> 32;  // arithmetic shift: floor division by 2^32
      w -= carry * (std::int64_t{1} << 32);
      words_[static_cast<std::size_t>(d) + 1] += carry;
    }
    pending_ = 0;
  }

  Words words_{};
  std::int64_t pending_ = 0;  // additions since the carries were last propagated
};

}  // namespace rkpm

// OpenMP threads each keep an exact sum and merge them at the end of the loop, in any
// order: `reduction(+ : s)` for an ExactSum s.
#pragma omp declare reduction(+ : rkpm::ExactSum : omp_out += omp_in)
