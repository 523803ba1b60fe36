// The particles whose ellipsoidal supports can reach points near a centre, found
// through a bucket grid shaped by the supports instead of a Euclidean ball.
//
// Why: a ball query around c must reach a_max + reach, a_max the longest semi-axis near
// c. In a refined shell that keeps its layers, the longest semi-axis is the one through
// the wall while the supports are short along it: at 1e6 particles (semi-axes about
// 0.09 um along the wall, 0.25 um across it) the ball held about 750 particles for the
// 30-65 a point needs, and the set-up grew faster than the particle count.
//
// How: an ellipsoid x^T G x <= 1 spans sqrt((G^-1)_ii) along axis i, so a particle
// whose support reaches a point p with |p - c| <= reach has |X_J,i - c_i| <=
// sqrt((G_J^-1)_ii) + reach on every axis. Every coarse cell (side C >= a_max + the
// largest reach served) holds the largest of those spans over the particles in the
// 3 x 3 x 3 cells around it, so the box of those half-widths (plus reach) around c holds
// every particle that matters. On a wall that lies along the axes the box is about as
// narrow as the supports along the wall; on a tilted wall it widens towards the ball's,
// and the query then takes the Euclidean ball's box where that is smaller, so it never
// visits more than a ball would.
//
// The particles are sorted by bucket (side s, C a multiple of s), so one row of buckets
// along x is one contiguous range; a query visits the rows of the box. The positions,
// metrics and smallest semi-axes are copied in that order, so a caller's test over a
// range reads contiguous arrays; the metrics in float, which a test with a limit widened
// by test_slack() tolerates (a looser test only keeps a few more particles whose kernel
// is zero, which the evaluation drops).
#pragma once

#include "rkpm/common/types.hpp"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace rkpm::rk {

class EllipsoidGrid {
 public:
  EllipsoidGrid() = default;
  // metric[J] = G_J, radius[J] its longest semi-axis, min_axis[J] its shortest. Keeps
  // copies of what the queries read, in bucket order.
  EllipsoidGrid(const std::vector<Vec3>& X, const std::vector<Mat3>& metric, const std::vector<double>& radius,
                const std::vector<double>& min_axis);

  bool empty() const { return order_.empty(); }
  // Whether a query with this reach stays within one coarse neighbourhood.
  bool covers(double reach) const { return reach <= max_reach_; }

  // Ranges [first, last) of positions in bucket order that hold every particle whose
  // support can reach a point within `reach` of c, and also lies within `ball` of c
  // (an upper bound of a_J + reach the caller knows: SupportBound). A superset: the
  // caller tests each particle. Requires covers(reach).
  void ranges(const Vec3& c, double reach, double ball, std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) const;

  // The particles in bucket order, and what the queries' callers test them with.
  const std::vector<Index>& order() const { return order_; }
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  const std::vector<double>& z() const { return z_; }
  // G_J's distinct entries 00, 11, 22, 01, 02, 12.
  // Stored in float (the grid is kept beside the operators while they are built): a
  // caller's test widens its limit by test_slack(), which covers that rounding.
  const std::array<std::vector<float>, 6>& g() const { return g_; }
  const std::vector<float>& inverse_min_axis() const { return inv_min_axis_; }
  double test_slack() const { return test_slack_; }

  // The largest half-widths sqrt((G_J^-1)_ii) over the neighbourhood of c's coarse cell
  // (zero where no particle lies near).
  const std::array<double, 3>& spans_near(const Vec3& c) const;

 private:
  int bucket_index(int axis, double coordinate) const;
  std::size_t coarse_of_bucket(int bx, int by, int bz) const;

  Vec3 origin_ = Vec3::Zero();
  double bucket_ = 1.0;  // s
  int per_coarse_ = 1;   // C / s
  double max_reach_ = 0.0;
  std::array<int, 3> dims_{1, 1, 1};         // buckets along each axis
  std::array<int, 3> coarse_dims_{1, 1, 1};  // coarse cells along each axis
  std::vector<std::uint32_t> start_;         // bucket b holds order_[start_[b] .. start_[b+1])
  std::vector<Index> order_;
  std::vector<double> x_, y_, z_;
  std::vector<float> inv_min_axis_;
  std::array<std::vector<float>, 6> g_;
  double test_slack_ = 0.0;
  std::vector<std::array<double, 3>> spans_;  // per coarse cell
};

}  // namespace rkpm::rk
