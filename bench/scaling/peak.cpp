#include "peak.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>

namespace rkpm::scaling {

namespace {

#if defined(__AVX512F__)
constexpr int kLanes = 8;
constexpr const char* kIsa = "AVX-512";
#elif defined(__AVX__)
constexpr int kLanes = 4;
constexpr const char* kIsa = "AVX";
#else
constexpr int kLanes = 2;
constexpr const char* kIsa = "SSE2";
#endif

using Vector = double __attribute__((vector_size(kLanes * sizeof(double))));

// Six multiply chains and six add chains, each operation waiting only on its own chain
// four or so cycles back: enough in flight to fill the floating-point ports of a current
// core, and with the two constants within sixteen registers. The factor and the addend
// keep every value finite and normal over any count.
template <class T>
T chains(long iterations, T m, T c) {
  T p0 = m, p1 = m + c, p2 = m + c + c, p3 = m - c, p4 = m - c - c, p5 = m + m;
  T s0 = c, s1 = c + c, s2 = m, s3 = m + c, s4 = m - c, s5 = c + m + m;
  for (long i = 0; i < iterations; ++i) {
    p0 *= m;
    s0 += c;
    p1 *= m;
    s1 += c;
    p2 *= m;
    s2 += c;
    p3 *= m;
    s3 += c;
    p4 *= m;
    s4 += c;
    p5 *= m;
    s5 += c;
  }
  return ((p0 + p1) + (p2 + p3)) + ((p4 + p5) + (s0 + s1)) + ((s2 + s3) + (s4 + s5));
}

// The scalar chains must stay scalar: the compiler would otherwise pack pairs of them
// into vector registers.
__attribute__((noinline, optimize("no-tree-vectorize", "no-tree-slp-vectorize"))) double scalar_chains(
    long iterations, double m, double c) {
  return chains<double>(iterations, m, c);
}

__attribute__((noinline)) double vector_chains(long iterations, double m, double c) {
  Vector vm, vc;
  for (int l = 0; l < kLanes; ++l) {
    vm[l] = m;
    vc[l] = c * (1 + l);
  }
  const Vector r = chains<Vector>(iterations, vm, vc);
  double sum = 0;
  for (int l = 0; l < kLanes; ++l) sum += r[l];
  return sum;
}

// Best rate over the repetitions, in 1e9 operations per second, with every thread
// running its own chains.
template <class Kernel>
double best_rate(const Kernel& kernel, int lanes, int threads, int repetitions) {
  constexpr long kIterations = 100'000'000;
  constexpr double kOperationsPerIteration = 12;
  omp_set_num_threads(threads);
  double best = 0.0;
  for (int r = 0; r < repetitions; ++r) {
    double sink = 0.0;
    const auto start = std::chrono::steady_clock::now();
#pragma omp parallel reduction(+ : sink)
    sink += kernel(kIterations, 1.0 + 1e-12, 1e-9 * (1 + r));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const volatile double keep = sink;  // the results are used: the loops are not dropped
    (void)keep;
    best = std::max(best, threads * kIterations * kOperationsPerIteration * lanes / seconds / 1e9);
  }
  return best;
}

}  // namespace

PeakResult measure_peak(int threads, int repetitions) {
  PeakResult p;
  p.vector_lanes = kLanes;
  p.isa = kIsa;
  p.threads = threads;
  p.vector_gflops = best_rate(vector_chains, kLanes, threads, repetitions);
  p.scalar_gflops = best_rate(scalar_chains, 1, threads, repetitions);
  return p;
}

}  // namespace rkpm::scaling
