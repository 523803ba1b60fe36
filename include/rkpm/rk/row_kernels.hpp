// The row kernels of the force pass, in one header: what the innermost loop does.
//
// A step reads each row L of the gradient operator once (sim/mechanics/body_mechanics.cpp):
//   gather   F_L = sum_I x_I (x) b_I(X_L)      deformation_gradient (with a coupled
//                                              field's gradient: deformation_and_field_gradients)
//   stress   P_L = material.stress(L, F_L)     (the material's own kernel)
//   scatter  f_I += V_L P_L b_I(X_L)           scatter_row
// and, when the body is stabilized, row L of the interpolation operator:
//   r_L = d_L - sum_I Psi_I(X_L) d_I          interpolation_residual
//   f_L, f_I -= (transpose) W_L r_L            scatter_residual (rk/stabilization.hpp).
// The kernels are typed by the operator's storage `grad` (op.grad or op.grad_float): a
// pass over many rows dispatches on the precision once and calls these. Single
// precision reads its rows through op.planar_row and the lanes kernels below; there
// `grad` only selects the kernel. The untyped wrappers that dispatch per call are in
// rk/nodal_integration.hpp.
//
// The single-precision kernels run on vector registers (namespace lanes). Why: the
// force pass spends most of its time in two loops over each row, the gather
// F_L = I + sum_k (v_k - v_L) (x) b~_k and the scatter f_k += w M b~_k. A 3-vector fills no whole vector register: Eigen packs
// two components of a Vector3d into an SSE2 register and does the third alone. Here:
// - the gather keeps v_k - v_L in the first three lanes of a four-lane vector and adds
//   one entry at a time, in the row's order: each of the nine sums is the sequential
//   sum the Eigen loop made, to the bit;
// - the scatter forms the contributions (w M) b~_k of four entries at once, each lane
//   with the operations of the Eigen loop in its order, and hands them to the sink in
//   the row's order: the same bits again.
// The row's entries are stored component by component (all x, then all y, then all z:
// GradientOperator's planar layout), so the scatter loads four entries' components with
// one load each. The vectors are the compiler's generic vector types; a build for the
// machine (RKPM_NATIVE) with AVX uses them (the vector form), the portable build (SSE2,
// where each 4-lane operation is two instructions and measured slower) runs the same
// arithmetic one entry at a time (the scalar form; kVectorRows picks). A lane's
// arithmetic is the same IEEE operation as the scalar one (no fused multiply-add:
// cmake/warnings.cmake), so both forms give the same bits, which are those of the
// portable build's Eigen loops they replace (tests/rk/test_row_lanes.cpp checks both
// forms in every build). A build with FMA had Eigen fuse two components of M b; there
// the scatter now rounds as the portable build does.
//
// Summing across lanes (lane l takes entries l, l + 4, ...) would shorten the gather's
// dependency chains, but changes F by round-off and with it the path of a relaxation
// (docs/verification/relaxation.md, "Round-off moves the path"), for a gain that was
// small in the native build and a loss in the portable one
// (docs/verification/performance.md measures both).
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/rk/operators.hpp"

#include <cstring>
#include <emmintrin.h>
#include <type_traits>
#include <vector>

