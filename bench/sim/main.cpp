// bench_sim: throughput of the simulation's step kernels on the example scenes
// (docs/verification/performance.md; `scripts/study bench` runs it and writes CSV). The benchmarks
// register themselves from bench_*.cpp.
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
