// Nodal vector fields (one Vec3 per particle) and the few BLAS-1 operations the
// Krylov solver needs. Reductions run in a fixed order per thread count, so a run
// is reproducible on the same machine.
#pragma once

#include "rkpm/common/types.hpp"

#include <vector>

namespace rkpm::study {

using Field = std::vector<Vec3>;

inline double dot(const Field& u, const Field& v) {
  const auto n = static_cast<Index>(u.size());
  double sum = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum)
  for (Index i = 0; i < n; ++i) sum += u[i].dot(v[i]);
  return sum;
}

// y += s x
inline void axpy(double s, const Field& x, Field& y) {
  const auto n = static_cast<Index>(x.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) y[i] += s * x[i];
}

}  // namespace rkpm::study
