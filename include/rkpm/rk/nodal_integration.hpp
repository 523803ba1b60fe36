// Nodal integration: one integration point per particle, at X_L with weight V_L,
// and the flat operators a time step needs, built once in the reference
// configuration (total Lagrangian).
//
// Stabilized conforming nodal integration (SCNI, Chen et al. 2001):
//   b_I(X_L) = (1/V_L) \oint_{dOmega_L} Psi_I N dGamma
// over the closed median-dual cell of L (see particles/dual_cells.hpp), by one-point
// rules on planar triangles. Because the cells tile the body and every facet is
// evaluated identically from both sides, sum_L V_L b_I(X_L) equals the boundary
// integral of Psi_I N (the integration constraint) and the linear patch test is
// passed to round-off on any cloud.
// Direct nodal integration (b_I = grad Psi_I(X_L)) is kept only as a contrast: it
// is unstable (spurious zero-energy modes).
//
// A step then computes F_L = sum_I x_I (x) b_I(X_L) (a gather over row L) and the
// internal force f_I = sum_L V_L P_L b_I(X_L) (a scatter from the same row, into
// per-thread buffers: rkpm/rk/row_scatter.hpp): no atomics. The simulator fuses both
// into one pass over the operator (sim/mechanics/body_mechanics.cpp) with the row kernels of
// rk/row_kernels.hpp; the untyped functions below dispatch the precision per call, for
// tests, studies and the per-point values outside the force pass.
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/particles/dual_cells.hpp"
#include "rkpm/rk/rk_approximation.hpp"
#include "rkpm/rk/operators.hpp"
#include "rkpm/rk/row_kernels.hpp"

#include <cstdint>
#include <type_traits>
#include <vector>

namespace rkpm::particles {
struct Cloud;
}

