// The operators a step applies, as data: the smoothed gradients b_I(X_L) and the
// shape-function values Psi_I(X_J), both in compressed rows. Built by
// rk/nodal_integration.hpp; applied row by row by the kernels of rk/row_kernels.hpp.
#pragma once

#include "rkpm/common/types.hpp"

#include <vector>

namespace rkpm::rk {

enum class GradientPrecision { Double, Float };

// A sparse matrix of 3-vectors in compressed rows. Its transposed products are
// computed as deterministic scatters from the rows (rkpm/rk/row_scatter.hpp), so no
// transpose is stored.
//
// The entries are stored in double (`grad`) or in single precision (`grad_float`, half
// the bytes a step streams; the other vector is empty). Sums are always taken in
// double. In single precision the stored b~_I(X_L) no longer sum to zero over a row to
// double round-off, and a gather sum_I v_I (x) b~_I would multiply that defect by |v|
// (a position, metres away from the origin). So the single-precision operator is used
// in its relative form: the effective entries are b~_I for I != L and b~_L - sum_J b~_J
// for the row's own particle, i.e. every row sums to zero exactly, which is the
// constant-reproduction property of the exact operator. Then
//   gather:  sum_I v_I (x) b_I   = sum_I (v_I - v_L) (x) b~_I,
//   scatter: f_I += M b~_I, and f_L -= M sum_J b~_J,
// are exact transposes of each other (the internal force stays the derivative of the
// discrete energy), and the deformation gradient is F_L = I + sum_I (d_I - d_L) (x) b~_I,
// which is exactly I at rest and errs by the storage round-off times |Grad u| otherwise.
struct GradientOperator {
  std::vector<Index> row_offset;  // n_points + 1
  std::vector<Index> col;         // particle I of each entry
  std::vector<Vec3> grad;         // b_I(X_L) of each entry [1/m], double storage
  // b_I(X_L) [1/m] in single precision, row by row in planar order: a row of n entries
  // from entry k0 on holds its x components at [3 k0, 3 k0 + n), then its y, then its z,
  // so the row kernels load several entries' components at once (rk/row_kernels.hpp).
  std::vector<float> grad_float;
  std::vector<double> weight;     // V_L: integration weight of each row [m^3]
  Index n_columns = 0;            // particles

  Index n_rows() const { return static_cast<Index>(row_offset.size()) - 1; }
  bool single_precision() const { return !grad_float.empty(); }
  // Row L's single-precision entries, in planar order.
  const float* planar_row(Index L) const { return grad_float.data() + 3 * static_cast<std::size_t>(row_offset[L]); }
  // b_I(X_L) of entry k of row L as stored (before the relative form's own-particle
  // correction).
  Vec3 entry(Index L, Index k) const {
    if (!single_precision()) return grad[k];
    const float* b = planar_row(L);
    const Index n = row_offset[L + 1] - row_offset[L], m = k - row_offset[L];
    return Vec3(b[m], b[n + m], b[2 * n + m]);
  }
};

// Shape-function values at the particles, Psi_I(X_J): maps the generalized
// coordinates d_I to the physical displacement u(X_J) = sum_I Psi_I(X_J) d_I.
//
// The values are stored in single precision (8 bytes per entry with the column, against
// 12) and every sum runs in double. A row is used in its relative form, like the
// single-precision gradients: the own particle J takes the weight 1 - sum_k psi_k on top
// of its stored value (own_weight), so each row is a partition of unity to double
// round-off whatever the float rounding of psi. A uniform field is then reproduced
// exactly and the stabilization residual of a rigid translation is zero; a linear field
// is reproduced to the storage's rounding (about 1e-7 of the support radius).
struct NodalInterpolation {
  std::vector<Index> row_offset;
  std::vector<Index> col;
  std::vector<float> psi;
};

}  // namespace rkpm::rk
