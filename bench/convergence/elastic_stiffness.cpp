#include "elastic_stiffness.hpp"

#include <utility>

namespace rkpm::study {

ElasticStiffness::ElasticStiffness(const rk::GradientOperator& gradient, const rk::NodalInterpolation& interpolation,
                                   rk::Stabilization stabilization, IsotropicElasticity material)
    : gradient_(gradient),
      interpolation_(interpolation),
      stabilization_(std::move(stabilization)),
      material_(material) {}

void ElasticStiffness::strains(const Field& d, std::vector<Mat3>& eps) const {
  // deformation_gradients applied to d (not to x = X + d) gives grad u directly.
  rk::deformation_gradients(gradient_, d, eps);
  const auto n = static_cast<Index>(eps.size());
#pragma omp parallel for schedule(static)
  for (Index L = 0; L < n; ++L) eps[L] = 0.5 * (eps[L] + eps[L].transpose()).eval();
}

void ElasticStiffness::apply(const Field& d, Field& Kd) {
  rk::deformation_gradients(gradient_, d, stress_);  // grad u, overwritten by the stress below
  const auto n_rows = static_cast<Index>(stress_.size());
#pragma omp parallel for schedule(static)
  for (Index L = 0; L < n_rows; ++L) stress_[L] = material_.stress(0.5 * (stress_[L] + stress_[L].transpose()));
  rk::internal_forces(gradient_, stress_, Kd);  // sum_L V_L sigma_L b_I(X_L)
  if (!stabilization_.active()) return;
  // add_stabilization_forces adds the restoring force -K_stab d.
  stabilization_force_.assign(d.size(), Vec3::Zero());
  rk::add_stabilization_forces(interpolation_, stabilization_, d, stabilization_force_);
  axpy(-1.0, stabilization_force_, Kd);
}

std::vector<Mat3> ElasticStiffness::diagonal_blocks() const {
  const auto n = static_cast<std::size_t>(gradient_.n_columns);
  std::vector<Mat3> block(n, Mat3::Zero());
  const double lambda = material_.lambda, mu = material_.mu;
  // Scattered from the rows, serially (once per solve). A single-precision operator's
  // own-particle correction (its row's sum, ~1e-7 of an entry) is left out: this is a
  // preconditioner.
  for (Index L = 0; L < gradient_.n_rows(); ++L)
    for (Index k = gradient_.row_offset[L]; k < gradient_.row_offset[L + 1]; ++k) {
      // d/dd_I of sum_L V_L sigma(sym(d_I (x) b)) b = V_L [mu (|b|^2 1 + b b^T) + lambda b b^T].
      const Vec3 b = gradient_.entry(L, k);
      block[gradient_.col[k]] +=
          gradient_.weight[L] * (mu * b.squaredNorm() * Mat3::Identity() + (mu + lambda) * b * b.transpose());
    }
  if (stabilization_.active()) {
    // [(I - N)^T W (I - N)]_II = sum_L W_L (delta_LI - Psi_I(X_L))^2, with the row's
    // weights in their relative form (rk::for_each_weight): Psi_L(X_L) takes the
    // correction 1 - sum, so delta_LL - Psi_L(X_L) = sum - psi_L.
    const auto& N = interpolation_;
    for (Index L = 0; L < static_cast<Index>(N.row_offset.size()) - 1; ++L) {
      const double w = stabilization_.weight[L];
      const double sum = 1.0 - rk::own_weight(N, L);
      bool has_self = false;
      for (Index k = N.row_offset[L]; k < N.row_offset[L + 1]; ++k) {
        const Index I = N.col[k];
        const double c = (L == I ? sum : 0.0) - static_cast<double>(N.psi[k]);
        has_self = has_self || L == I;
        block[I] += (w * c * c) * Mat3::Identity();
      }
      if (!has_self) block[L] += (w * sum * sum) * Mat3::Identity();
    }
  }
  return block;
}

}  // namespace rkpm::study
