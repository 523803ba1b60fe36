// libFuzzer program: the .vtu importer (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rkpm::fuzz::vtu_file(data, size);
  return 0;
}
