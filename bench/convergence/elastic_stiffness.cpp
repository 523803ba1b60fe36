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
  rk::CsrTranspose T;  // the step needs no transpose; this preconditioner does
  T.build(gradient_.row_offset, gradient_.col, gradient_.n_columns);
  const auto n = static_cast<Index>(T.offset.size()) - 1;
  std::vector<Mat3> block(static_cast<std::size_t>(n), Mat3::Zero());
  const double lambda = material_.lambda, mu = material_.mu;
#pragma omp parallel for schedule(static)
  for (Index I = 0; I < n; ++I) {
    // d/dd_I of sum_L V_L sigma(sym(d_I (x) b)) b = V_L [mu (|b|^2 1 + b b^T) + lambda b b^T].
    Mat3 k = Mat3::Zero();
    for (Index t = T.offset[I]; t < T.offset[I + 1]; ++t) {
      const Vec3& b = gradient_.grad[T.entry[t]];
      k += gradient_.weight[T.row[t]] * (mu * b.squaredNorm() * Mat3::Identity() + (mu + lambda) * b * b.transpose());
    }
    if (stabilization_.active()) {
      // [(I - N)^T W (I - N)]_II = sum_L W_L (delta_LI - Psi_I(X_L))^2.
      const auto& NT = interpolation_.transpose;
      double s = 0.0;
      bool has_self = false;
      for (Index t = NT.offset[I]; t < NT.offset[I + 1]; ++t) {
        const Index L = NT.row[t];
        const double c = (L == I ? 1.0 : 0.0) - interpolation_.psi[NT.entry[t]];
        has_self = has_self || L == I;
        s += stabilization_.weight[L] * c * c;
      }
      if (!has_self) s += stabilization_.weight[I];
      k += s * Mat3::Identity();
    }
    block[I] = k;
  }
  return block;
}

}  // namespace rkpm::study
