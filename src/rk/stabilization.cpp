#include "rkpm/rk/stabilization.hpp"

#include <omp.h>

#include <cmath>

namespace rkpm::rk {

Stabilization build_stabilization(const std::vector<double>& volume, const std::vector<double>& shear_modulus,
                                  double alpha) {
  Stabilization s;
  if (alpha <= 0.0) return s;
  s.weight.resize(volume.size());
  for (std::size_t L = 0; L < volume.size(); ++L)
    s.weight[L] = alpha * shear_modulus[L] * volume[L] / std::cbrt(volume[L] * volume[L]);
  return s;
}

double add_stabilization_forces(const NodalInterpolation& N, Stabilization& s, const std::vector<Vec3>& d,
                                std::vector<Vec3>& f) {
  const auto n = static_cast<Index>(s.weight.size());
  const int threads = RowScatter::team_threads();
  if (!s.scatter.planned_for(threads)) s.scatter.plan(n, n, {{&N.row_offset, &N.col}}, threads, 1);
  std::vector<double> energy(static_cast<std::size_t>(threads), 0.0);
  // r_L = d_L - sum_I Psi_I(X_L) d_I, pre-multiplied by W_L; then f -= the transpose
  // of the residual applied to W r, scattered from row L (scatter_residual).
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    s.scatter.clear(t);
    Vec3* sum = s.scatter.buffer(t, 0);
    for (Index L = s.scatter.row_begin(t); L < s.scatter.row_end(t); ++L) {
      const auto [r, weight_sum] = interpolation_residual(N, d, L);
      energy[static_cast<std::size_t>(t)] += 0.5 * s.weight[L] * r.squaredNorm();
      const Vec3 wr = s.weight[L] * r;
      scatter_residual(N, L, wr, weight_sum, RowScatter::AddTo{sum});
    }
#pragma omp barrier
    s.scatter.reduce_add(t, 0, -1.0, f);
  }
  double total = 0.0;
  for (double e : energy) total += e;
  return total;
}

}  // namespace rkpm::rk
