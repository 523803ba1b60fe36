// Reproducing-kernel shape functions (Liu, Jun & Zhang 1995; Chen et al. 1996).
//
//   Psi_I(x) = H(0)^T M(x)^-1 H((X_I - x)/d) phi_I(x),
//   M(x)     = sum_J H((X_J - x)/d) H((X_J - x)/d)^T phi_J(x),
// with H the monomial basis (linear: 1, xi; quadratic: also xi_i xi_j), phi_I the
// kernel of particle I, and d a length that only scales the basis so M is well
// conditioned. The kernel's support is a ball of radius a_I, or an ellipsoid
// q_I(x)^2 = (x - X_I)^T G_I (x - X_I) < 1 shaped like the particle's own mesh edges
// (SupportShape::Ellipsoid): in a thin wall the support then reaches as many spacings
// through the thickness as along it, instead of being set by the longest edge in every
// direction (which makes a refined shell's rows grow with its in-plane refinement). The correction makes the functions
// reproduce every polynomial in H exactly: sum Psi_I = 1, sum Psi_I X_I = x, and
// the same for gradients, to round-off.
//
// A point whose moment matrix is singular or badly conditioned (too few particles
// in reach, or all of them on a plane: a support smaller than the spacing, a shell
// thinner than the support can see) is reported, never silently turned into NaN.
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/rk/kernel.hpp"
#include "rkpm/rk/neighbor_search.hpp"
#include "rkpm/rk/oriented_grids.hpp"
#include "rkpm/rk/support_bound.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rkpm::particles {
struct Cloud;
}

