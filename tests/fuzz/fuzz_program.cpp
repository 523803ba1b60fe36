// A libFuzzer program: one fuzz target of fuzz_targets.hpp, named at compile time by
// RKPM_FUZZ_TARGET (tests/fuzz/CMakeLists.txt builds one program per target).
#include "fuzz_targets.hpp"

#ifndef RKPM_FUZZ_TARGET
#error "RKPM_FUZZ_TARGET names the target function, for example rkpm::fuzz::scene_text"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  RKPM_FUZZ_TARGET(data, size);
  return 0;
}
