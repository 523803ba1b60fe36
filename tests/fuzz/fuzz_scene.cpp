// libFuzzer program: the scene loader (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rkpm::fuzz::scene_text(data, size);
  return 0;
}
