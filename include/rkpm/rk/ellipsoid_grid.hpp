// The particles whose ellipsoidal supports can reach points near a centre, found
// through a bucket grid instead of a kd-tree ball.
//
// Why: a ball query around c must reach a_max + reach, a_max the longest semi-axis near
// c. In a refined shell that keeps its layers the longest semi-axis is the one across
// the wall while the supports are short along it, so the finer the shell, the more the
// tree's ball holds beyond the particles a point needs (docs/verification/performance.md
// counts them on large shells), gathered one by one from wherever the tree kept them.
//
// How: an ellipsoid x^T G x <= 1 spans sqrt((G^-1)_ii) along axis i, so a particle
// whose support reaches a point p with |p - c| <= reach has |X_J,i - c_i| <=
// sqrt((G_J^-1)_ii) + reach on every axis. Every coarse cell (side C >= a_max + the
// largest reach served) holds the largest of those spans over the particles in the
// 3 x 3 x 3 cells around it; the query visits the box of those half-widths (plus reach)
// around c, cut to the Euclidean ball, so it never needs more than the ball.
//
// What that box saves depends on how the supports lie: where their long axes follow a
// coordinate axis it is as narrow as the supports across the others; on the RBC shell
// the layers' edges follow the cubed sphere's unit directions, up to about 40 degrees
// from the wall's normal, and the box is about the ball's. What the grid gains there
// (with the caller's branch-free filter; docs/verification/performance.md measures
// the set-up) is its layout: the particles
// are sorted by bucket (side s, C a multiple of s), one row of buckets along x is one
// contiguous range, and the supports' metrics and smallest semi-axes are
// copied in that order, so the test over a range streams contiguous arrays (the
// positions are read through order(): copying them too measured no faster). The
// metrics are stored in float; a caller's test widens its limit by test_slack(), which
// covers that rounding (a looser test only keeps a few more particles whose kernel is
// zero, which the evaluation drops).
#pragma once

#include "rkpm/common/types.hpp"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace rkpm::rk {

// A symmetric matrix's distinct entries 00, 11, 22, 01, 02, 12: how the supports'
// metrics are stored (two thirds of a Mat3).
using SymmetricEntries = std::array<double, 6>;
inline SymmetricEntries symmetric_entries(const Mat3& G) {
  return {G(0, 0), G(1, 1), G(2, 2), G(1, 0), G(2, 0), G(2, 1)};
}

// q^2 = r^T G r from G's distinct entries (in symmetric_entries' order). Every q^2 of
// the approximation and of its candidate tests is formed here, so a particle is in or
// out of a support alike wherever it is asked.
inline double quadratic_form(double g00, double g11, double g22, double g01, double g02, double g12, double rx,
                             double ry, double rz) {
  const double q2 = g00 * rx * rx + g11 * ry * ry + g22 * rz * rz + 2.0 * (g01 * rx * ry + g02 * rx * rz + g12 * ry * rz);
  return q2 > 0.0 ? q2 : 0.0;
}

// The box of the particles' positions and their longest semi-axis (non-empty X).
struct SupportsBox {
  Vec3 lo, hi;
  double a_max = 0.0;
};
SupportsBox supports_box(const std::vector<Vec3>& X, const std::vector<double>& radius);

class EllipsoidGrid {
 public:
  EllipsoidGrid() = default;
  // metric[J] = G_J, radius[J] its longest semi-axis, min_axis[J] its shortest. Keeps
  // copies of what the queries read, in bucket order.
  // Buckets of `bucket_fraction` of the median shortest semi-axis.
  EllipsoidGrid(const std::vector<Vec3>& X, const std::vector<SymmetricEntries>& metric,
                const std::vector<double>& radius, const std::vector<double>& min_axis, double bucket_fraction = 0.5);

  bool empty() const { return order_.empty(); }
  // Whether a query with this reach stays within one coarse neighbourhood.
  bool covers(double reach) const { return reach <= max_reach_; }
  double max_reach() const { return max_reach_; }

  // Ranges [first, last) of positions in bucket order that hold every particle whose
  // support can reach a point within `reach` of c, and also lies within `ball` of c
  // (an upper bound of a_J + reach the caller knows: SupportBound). A superset: the
  // caller tests each particle. Requires covers(reach).
  void ranges(const Vec3& c, double reach, double ball, std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) const {
    ranges(c, Vec3::Constant(reach), ball, out);
  }
  // The same for points within `reach_along(a)` of c along each axis a (of the grid's
  // frame): a query cell that is flat in the frame of needle-shaped supports reaches
  // across them by its own width, not by its radius.
  void ranges(const Vec3& c, const Vec3& reach_along, double ball,
              std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) const;

  // The particles in bucket order, and the supports' shapes in that order.
  const std::vector<Index>& order() const { return order_; }
  // G_J's distinct entries 00, 11, 22, 01, 02, 12.
  // Stored in float (the grid is kept beside the operators while they are built): a
  // caller's test widens its limit by test_slack(), which covers that rounding.
  const std::array<std::vector<float>, 6>& g() const { return g_; }
  const std::vector<float>& inverse_min_axis() const { return inv_min_axis_; }
  double test_slack() const { return test_slack_; }

 private:
  // The largest half-widths sqrt((G_J^-1)_ii) over the neighbourhood of c's coarse cell
  // (zero where no particle lies near).
  const std::array<double, 3>& spans_near(const Vec3& c) const;
  int bucket_index(int axis, double coordinate) const;
  std::size_t coarse_of_bucket(int bx, int by, int bz) const;

  Vec3 origin_ = Vec3::Zero();
  double bucket_ = 1.0;  // s
  double inverse_bucket_ = 1.0;
  int per_coarse_ = 1;   // C / s
  double max_reach_ = 0.0;
  std::array<int, 3> dims_{1, 1, 1};         // buckets along each axis
  std::array<int, 3> coarse_dims_{1, 1, 1};  // coarse cells along each axis
  std::vector<std::uint32_t> start_;         // bucket b holds order_[start_[b] .. start_[b+1])
  std::vector<Index> order_;
  std::vector<float> inv_min_axis_;
  std::array<std::vector<float>, 6> g_;
  double test_slack_ = 0.0;
  std::vector<std::array<double, 3>> spans_;  // per coarse cell
};

}  // namespace rkpm::rk
