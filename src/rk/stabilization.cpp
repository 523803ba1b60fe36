#include "rkpm/rk/stabilization.hpp"

#include <cmath>

namespace rkpm::rk {

Stabilization build_stabilization(const std::vector<double>& volume, const std::vector<double>& shear_modulus,
                                  double alpha) {
  Stabilization s;
  if (alpha <= 0.0) return s;
  s.weight.resize(volume.size());
  for (std::size_t L = 0; L < volume.size(); ++L)
    s.weight[L] = alpha * shear_modulus[L] * volume[L] / std::cbrt(volume[L] * volume[L]);
  s.residual.assign(volume.size(), Vec3::Zero());
  return s;
}

double add_stabilization_forces(const NodalInterpolation& N, Stabilization& s, const std::vector<Vec3>& d,
                                std::vector<Vec3>& f) {
  const auto n = static_cast<Index>(s.weight.size());
  double energy = 0.0;
  // r_L = d_L - sum_I Psi_I(X_L) d_I, stored pre-multiplied by W_L.
#pragma omp parallel for schedule(static) reduction(+ : energy)
  for (Index L = 0; L < n; ++L) {
    const Vec3 r = interpolation_residual(N, d, L);
    energy += 0.5 * s.weight[L] * r.squaredNorm();
    s.residual[L] = s.weight[L] * r;
  }
  // f_I -= (W r)_I - sum_L Psi_I(X_L) (W r)_L: the transpose product as a gather.
  const auto& T = N.transpose;
#pragma omp parallel for schedule(static)
  for (Index I = 0; I < n; ++I) {
    Vec3 back = Vec3::Zero();
    for (Index t = T.offset[I]; t < T.offset[I + 1]; ++t) back += N.psi[T.entry[t]] * s.residual[T.row[t]];
    f[I] -= s.residual[I] - back;
  }
  return energy;
}

}  // namespace rkpm::rk
