// The particles whose ellipsoidal supports can reach points near a centre, found through
// one bucket grid (rk/ellipsoid_grid.hpp) per orientation of the supports, each in a
// frame turned to its supports' long axis.
//
// Why: a bucket grid's query visits the box of its supports' axis-aligned spans. On a
// thin wall refined in its plane the supports are needles across the wall (the RBC shell
// at 1e6 particles: about 0.25 um long, 0.09 um wide), tilted up to about 40 degrees from
// the coordinate axes, and a needle's axis-aligned spans are nearly its length on every
// axis: the grid visits about 1,100 particles per query of which about 200 reach, and the
// finer the wall the more (docs/verification/performance.md, "The set-up"). In a frame
// whose first axis follows the needles the spans across it are their width, so a grid
// per orientation visits little more than what reaches.
//
// How (the constants are in rk/oriented_grids.cpp): the particles are sorted into regions, cubes of kRegionSpans longest semi-axes,
// and within a region by the direction of their long axis (the eigenvector of G's
// smallest eigenvalue), without its sign: one of kBinsPerFace^2 cells on each of three
// faces of a cube of directions. Each non-empty (region, direction) pair is a class with
// its own grid, in the frame whose first axis is its members' mean long axis, over its
// members' positions and metrics turned into that frame. The regions keep each grid
// compact (a class spread over the whole wall would get buckets as coarse as its box is
// sparse; measured: more visits than the single grid). A query turns the centre into the
// frame of each class in the 27 regions around it whose members lie near enough, skips
// the class if the box of its supports in that frame is out of reach, and asks its grid
// for the box of the query's points in that frame (a query cell as deep as the wall's
// layer spacing is flat across the needles: its radius would widen every row of the
// query by the cell's depth). Supports that are nearly balls (median longest over shortest semi-axis
// below kAnisotropy) have no long axis worth following: one class in the coordinate
// frame, the single grid as before.
#pragma once

#include "rkpm/rk/ellipsoid_grid.hpp"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace rkpm::rk {

class OrientedGrids {
 public:
  OrientedGrids() = default;
  // As EllipsoidGrid's constructor: metric[J] = G_J, radius[J] its longest semi-axis,
  // min_axis[J] its shortest.
  OrientedGrids(const std::vector<Vec3>& X, const std::vector<SymmetricEntries>& metric,
                const std::vector<double>& radius, const std::vector<double>& min_axis);

  bool empty() const { return classes_.empty(); }
  std::size_t classes() const { return classes_.size(); }
  // Whether a query with this reach stays within one coarse neighbourhood of every grid.
  bool covers(double reach) const { return reach <= max_reach_; }

  // Appends to `kept` the particles (ids into X) whose support may reach a point within
  // `reach` of c and that lie within `ball` of c (an upper bound of a_J + reach), by the
  // test q_J(c) < (1 + reach / b_J) * slack with b_J the shortest semi-axis, widened by
  // the float storage's rounding: a superset of those that reach, in no particular order.
  // Given the `count` points at `points` (all within `reach` of c), the superset of those
  // that reach one of them, by the tighter of that test and
  // q_J(c) < (1 + sqrt(sum_ij |G_J,ij| e_i e_j)) * slack, e_i the points' largest offset
  // from c along axis i of the class's frame: q_J is a norm, so q_J(p) <= q_J(c) + |p - c|_G,
  // and |v|_G^2 <= sum_ij |G_ij| |v_i| |v_j|. Returns how many particles it tested.
  // Requires covers(reach).
  std::size_t candidates(const Vec3& c, double reach, double ball, double slack, std::vector<Index>& kept,
                         std::vector<std::pair<std::uint32_t, std::uint32_t>>& ranges, const Vec3* points = nullptr,
                         std::size_t count = 0) const;

 private:
  struct OrientationClass {
    Mat3 to_frame = Mat3::Identity();  // rows: the frame's axes
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // the members' box (coordinate frame), grown by their longest semi-axis
    Vec3 frame_lo = Vec3::Zero(), frame_hi = Vec3::Zero();  // the box of the members' supports in the class's frame
    std::vector<Index> ids;     // the members, in the grid's bucket order
    std::vector<Vec3> X;        // their positions in the frame, in the grid's bucket order
    EllipsoidGrid grid;
  };
  // The region holding a point (clamped to the regions' box), per axis.
  std::array<int, 3> region_of(const Vec3& x) const;

  std::vector<OrientationClass> classes_;  // by region, then by direction cell
  double max_reach_ = 0.0;
  // Regions (empty when one class holds every particle): the classes of region r are
  // classes_[region_first_[r] .. region_first_[r + 1]).
  Vec3 region_origin_ = Vec3::Zero();
  double region_side_ = 0.0;
  std::array<int, 3> region_dims_{0, 0, 0};
  std::vector<std::uint32_t> region_first_;
};

}  // namespace rkpm::rk