namespace rkpm::rk::lanes {

// Whether the target has whole 4-double registers. Without them (the portable SSE2
// build) each 4-lane operation is two instructions, and the scalar form measured
// faster (docs/verification/performance.md), so the force pass takes it there. Both forms give the
// same bits, so translation units built for different targets agree.
#ifdef __AVX__
inline constexpr bool kVectorRows = true;
#else
inline constexpr bool kVectorRows = false;
#endif

constexpr int kWidth = 4;
using Doubles = double __attribute__((vector_size(kWidth * sizeof(double))));
using Floats = float __attribute__((vector_size(kWidth * sizeof(float))));
using Pairs = double __attribute__((vector_size(2 * sizeof(double))));

inline Doubles broadcast(double x) { return Doubles{x, x, x, x}; }

// Four stored entries from p, widened to double.
inline Doubles widen(const float* p) {
  Floats f;
  std::memcpy(&f, p, sizeof f);
  return __builtin_convertvector(f, Doubles);
}

// M b with the association of Eigen's Matrix3d * Vector3d in a portable build (SSE2:
// the first two components in one packet, column by column, the third by a scalar
// sum): (M_i0 b_0 + M_i1 b_1) + M_i2 b_2 for i = 0, 1, and
// M_20 b_0 + (M_21 b_1 + M_22 b_2). The force pass formed w (M b) with Eigen before
// these kernels, which evaluates it as (w M) b, and a relaxation's path follows the
// round-off (docs/verification/relaxation.md, "Round-off moves the path"), so the kernels keep those
// bits. T is double or Doubles (four entries at once).
template <class T>
void product(const T m[3][3], const T& b0, const T& b1, const T& b2, T out[3]) {
  out[0] = (m[0][0] * b0 + m[0][1] * b1) + m[0][2] * b2;
  out[1] = (m[1][0] * b0 + m[1][1] * b1) + m[1][2] * b2;
  out[2] = m[2][0] * b0 + (m[2][1] * b1 + m[2][2] * b2);
}

// The absent second field of row_gradients (a gather of one field).
struct NoField {
  Vec3 operator()(Index) const { return Vec3::Zero(); }
};

// g = sum_k (v_k - v_L) (x) b~_k over a row of n entries whose components sit at
// b[0..n), b[n..2n), b[2n..3n) and whose particles are col[0..n); value(I) gives v_I;
// for one field, or for two at once (ga from a, gb from b: the force pass gathers the
// displacements and, for a material with a coupled field, that field over the same row, so the row
// and its columns are loaded once and the two sets of sums run side by side).
// One entry at a time, in the row's order; the vector form keeps v_k - v_L in the first
// three lanes. Either way each of the nine sums of a field is the sequential sum, to the
// bit, whether gathered alone or with another field.
template <bool Vector = kVectorRows, class ValueA, class ValueB = NoField>
void row_gradients(const Index* col, const float* b, Index n, const ValueA& value_a, const Vec3& aL, Mat3& ga,
                   const ValueB& value_b = NoField{}, const Vec3& bL = Vec3::Zero(), Mat3* gb = nullptr) {
  constexpr bool two = !std::is_same_v<ValueB, NoField>;
  const float* bx = b;
  const float* by = b + n;
  const float* bz = b + 2 * n;
  if constexpr (Vector) {
    const Doubles AL{aL(0), aL(1), aL(2), 0.0}, BL{bL(0), bL(1), bL(2), 0.0};
    const Doubles zero{0.0, 0.0, 0.0, 0.0};
    Doubles a0 = zero, a1 = zero, a2 = zero, b0 = zero, b1 = zero, b2 = zero;  // columns of ga, gb
    for (Index m = 0; m < n; ++m) {
      const Index I = col[m];
      const Doubles ex = broadcast(static_cast<double>(bx[m])), ey = broadcast(static_cast<double>(by[m])),
                    ez = broadcast(static_cast<double>(bz[m]));
      const Vec3 ak = value_a(I);
      const Doubles va = Doubles{ak(0), ak(1), ak(2), 0.0} - AL;
      a0 += va * ex;
      a1 += va * ey;
      a2 += va * ez;
      if constexpr (two) {
        const Vec3 bk = value_b(I);
        const Doubles vb = Doubles{bk(0), bk(1), bk(2), 0.0} - BL;
        b0 += vb * ex;
        b1 += vb * ey;
        b2 += vb * ez;
      }
    }
    ga << a0[0], a1[0], a2[0], a0[1], a1[1], a2[1], a0[2], a1[2], a2[2];
    if constexpr (two) *gb << b0[0], b1[0], b2[0], b0[1], b1[1], b2[1], b0[2], b1[2], b2[2];
  } else if constexpr (two) {
    // Two fields on two-lane registers: the six components of v_k - v_L in three pairs
    // (a_x a_y | a_z b_x | b_y b_z), each pair times each component of b~_k into its own
    // sum, nine registers of sums. Eigen's Vector3d arithmetic (a pair and a single per
    // vector) holds twelve, which with the operands outgrows SSE2's sixteen registers:
    // the compiler kept four sums in memory, and each entry waited on a store and a load
    // (docs/verification/performance.md measures the gain). Each lane makes the scalar
    // form's operations on its component, so the bits are those of the one-field form below.
    const Pairs L0{aL(0), aL(1)}, L1{aL(2), bL(0)}, L2{bL(1), bL(2)};
    Pairs s00{}, s01{}, s02{}, s10{}, s11{}, s12{}, s20{}, s21{}, s22{};  // pair p times component j
    for (Index m = 0; m < n; ++m) {
      const Index I = col[m];
      // By reference where value() returns one, and loaded straight into the registers:
      // through a copy on the stack, a 16-byte load of two 8-byte stores waits for both.
      const auto& ak = value_a(I);
      const auto& bk = value_b(I);
      const Pairs p0 = Pairs(_mm_loadu_pd(ak.data())) - L0;
      const Pairs p1 = Pairs(_mm_unpacklo_pd(_mm_load_sd(ak.data() + 2), _mm_load_sd(bk.data()))) - L1;
      const Pairs p2 = Pairs(_mm_loadu_pd(bk.data() + 1)) - L2;
      const double ex = bx[m], ey = by[m], ez = bz[m];
      const Pairs e0{ex, ex}, e1{ey, ey}, e2{ez, ez};
      s00 += p0 * e0;
      s01 += p0 * e1;
      s02 += p0 * e2;
      s10 += p1 * e0;
      s11 += p1 * e1;
      s12 += p1 * e2;
      s20 += p2 * e0;
      s21 += p2 * e1;
      s22 += p2 * e2;
    }
    ga << s00[0], s01[0], s02[0], s00[1], s01[1], s02[1], s10[0], s11[0], s12[0];
    *gb << s10[1], s11[1], s12[1], s20[0], s21[0], s22[0], s20[1], s21[1], s22[1];
  } else {
    Vec3 a0 = Vec3::Zero(), a1 = a0, a2 = a0;
    for (Index m = 0; m < n; ++m) {
      const Index I = col[m];
      const double ex = bx[m], ey = by[m], ez = bz[m];
      const Vec3 va = value_a(I) - aL;
      a0 += va * ex;
      a1 += va * ey;
      a2 += va * ez;
    }
    ga << a0, a1, a2;
  }
}

// The gather of one field (row_gradients).
template <bool Vector = kVectorRows, class Value>
Mat3 row_gradient(const Index* col, const float* b, Index n, const Value& value, const Vec3& vL) {
  Mat3 g;
  row_gradients<Vector>(col, b, n, value, vL, g);
  return g;
}

// add(col[k], (w M) b~_k) for the row's entries in order, then add(L, -((w M) sum_k b~_k))
// (the relative form's own-particle term), with the sum over the entries in order. The
// vector form makes four entries' contributions at once.
template <bool Vector = kVectorRows, class Add>
void scatter_row(const Index* col, const float* b, Index n, Index L, double w, const Mat3& M, const Add& add) {
  const float* bx = b;
  const float* by = b + n;
  const float* bz = b + 2 * n;
  double wm[3][3];  // w M
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) wm[i][j] = w * M(i, j);
  double sx = 0.0, sy = 0.0, sz = 0.0;  // sum_k b~_k
  Index k = 0;
  if constexpr (Vector) {
    Doubles m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = broadcast(wm[i][j]);
    for (; k + kWidth <= n; k += kWidth) {
      const Doubles b0 = widen(bx + k), b1 = widen(by + k), b2 = widen(bz + k);
      Doubles c[3];
      product(m, b0, b1, b2, c);
      for (int l = 0; l < kWidth; ++l) {
        add(col[k + l], Vec3(c[0][l], c[1][l], c[2][l]));
        sx += b0[l];
        sy += b1[l];
        sz += b2[l];
      }
    }
  }
  // The scalar form's entries, and the vector form's last ones (the same operations).
  for (; k < n; ++k) {
    const double b0 = bx[k], b1 = by[k], b2 = bz[k];
    double c[3];
    product(wm, b0, b1, b2, c);
    add(col[k], Vec3(c[0], c[1], c[2]));
    sx += b0;
    sy += b1;
    sz += b2;
  }
  double own[3];
  product(wm, sx, sy, sz, own);
  add(L, Vec3(-own[0], -own[1], -own[2]));
}

}  // namespace rkpm::rk::lanes

