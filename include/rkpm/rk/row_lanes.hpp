// The row kernels of the single-precision gradient operator, on vector registers.
//
// Why: the force pass spends most of its time in two loops over each row, the gather
// F_L = I + sum_k (v_k - v_L) (x) b~_k and the scatter f_k += w M b~_k
// (rk/nodal_integration.hpp). A 3-vector fills no whole vector register: Eigen packs
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

#include <cstring>
#include <type_traits>

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
  } else {
    Vec3 a0 = Vec3::Zero(), a1 = a0, a2 = a0, b0 = a0, b1 = a0, b2 = a0;
    for (Index m = 0; m < n; ++m) {
      const Index I = col[m];
      const double ex = bx[m], ey = by[m], ez = bz[m];
      const Vec3 va = value_a(I) - aL;
      a0 += va * ex;
      a1 += va * ey;
      a2 += va * ez;
      if constexpr (two) {
        const Vec3 vb = value_b(I) - bL;
        b0 += vb * ex;
        b1 += vb * ey;
        b2 += vb * ez;
      }
    }
    ga << a0, a1, a2;
    if constexpr (two) *gb << b0, b1, b2;
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
