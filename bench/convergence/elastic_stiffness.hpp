// The small-strain linear-elastic stiffness of the nodal-integration
// discretisation, applied without assembling it:
//   K d = sum_L V_L B_L^T D B_L d  +  (I - N)^T W (I - N) d,
// the first term from the (smoothed) gradient operator b_I(X_L), the second the
// interpolation-residual stabilization (stabilization.hpp). K d is computed with
// exactly the gathers a simulator time step uses: deformation_gradients gives
// grad u = sum_I d_I (x) b_I(X_L), Hooke's law the stress, internal_forces the
// nodal forces sum_L V_L sigma_L b_I(X_L), add_stabilization_forces the second term.
//
// Why matrix-free: K couples two particles whenever their supports reach a common
// smoothing cell, i.e. within about two support radii (~4-5 spacings): several
// hundred neighbours per particle, 3x3 blocks each, which at 1e5 particles is
// gigabytes for an assembled matrix; applying K costs two passes over the gradient
// operator (~60 entries per row).
#pragma once

#include "field.hpp"
#include "lame_sphere.hpp"

#include "rkpm/rk/nodal_integration.hpp"
#include "rkpm/rk/stabilization.hpp"

#include <vector>

namespace rkpm::study {

class ElasticStiffness {
 public:
  // `gradient` and `interpolation` must outlive this object; `stabilization` may be inactive.
  ElasticStiffness(const rk::GradientOperator& gradient, const rk::NodalInterpolation& interpolation,
                   rk::Stabilization stabilization, IsotropicElasticity material);

  // Kd = K d.
  void apply(const Field& d, Field& Kd);

  // The 3x3 diagonal blocks K_II, for a block-Jacobi preconditioner.
  std::vector<Mat3> diagonal_blocks() const;

  // Small-strain tensor sym(grad u) at every integration point.
  void strains(const Field& d, std::vector<Mat3>& eps) const;

  const IsotropicElasticity& material() const { return material_; }

 private:
  const rk::GradientOperator& gradient_;
  const rk::NodalInterpolation& interpolation_;
  rk::Stabilization stabilization_;
  IsotropicElasticity material_;
  std::vector<Mat3> stress_;   // scratch
  Field stabilization_force_;  // scratch
};

}  // namespace rkpm::study
