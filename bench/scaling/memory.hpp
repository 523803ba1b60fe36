// Memory of this process and of the machine, from /proc (Linux).
#pragma once

#include <cstddef>

namespace rkpm::scaling {

// Peak resident set size of this process so far (VmHWM) [bytes]; 0 if unknown.
std::size_t peak_rss_bytes();
// Memory the kernel can give new allocations without swapping (MemAvailable) [bytes]; 0 if unknown.
std::size_t available_bytes();

}  // namespace rkpm::scaling
