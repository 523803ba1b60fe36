// The machine's streaming bandwidth, STREAM-style: a[i] = b[i] + s c[i] over
// arrays far larger than any cache.
//
// 24 bytes per element are counted (read b, read c, write a), as STREAM does: the
// write-allocate read of a that ordinary (not non-temporal) stores cause is NOT
// counted, so the DRAM traffic is up to 4/3 of the reported figure. The
// internal-force traffic (bench/common/footprint.hpp) counts written arrays the
// same way, so the two compare like for like.
#pragma once

#include <cstddef>

namespace rkpm::scaling {

struct TriadResult {
  double gb_per_s = 0.0;       // best repetition, 1e9 bytes per second, 24 B per element
  std::size_t array_bytes = 0; // size of each of the three arrays
  int threads = 0;
  int repetitions = 0;
};

TriadResult measure_triad(std::size_t array_bytes, int threads, int repetitions);

}  // namespace rkpm::scaling