namespace rkpm::rk {

enum class Basis { Linear, Quadratic };
enum class SupportShape { Sphere, Ellipsoid };

struct RKSettings {
  KernelType kernel = KernelType::CubicBSpline;
  double support = 2.0;           // support radius / local particle spacing
  SupportShape shape = SupportShape::Sphere;
  Basis basis = Basis::Linear;
  double max_condition = 1e10;    // reject moment matrices worse conditioned than this
};

// Raised when a moment matrix cannot be inverted reliably.
struct ApproximationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The particles whose supports may cover points near one centre (RKApproximation::
// candidates), sorted by id, with their positions and support metrics gathered side by
// side: an evaluation then tests them all with straight-line arithmetic over
// contiguous arrays (which the compiler vectorizes) instead of chasing each id.
struct CandidateSet {
  std::vector<Index> id;
  std::vector<double> x, y, z;  // X_I
  // G_I's distinct entries 00, 11, 22, 01, 02, 12 (a ball: 1/a_I^2 on the diagonal).
  std::array<std::vector<double>, 6> g;
  std::vector<std::pair<Index, double>> found;  // the tree query's buffer
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;  // the grid query's buffer
  std::vector<Index> sort_buffer;                               // the sort's other half
  std::size_t size() const { return id.size(); }
};

// Shape-function values (and optionally gradients) at one evaluation point.
struct ShapeValues {
  std::vector<Index> ids;                          // particles whose support covers the point, sorted
  std::vector<double> psi;
  std::vector<Vec3> grad;                          // filled only when gradients are requested
  CandidateSet near;                               // evaluate()'s candidates
  std::vector<double> q2;                          // scratch: q_I^2 of each candidate
  std::vector<Vec3> offsets;                       // scratch: (X_I - x) / d of each id
  double condition = 0.0;                          // condition number of M (1-norm)
  int n_neighbors = 0;
};

// Local particle spacing h_I: the longest mesh edge at particle I. Robust for the
// anisotropic cells of thin shells, where a volume-based spacing underestimates the
// in-plane distance and the support would miss neighbours.
std::vector<double> local_spacing(const particles::Cloud& cloud);

// Ellipsoidal supports that follow the local spacing in each direction. With C_I the
// covariance sum_e e e^T of particle I's mesh edges e, the metric is
//   G_I = C_I^-1 / (support^2 s_I),   s_I = max_e e^T C_I^-1 e,
// the smallest ellipsoid of the shape of C_I that contains every edge, scaled by the
// support factor. C_I is invariant under rotation and sign of the edges, so on a
// regular lattice (any orientation) the ellipsoid is the ball of radius support x edge,
// as SupportShape::Sphere gives; on a wall of spacing h_t across and h_p along it, the
// semi-axes are support x h_t and support x h_p.
struct SupportEllipsoids {
  std::vector<Mat3> metric;    // G_I [1/m^2]
  std::vector<double> radius;    // largest semi-axis [m]: the ball that contains the ellipsoid
  std::vector<double> min_axis;  // smallest semi-axis [m]
};
SupportEllipsoids ellipsoidal_supports(const particles::Cloud& cloud, double support);

class RKApproximation {
 public:
  // support_radius[I] = a_I. Keeps references to `X`; both must outlive this object.
  RKApproximation(const std::vector<Vec3>& X, std::vector<double> support_radius, RKSettings settings);
  // Supports from the cloud's mesh: a_I = settings.support * local_spacing(cloud)[I], or
  // the ellipsoids of ellipsoidal_supports (settings.shape).
  RKApproximation(const particles::Cloud& cloud, RKSettings settings);

  // Evaluates Psi (and grad Psi if with_gradient) at x. Returns false when the moment
  // matrix is singular or its condition exceeds settings.max_condition; out.condition
  // and out.n_neighbors then describe why. Thread-safe; reuses out's storage.
  bool evaluate(const Vec3& x, ShapeValues& out, bool with_gradient) const;

  // Same, but throws ApproximationError with a message naming `what` (e.g. "particle 12").
  void evaluate_or_throw(const Vec3& x, ShapeValues& out, bool with_gradient, const std::string& what) const;

  // For many evaluation points near one centre (the facets of one smoothing cell): the
  // particles that can reach any point within `reach` of `centre`, sorted by id, found
  // with one tree query; then `evaluate_among` evaluates at such a point from that set
  // alone, with the same result as `evaluate` (same neighbours, same order).
  void candidates(const Vec3& centre, double reach, CandidateSet& out) const;
  // The same for the `count` points at `points` alone (reach: their largest distance from
  // the centre). On ellipsoidal supports the test then also bounds how far each support
  // must reach by the points' extent along each axis of its own shape (OrientedGrids),
  // which keeps far fewer of a cell elongated across a thin wall than a ball of `reach`.
  void candidates(const Vec3& centre, const Vec3* points, std::size_t count, CandidateSet& out) const;
  bool evaluate_among(const Vec3& x, const CandidateSet& candidates, ShapeValues& out, bool with_gradient) const;

  const std::vector<Vec3>& points() const { return X_; }
  // a_I: the support's radius, or for an ellipsoid its largest semi-axis.
  const std::vector<double>& support_radius() const { return a_; }
  // Normalised distance q = |x - X_I| / a_I or sqrt(r^T G_I r), r = x - X_I (1 outside
  // a ball), and the kernel's gradient dw/dq dq/dx there (zero at q = 0).
  double normalized_distance(Index id, const Vec3& x) const;
  Vec3 kernel_gradient(Index id, const Vec3& x, double q, double dw_dq) const;
  const RKSettings& settings() const { return settings_; }
  int basis_size() const { return settings_.basis == Basis::Linear ? 4 : 10; }

 private:
  // q^2, without the square root the kernel's support test does not need.
  double squared_normalized_distance(Index id, const Vec3& x) const;
  // G_I's distinct entries in CandidateSet::g's order.
  std::array<double, 6> metric_entries(Index id) const;
  template <int N>
  bool evaluate_basis(const Vec3& x, const CandidateSet& candidates, ShapeValues& out, bool with_gradient) const;

  RKApproximation(const std::vector<Vec3>& X, SupportEllipsoids supports, RKSettings settings);
  void collect_candidates(const Vec3& centre, double reach, const Vec3* points, std::size_t count,
                          CandidateSet& out) const;
  static SupportEllipsoids supports_of(const particles::Cloud& cloud, const RKSettings& settings);

  const std::vector<Vec3>& X_;
  std::vector<double> a_;
  std::vector<SymmetricEntries> metric_;  // G_I's distinct entries; empty for spherical supports
  std::vector<double> min_axis_;  // the ellipsoids' smallest semi-axes
  double a_max_ = 0.0;
  RKSettings settings_;
  // The kd-tree: built at once for balls, and for ellipsoids only when a query's reach is
  // more than the grid covers (its memory is then not spent on every body).
  const NeighborSearch& tree() const;
  mutable std::once_flag tree_built_;
  mutable std::unique_ptr<NeighborSearch> search_;
  SupportBound bound_;  // the largest a_I near a point, for the query radius
  OrientedGrids grid_;  // ellipsoidal supports: the query that follows their shape
};

}  // namespace rkpm::rk
