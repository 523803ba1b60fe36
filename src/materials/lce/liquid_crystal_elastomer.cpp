#include "materials/lce/liquid_crystal_elastomer.hpp"

#include "materials/parameter_checks.hpp"

#include <Eigen/Eigenvalues>

namespace rkpm::materials {

void LiquidCrystalElastomer::validate() const {
  constexpr std::string_view model = "lce";
  detail::require_positive(model, "mu", mu);
  detail::require_non_negative(model, "K", K);
  detail::require_positive(model, "s", s);
  detail::require_non_negative(model, "kappa", kappa);
  detail::require_finite(model, "zeta", zeta);
  detail::require_non_negative(model, "mobility", mobility);
}

Vec3 LiquidCrystalElastomer::equilibrium_director(const Mat3& F, const Vec3& h0) const {
  const Vec3 Fh0 = F * h0;
  if (s == 1.0) return Fh0.normalized();
  // The accurate (QR) solver, not computeDirect: the director is a state
  // variable, and near-repeated eigenvalues are common (soft-mode onset).
  const Mat3 M = F * reference_step_length(h0) * F.transpose();
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(M);
  Vec3 h = solver.eigenvectors().col(s > 1.0 ? 2 : 0);  // eigenvalues ascending
  if (h.dot(Fh0) < 0.0) h = -h;                        // nematic: keep the branch nearest F h0
  return h.normalized();
}

}  // namespace rkpm::materials
