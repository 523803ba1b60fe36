// Nodal vector fields (one Vec3 per particle) and the few BLAS-1 operations the
// Krylov solver needs. Serial on purpose: they cost microseconds next to a
// stiffness product, while every OpenMP region adds a barrier, which on a loaded
// machine can cost a scheduler time slice. Serial sums are also reproducible.
#pragma once

#include "rkpm/common/types.hpp"

#include <vector>

namespace rkpm::study {

using Field = std::vector<Vec3>;

inline double dot(const Field& u, const Field& v) {
  const auto n = static_cast<Index>(u.size());
  double sum = 0.0;
  for (Index i = 0; i < n; ++i) sum += u[i].dot(v[i]);
  return sum;
}

// y += s x
inline void axpy(double s, const Field& x, Field& y) {
  const auto n = static_cast<Index>(x.size());
  for (Index i = 0; i < n; ++i) y[i] += s * x[i];
}

}  // namespace rkpm::study
