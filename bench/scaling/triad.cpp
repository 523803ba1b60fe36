#include "triad.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <memory>

namespace rkpm::scaling {

TriadResult measure_triad(std::size_t array_bytes, int threads, int repetitions) {
  const auto n = static_cast<long long>(array_bytes / sizeof(double));
  // Raw arrays, first touched by the threads that will stream them (page placement).
  std::unique_ptr<double[]> a(new double[n]), b(new double[n]), c(new double[n]);
  omp_set_num_threads(threads);
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < n; ++i) {
    a[i] = 0.0;
    b[i] = 1.0;
    c[i] = 2.0;
  }
  const double s = 3.0;
  double best = 0.0;
  for (int r = 0; r < repetitions; ++r) {
    const auto start = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
    for (long long i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, 24.0 * static_cast<double>(n) / seconds / 1e9);
    // Keep the compiler from dropping repetitions whose results are overwritten.
    volatile double sink = a[static_cast<std::size_t>(r) % static_cast<std::size_t>(n)];
    (void)sink;
  }
  TriadResult result;
  result.gb_per_s = best;
  result.array_bytes = static_cast<std::size_t>(n) * sizeof(double);
  result.threads = threads;
  result.repetitions = repetitions;
  return result;
}

}  // namespace rkpm::scaling
