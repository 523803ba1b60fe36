#include "rkpm/rk/oriented_grids.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace rkpm::rk {

namespace {

constexpr int kBinsPerFace = 4;         // direction cells per face edge: at most about 14 degrees across
constexpr double kAnisotropy = 3.0;     // median longest / shortest semi-axis from which classes pay
constexpr double kRegionSpans = 4.0;    // a region's side, in longest semi-axes
constexpr double kBucketFraction = 1.0; // a class grid's bucket, of its median shortest semi-axis

Mat3 matrix_of(const SymmetricEntries& g) {  // 00, 11, 22, 01, 02, 12
  Mat3 G;
  G << g[0], g[3], g[4], g[3], g[1], g[5], g[4], g[5], g[2];
  return G;
}

// The long axis's direction without its sign, as the cell of a cube of directions: the
// dominant component's axis i (made positive), and the two others over it, each in
// kBinsPerFace bins of [-1, 1].
int direction_cell(Vec3 u) {
  constexpr int bins = kBinsPerFace;
  Eigen::Index i = 0;
  u.cwiseAbs().maxCoeff(&i);
  if (u(i) < 0.0) u = -u;
  const auto bin = [](double t) { return std::clamp(static_cast<int>(std::floor((t + 1.0) * 0.5 * bins)), 0, bins - 1); };
  const auto j = (i + 1) % 3, k = (i + 2) % 3;
  return (static_cast<int>(i) * bins + bin(u(j) / u(i))) * bins + bin(u(k) / u(i));
}

// Rows: w, then two unit vectors across it (a rotation into a frame whose first axis is
// w). The grid's rows of buckets run along its first axis: along the supports, a query's
// box is a few rows of many buckets instead of many rows of a few.
Mat3 frame_along(const Vec3& w) {
  Eigen::Index smallest = 0;
  w.cwiseAbs().minCoeff(&smallest);
  const Vec3 e1 = w.cross(Vec3::Unit(smallest)).normalized();
  const Vec3 e2 = w.cross(e1);
  Mat3 R;
  R.row(0) = w.transpose();
  R.row(1) = e1.transpose();
  R.row(2) = e2.transpose();
  return R;
}

double median_of(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

OrientedGrids::OrientedGrids(const std::vector<Vec3>& X, const std::vector<SymmetricEntries>& metric,
                             const std::vector<double>& radius, const std::vector<double>& min_axis) {
  const std::size_t n = X.size();
  if (n == 0) return;
  std::vector<double> aspect(n);
  for (std::size_t i = 0; i < n; ++i) aspect[i] = radius[i] / min_axis[i];
  const bool oriented = median_of(aspect) >= kAnisotropy;

  // Each particle's class key (region, then the direction cell of its long axis) and
  // that axis, made to point into the cell's face so that a class's axes can be averaged.
  constexpr int kDirectionCells = 3 * kBinsPerFace * kBinsPerFace;
  std::vector<std::int64_t> key(n, 0);
  std::vector<Vec3> axis(n, Vec3::UnitZ());
  if (oriented) {
    const auto [lo, hi, a_max] = supports_box(X, radius);
    region_origin_ = lo;
    region_side_ = kRegionSpans * a_max;
    for (int d = 0; d < 3; ++d) region_dims_[d] = static_cast<int>(std::floor((hi(d) - lo(d)) / region_side_)) + 1;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      Eigen::SelfAdjointEigenSolver<Mat3> eigen;
      eigen.computeDirect(matrix_of(metric[i]));
      Vec3 u = eigen.eigenvectors().col(0);  // smallest eigenvalue of G: the longest semi-axis
      Eigen::Index d = 0;
      u.cwiseAbs().maxCoeff(&d);
      if (u(d) < 0.0) u = -u;
      axis[i] = u;
      const auto r = region_of(X[i]);
      const std::int64_t region = (static_cast<std::int64_t>(r[2]) * region_dims_[1] + r[1]) * region_dims_[0] + r[0];
      key[i] = region * kDirectionCells + direction_cell(u);
    }
  }
  // The particles by key, ids ascending within a class.
  std::vector<Index> by_key(n);
  for (std::size_t i = 0; i < n; ++i) by_key[i] = static_cast<Index>(i);
  std::stable_sort(by_key.begin(), by_key.end(),
                   [&](Index p, Index q) { return key[static_cast<std::size_t>(p)] < key[static_cast<std::size_t>(q)]; });

  max_reach_ = HUGE_VAL;
  if (oriented) {
    const std::size_t regions = static_cast<std::size_t>(region_dims_[0]) * region_dims_[1] * region_dims_[2];
    region_first_.assign(regions + 1, 0);
  }
  for (std::size_t first = 0; first < n;) {
    const std::int64_t k = key[static_cast<std::size_t>(by_key[first])];
    std::size_t last = first;
    while (last < n && key[static_cast<std::size_t>(by_key[last])] == k) ++last;
    const std::vector<Index> ids(by_key.begin() + static_cast<std::ptrdiff_t>(first),
                                 by_key.begin() + static_cast<std::ptrdiff_t>(last));
    first = last;
    OrientationClass cl;
    if (oriented) {
      Vec3 sum = Vec3::Zero();
      for (Index id : ids) sum += axis[static_cast<std::size_t>(id)];
      cl.to_frame = frame_along(sum.normalized());
      ++region_first_[static_cast<std::size_t>(k / kDirectionCells) + 1];
    }
    const std::size_t m = ids.size();
    std::vector<Vec3> Xf(m);
    std::vector<SymmetricEntries> Gf(m);
    std::vector<double> a(m), b(m);
    cl.lo = cl.hi = X[static_cast<std::size_t>(ids.front())];
    double a_max = 0.0;
    cl.frame_lo = Vec3::Constant(HUGE_VAL);
    cl.frame_hi = -cl.frame_lo;
    for (std::size_t j = 0; j < m; ++j) {
      const auto i = static_cast<std::size_t>(ids[j]);
      // In the coordinate frame the copies are exact: a single class tests as one grid would.
      Xf[j] = oriented ? Vec3(cl.to_frame * X[i]) : X[i];
      Gf[j] = oriented ? symmetric_entries(cl.to_frame * matrix_of(metric[i]) * cl.to_frame.transpose()) : metric[i];
      // The support spans sqrt((G^-1)_aa) along axis a of the frame (at most its longest semi-axis).
      const Vec3 span = matrix_of(Gf[j]).inverse().diagonal().cwiseSqrt().cwiseMin(radius[i]) * (1.0 + 1e-9);
      cl.frame_lo = cl.frame_lo.cwiseMin(Xf[j] - span);
      cl.frame_hi = cl.frame_hi.cwiseMax(Xf[j] + span);
      a[j] = radius[i];
      b[j] = min_axis[i];
      cl.lo = cl.lo.cwiseMin(X[i]);
      cl.hi = cl.hi.cwiseMax(X[i]);
      a_max = std::max(a_max, radius[i]);
    }
    // A particle that reaches a point within `reach` of c lies within a_J + reach of it.
    cl.lo -= Vec3::Constant(a_max * (1.0 + 1e-9));
    cl.hi += Vec3::Constant(a_max * (1.0 + 1e-9));
    cl.grid = EllipsoidGrid(Xf, Gf, a, b, oriented ? kBucketFraction : 0.5);
    max_reach_ = std::min(max_reach_, cl.grid.max_reach());
    // The members and their positions in the grid's bucket order, read as it streams.
    const auto& order = cl.grid.order();
    cl.ids.resize(m);
    cl.X.resize(m);
    for (std::size_t j = 0; j < m; ++j) {
      const auto local = static_cast<std::size_t>(order[j]);
      cl.ids[j] = ids[local];
      cl.X[j] = Xf[local];
    }
    classes_.push_back(std::move(cl));
  }
  if (oriented) {
    for (std::size_t r = 0; r + 1 < region_first_.size(); ++r) region_first_[r + 1] += region_first_[r];
    // A particle reaching c lies within a_max + reach of it: in one of the 27 regions around c.
    max_reach_ = std::min(max_reach_, region_side_ * (1.0 - 1.0 / kRegionSpans) * (1.0 - 1e-9));
  }
}

std::array<int, 3> OrientedGrids::region_of(const Vec3& x) const {
  std::array<int, 3> r{};
  for (int d = 0; d < 3; ++d) {
    const double t = std::floor((x(d) - region_origin_(d)) / region_side_);
    r[d] = static_cast<int>(std::clamp(t, 0.0, static_cast<double>(region_dims_[d] - 1)));
  }
  return r;
}

std::size_t OrientedGrids::candidates(const Vec3& c, double reach, double ball, double slack, std::vector<Index>& kept,
                                      std::vector<std::pair<std::uint32_t, std::uint32_t>>& ranges, const Vec3* points,
                                      std::size_t count) const {
  std::size_t tested = 0;
  const bool oriented = !region_first_.empty();
  const auto query = [&](const OrientationClass& cl) {
    if ((c.array() < cl.lo.array() - reach).any() || (c.array() > cl.hi.array() + reach).any()) return;
    const Vec3 cf = oriented ? Vec3(cl.to_frame * c) : c;
    if ((cf.array() < cl.frame_lo.array() - reach).any() || (cf.array() > cl.frame_hi.array() + reach).any()) return;
    // The points' largest offsets from c along the frame's axes (each at most `reach`).
    Vec3 e = Vec3::Constant(reach);
    if (count > 0) {
      e.setZero();
      for (std::size_t p = 0; p < count; ++p)
        e = e.cwiseMax((oriented ? Vec3(cl.to_frame * (points[p] - c)) : Vec3(points[p] - c)).cwiseAbs());
    }
    cl.grid.ranges(cf, e, ball, ranges);
    std::size_t visited = 0;
    for (const auto& range : ranges) visited += range.second - range.first;
    // Written in place and counted without a branch: about half the visited particles
    // pass, which a branch would mispredict; the arrays are local pointers, so the
    // stores to the list do not make the compiler reload them.
    const std::size_t start = kept.size();
    kept.resize(start + visited);
    Index* out = kept.data() + start;
    std::size_t m = 0;
    const auto& g = cl.grid.g();
    const float *g0 = g[0].data(), *g1 = g[1].data(), *g2 = g[2].data();
    const float *g3 = g[3].data(), *g4 = g[4].data(), *g5 = g[5].data();
    const float* inv_b = cl.grid.inverse_min_axis().data();
    const Index* ids = cl.ids.data();
    const Vec3* P = cl.X.data();
    const double cx = cf.x(), cy = cf.y(), cz = cf.z();
    const double widened = slack * (1.0 + cl.grid.test_slack());
    // The test of each listed particle; reach_in_q(k): how far past its support, in its
    // own norm, particle k must reach.
    const auto sweep = [&](const auto& reach_in_q) {
      for (const auto& [first, last] : ranges)
        for (std::uint32_t k = first; k < last; ++k) {
          const double q2 =
              quadratic_form(g0[k], g1[k], g2[k], g3[k], g4[k], g5[k], cx - P[k].x(), cy - P[k].y(), cz - P[k].z());
          const double limit = (1.0 + reach_in_q(k)) * widened;
          out[m] = ids[k];
          m += q2 < limit * limit ? 1 : 0;
        }
    };
    if (count == 0) {
      sweep([&](std::uint32_t k) { return reach * inv_b[k]; });
    } else {
      // The products of the points' largest offsets along the frame's axes.
      const double e00 = e(0) * e(0), e11 = e(1) * e(1), e22 = e(2) * e(2);
      const double e01 = e(0) * e(1), e02 = e(0) * e(2), e12 = e(1) * e(2);
      sweep([&](std::uint32_t k) {
        const double spread = std::sqrt(g0[k] * e00 + g1[k] * e11 + g2[k] * e22 +
                                        2.0 * (std::abs(g3[k]) * e01 + std::abs(g4[k]) * e02 + std::abs(g5[k]) * e12));
        return std::min(reach * inv_b[k], spread);
      });
    }
    kept.resize(start + m);
    tested += visited;
  };
  if (!oriented) {
    for (const auto& cl : classes_) query(cl);
    return tested;
  }
  // A point outside the regions' box takes the nearest region: every particle within a
  // region's side of it lies in that region's neighbourhood too.
  const auto r = region_of(c);
  for (int z = std::max(0, r[2] - 1); z <= std::min(region_dims_[2] - 1, r[2] + 1); ++z)
    for (int y = std::max(0, r[1] - 1); y <= std::min(region_dims_[1] - 1, r[1] + 1); ++y)
      for (int x = std::max(0, r[0] - 1); x <= std::min(region_dims_[0] - 1, r[0] + 1); ++x) {
        const std::size_t region = (static_cast<std::size_t>(z) * region_dims_[1] + y) * region_dims_[0] + x;
        for (std::uint32_t k = region_first_[region]; k < region_first_[region + 1]; ++k) query(classes_[k]);
      }
  return tested;
}

}  // namespace rkpm::rk
