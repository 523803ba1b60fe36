// A small deterministic random generator (SplitMix64, Steele, Lea & Flood 2014): the
// same seed gives the same numbers on every platform, which std:: distributions do not
// promise. Cloud jitter, initial velocity noise and the tests' random inputs use it.
#pragma once

#include <cstdint>

namespace rkpm {

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  // Uniform in [0, 1) from the top 53 bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform in [-1, 1).
  double symmetric_unit() { return 2.0 * static_cast<double>(next() >> 11) * 0x1.0p-53 - 1.0; }

 private:
  std::uint64_t state_;
};

}  // namespace rkpm