namespace rkpm::rk {

enum class Integration { SCNI, Direct };

// The quadrature of SCNI's cell-boundary integrals on each planar triangle of a
// smoothing cell's surface (both exact for linear functions: the patch test holds with
// either). Corners: the shape functions at the triangle's corners, a third of the area
// each; the corners (edge midpoints, face and element centroids) are shared by up to
// eight cells, so a hexahedral cloud costs about 7 evaluations per particle. Centroids:
// at the triangle's centroid, about 24 per particle. docs/verification/convergence.md compares them.
enum class FacetRule { Corners, Centroids };

// The transpose of a compressed-row pattern as index lists: for column I, the entries
// (by index into the row arrays) that reference it, ordered by row. Lets a "scatter"
// A^T y be computed as a gather: no atomics, deterministic.
struct CsrTranspose {
  std::vector<Index> offset;  // n_columns + 1
  std::vector<Index> entry;
  std::vector<Index> row;
  void build(const std::vector<Index>& row_offset, const std::vector<Index>& col, Index n_columns);
};

// Points on the body's surface with their weights (outward area vectors) and the shape
// functions there: the quadrature for tractions, surface terms and the integration
// constraint, consistent with the SCNI cells (the same boundary facets, by the same
// FacetRule as the gradient operator: with corners, a point per distinct corner of a
// cell's boundary pieces on one set of named surfaces, weighted by a third of the area
// of each piece it is a corner of).
struct BoundaryQuadrature {
  std::vector<Vec3> point;        // [m]
  std::vector<Vec3> area;         // outward area vector: the point's weight [m^2]
  std::vector<Index> owner;       // the particle whose dual cell the facet bounds
  std::vector<std::uint32_t> surface_mask;  // the named surfaces (Cloud::surface_names bits) the facet lies on
  std::vector<Index> row_offset;  // shape functions at each point (CSR)
  std::vector<Index> col;
  std::vector<double> psi;
};

// `rows` selects the rows to build (rows[L] != 0), for a rank of a distributed run that
// evaluates only its own points; the others stay empty, with weight 0. Empty: every row.
GradientOperator build_gradient_operator(const particles::Cloud& cloud, const RKApproximation& rk,
                                         Integration scheme,
                                         GradientPrecision precision = GradientPrecision::Double,
                                         const std::vector<char>& rows = {}, FacetRule rule = FacetRule::Corners);
// The facets on the named surfaces of `surface_bits` (Cloud::surface_bit; 0 = the whole
// boundary). Built by the terms that integrate over a surface, for their surface only.
BoundaryQuadrature build_boundary_quadrature(const particles::Cloud& cloud, const RKApproximation& rk,
                                             std::uint32_t surface_bits = 0u, FacetRule rule = FacetRule::Corners);
// The same for the facets of the boundary particles cloud.boundary_particles[first, last)
// only, in the same order, with the cloud's dual cells built once by the caller: a caller
// that reduces the quadrature as it goes builds it in batches, so the whole surface's
// shape functions are never held at once.
BoundaryQuadrature build_boundary_quadrature(const particles::Cloud& cloud, const particles::DualCells& cells,
                                             const RKApproximation& rk, std::uint32_t surface_bits,
                                             std::size_t first, std::size_t last, FacetRule rule = FacetRule::Corners);
NodalInterpolation build_nodal_interpolation(const particles::Cloud& cloud, const RKApproximation& rk,
                                             const std::vector<char>& rows = {});

// The correction row J adds at its own particle: 1 - sum_k psi_k, summed in double (see
// NodalInterpolation). A row that was not built (another rank's point) has none.
inline double own_weight(const NodalInterpolation& N, Index J) {
  const Index k0 = N.row_offset[J], k1 = N.row_offset[J + 1];
  if (k0 == k1) return 0.0;
  double sum = 0.0;
  for (Index k = k0; k < k1; ++k) sum += static_cast<double>(N.psi[k]);
  return 1.0 - sum;
}

// Row J's weights in the order every transposed product uses: add(I, w) for each entry,
// then add(J, own_weight). Their sum is one to double round-off.
template <class Add>
void for_each_weight(const NodalInterpolation& N, Index J, const Add& add) {
  const Index k0 = N.row_offset[J], k1 = N.row_offset[J + 1];
  if (k0 == k1) return;
  double sum = 0.0;
  for (Index k = k0; k < k1; ++k) {
    const double w = N.psi[k];
    sum += w;
    add(N.col[k], w);
  }
  add(J, 1.0 - sum);
}

// The particles for_each_weight visits for row J, in its order (an ordered
// rk::RowScatter plans with it).
template <class Emit>
void for_each_weight_column(const NodalInterpolation& N, Index J, const Emit& emit) {
  const Index k0 = N.row_offset[J], k1 = N.row_offset[J + 1];
  if (k0 == k1) return;
  for (Index k = k0; k < k1; ++k) emit(N.col[k]);
  emit(J);
}

// sum_I Psi_I(X_J) v_I over row J: the field of the generalized values v at particle J
// (physical displacement from d, physical velocity from v). The one interpolation
// gather every per-point value uses, in the relative form v_J + sum_k psi_k (v_k - v_J),
// which equals the weights of for_each_weight and reproduces a uniform v exactly.
inline Vec3 interpolate(const NodalInterpolation& N, const std::vector<Vec3>& v, Index J) {
  const Index k0 = N.row_offset[J], k1 = N.row_offset[J + 1];
  if (k0 == k1) return Vec3::Zero();
  const Vec3 vJ = v[J];
  Vec3 s = Vec3::Zero();
  for (Index k = k0; k < k1; ++k) s += static_cast<double>(N.psi[k]) * (v[N.col[k]] - vJ);
  return vJ + s;
}

// sum_I v_I (x) b_I(X_L) over row L: Grad_X h from a per-particle field, dF/dt from velocities,
// F_L from positions. The one gather every per-point gradient uses (in the relative
// form for single-precision storage, see GradientOperator).
inline Mat3 row_gradient(const GradientOperator& op, const std::vector<Vec3>& v, Index L) {
  return op.single_precision() ? row_gradient(op, op.grad_float, v, L) : row_gradient(op, op.grad, v, L);
}

// out[I] += w M b_I(X_L) over row L: the transposed product of row_gradient, for the
// internal force (w M = V_L P_L) and a coupled field's flux divergence.
inline void scatter_row(const GradientOperator& op, Index L, double w, const Mat3& M, Vec3* out) {
  if (op.single_precision())
    scatter_row(op, op.grad_float, L, w, M, out);
  else
    scatter_row(op, op.grad, L, w, M, out);
}

// Calls entry(I, b) for the entries of row L as the operator acts: as stored in double;
// in single precision the stored entries and then (L, -sum_J b~_J), the relative
// form's own-particle correction (GradientOperator). For assembling matrices (tests,
// studies); the step uses row_gradient and scatter_row.
template <class Entry>
void for_each_acting_entry(const GradientOperator& op, Index L, Entry entry) {
  Vec3 row_sum = Vec3::Zero();
  for (Index k = op.row_offset[L]; k < op.row_offset[L + 1]; ++k) {
    const Vec3 b = op.entry(L, k);
    entry(op.col[k], b);
    row_sum += b;
  }
  if (op.single_precision()) entry(L, Vec3(-row_sum));
}

// F_L of a body with reference positions X and displacements d: sum_I (X_I + d_I) (x)
// b_I(X_L) in double storage; I + sum_I (d_I - d_L) (x) b~_I in single precision, exact
// at rest.
inline Mat3 deformation_gradient(const GradientOperator& op, const std::vector<Vec3>& X, const std::vector<Vec3>& d,
                                 Index L) {
  return op.single_precision() ? deformation_gradient(op, op.grad_float, X, d, L)
                               : deformation_gradient(op, op.grad, X, d, L);
}

// F_L = sum_I x_I (x) b_I(X_L) for every row; x are current positions (X + d).
void deformation_gradients(const GradientOperator& op, const std::vector<Vec3>& x, std::vector<Mat3>& F);

// f_I = sum_L V_L P_L b_I(X_L): the internal force (P the first Piola-Kirchhoff stress per row).
void internal_forces(const GradientOperator& op, const std::vector<Mat3>& P, std::vector<Vec3>& f);

}  // namespace rkpm::rk
