// The machine's arithmetic peak, the other ceiling of the roofline
// (docs/verification/performance.md): independent chains of multiplies and adds on the
// widest vectors the build targets, and on scalars, with every thread.
//
// Multiplies and adds are separate instructions, as in the force pass (the build fuses
// none: cmake/warnings.cmake), so this is the peak without fused multiply-adds: one
// multiply or add per lane counts one operation.
#pragma once

#include <string>

namespace rkpm::scaling {

struct PeakResult {
  double vector_gflops = 0.0;  // best repetition, 1e9 operations per second
  double scalar_gflops = 0.0;
  int vector_lanes = 1;        // doubles per vector register of the build's target
  std::string isa;             // "AVX-512", "AVX" or "SSE2"
  int threads = 0;
};

PeakResult measure_peak(int threads, int repetitions);

}  // namespace rkpm::scaling
