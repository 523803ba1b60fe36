// Sorting of face node ids (at most 4). std::sort on such short ranges trips a
// false -Warray-bounds in GCC 12 and is slower than this anyway.
#pragma once

#include <cstdint>
#include <utility>

namespace rkpm::particles::detail {

inline void sort_small(std::int32_t* ids, int n) {
  for (int i = 1; i < n; ++i) {
    for (int j = i; j > 0 && ids[j] < ids[j - 1]; --j) std::swap(ids[j], ids[j - 1]);
  }
}

}  // namespace rkpm::particles::detail
