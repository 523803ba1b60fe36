// When a loop is worth an OpenMP parallel region.
#pragma once

#include <cstdint>

namespace rkpm {

// Below this many iterations a loop runs on the calling thread: the fork and join of a
// region cost more than such a loop, and on cores shared with other work a region also
// waits for threads the operating system has not scheduled, so a scene of many small
// terms (one region each) would take a time that depends on the machine's load instead
// of on the scene. Results do not depend on it: every sum a term makes is exact or in
// particle order.
constexpr std::int64_t kParallelLoopMinimum = 2048;

constexpr bool worth_threads(std::int64_t iterations) { return iterations >= kParallelLoopMinimum; }

}  // namespace rkpm