namespace rkpm::rk {

// The row loops below read the operator through raw pointers and accumulate in locals:
// with the vectors' members and a Mat3 in memory, the compiler must assume each store
// may alias them and reloads them per entry, extra loads in the innermost loop of the
// force pass (docs/verification/performance.md measures the pass).
//
// value(I) gives the field at particle I: a stored array (row_gradient) or a sum formed
// on the fly (the positions X_I + d_I, which are not stored).
template <class Stored, class Value>
Mat3 row_gradient_of(const GradientOperator& op, const std::vector<Stored>& grad, const Value& value, Index L) {
  const Index* col = op.col.data();
  const Index k0 = op.row_offset[L], k1 = op.row_offset[L + 1];
  if constexpr (std::is_same_v<Stored, float>) {
    return lanes::row_gradient(col + k0, op.planar_row(L), k1 - k0, value, value(L));
  } else {
    // g = sum_k v_k b_k^T, one column per component of b.
    const Stored* b = grad.data();
    Vec3 g0 = Vec3::Zero(), g1 = Vec3::Zero(), g2 = Vec3::Zero();
    for (Index k = k0; k < k1; ++k) {
      const Vec3 vk = value(col[k]);
      g0 += vk * b[k](0);
      g1 += vk * b[k](1);
      g2 += vk * b[k](2);
    }
    Mat3 g;
    g << g0, g1, g2;
    return g;
  }
}

template <class Stored>
Mat3 row_gradient(const GradientOperator& op, const std::vector<Stored>& grad, const std::vector<Vec3>& v, Index L) {
  const Vec3* vp = v.data();
  return row_gradient_of(op, grad, [vp](Index I) -> const Vec3& { return vp[I]; }, L);
}

// Row L's contributions w M b_I(X_L), handed to add(I, c) in the row's order: its
// entries, then (single precision) the own-particle correction at L.
// `scatter_columns` names the same columns in the same order (an ordered
// rk::RowScatter plans with it).
template <class Stored, class Add>
void scatter_row(const GradientOperator& op, const std::vector<Stored>& grad, Index L, double w, const Mat3& M_in,
                 const Add& add) {
  const Mat3 M = M_in;
  const Index* col = op.col.data();
  const Index k0 = op.row_offset[L], k1 = op.row_offset[L + 1];
  if constexpr (std::is_same_v<Stored, float>) {
    lanes::scatter_row(col + k0, op.planar_row(L), k1 - k0, L, w, M, add);
  } else {
    const Stored* b = grad.data();
    for (Index k = k0; k < k1; ++k) add(col[k], Vec3(w * (M * b[k])));
  }
}

template <class Stored>
void scatter_row(const GradientOperator& op, const std::vector<Stored>& grad, Index L, double w, const Mat3& M,
                 Vec3* out) {
  scatter_row(op, grad, L, w, M, [out](Index I, const Vec3& c) { out[I] += c; });
}

template <class Emit>
void scatter_columns(const GradientOperator& op, Index L, const Emit& emit) {
  for (Index k = op.row_offset[L]; k < op.row_offset[L + 1]; ++k) emit(op.col[k]);
  if (op.single_precision()) emit(L);
}

// F_L in the form the storage needs (see deformation_gradient below).
// Double storage gathers the positions X + d (formed per entry, the same bits as a
// stored sum); single storage gathers d in the relative form and adds I.
template <class Stored>
Mat3 deformation_gradient(const GradientOperator& op, const std::vector<Stored>& grad, const std::vector<Vec3>& X,
                          const std::vector<Vec3>& d, Index L) {
  if constexpr (!std::is_same_v<Stored, float>) {
    const Vec3* Xp = X.data();
    const Vec3* dp = d.data();
    return row_gradient_of(op, grad, [Xp, dp](Index I) { return Vec3(Xp[I] + dp[I]); }, L);
  } else {
    return Mat3::Identity() + row_gradient(op, grad, d, L);
  }
}

// F_L and Grad_X h_L of a per-particle vector field h, one row together (the force pass
// of a material with a coupled field, such as the LCE's Frank term). In single
// precision one sweep over the row gathers both (lanes::row_gradients): the row and its
// columns are read once, and the bits are those of the two gathers apart.
template <class Stored>
void deformation_and_field_gradients(const GradientOperator& op, const std::vector<Stored>& grad,
                                     const std::vector<Vec3>& X, const std::vector<Vec3>& d,
                                     const std::vector<Vec3>& h, Index L, Mat3& F, Mat3& grad_h) {
  if constexpr (std::is_same_v<Stored, float>) {
    const Vec3* dp = d.data();
    const Vec3* hp = h.data();
    const Index k0 = op.row_offset[L], k1 = op.row_offset[L + 1];
    Mat3 grad_u;
    lanes::row_gradients(
        op.col.data() + k0, op.planar_row(L), k1 - k0, [dp](Index I) -> const Vec3& { return dp[I]; }, dp[L],
        grad_u, [hp](Index I) -> const Vec3& { return hp[I]; }, hp[L], &grad_h);
    F = Mat3::Identity() + grad_u;
  } else {
    F = deformation_gradient(op, grad, X, d, L);
    grad_h = row_gradient(op, grad, h, L);
  }
}

// r_L = d_L - sum_I Psi_I(X_L) d_I = sum_k psi_k (d_L - d_k) in the relative form of
// NodalInterpolation: how far d_L is from the field it interpolates, zero for a rigid
// translation whatever the storage's rounding. Also sum_k psi_k, in the row's order,
// which the transpose (scatter_residual) needs at L: taken in the same sweep, it costs
// one add per entry instead of a third pass over the row.
struct RowResidual {
  Vec3 r;
  double weight_sum;
};

inline RowResidual interpolation_residual(const NodalInterpolation& N, const std::vector<Vec3>& d, Index L) {
  const Index* col = N.col.data();
  const auto* psi = N.psi.data();
  const Vec3* dp = d.data();
  const Index k0 = N.row_offset[L], k1 = N.row_offset[L + 1];
  const Vec3 dL = dp[L];
  Vec3 r = Vec3::Zero();
  double sum = 0.0;
  for (Index k = k0; k < k1; ++k) {
    const double p = psi[k];
    r += p * (dL - dp[col[k]]);
    sum += p;
  }
  return {r, sum};
}

// Row L's share of the stabilization force, sink(I, c) in the row's order: the transpose
// of interpolation_residual applied to wr = W_L r_L, i.e. +(sum_k psi_k) wr at L
// (weight_sum, from interpolation_residual), then -psi_k wr at each entry's particle. The
// forces of a row sum to zero.
template <class Sink>
void scatter_residual(const NodalInterpolation& N, Index L, const Vec3& wr, double weight_sum, const Sink& sink) {
  const Index* col = N.col.data();
  const auto* psi = N.psi.data();
  const Index k0 = N.row_offset[L], k1 = N.row_offset[L + 1];
  sink(L, Vec3(weight_sum * wr));
  for (Index k = k0; k < k1; ++k) sink(col[k], Vec3(-(static_cast<double>(psi[k]) * wr)));
}

}  // namespace rkpm::rk
