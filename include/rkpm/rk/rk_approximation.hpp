// Reproducing-kernel shape functions (Liu, Jun & Zhang 1995; Chen et al. 1996).
//
//   Psi_I(x) = H(0)^T M(x)^-1 H((X_I - x)/d) phi_I(x),
//   M(x)     = sum_J H((X_J - x)/d) H((X_J - x)/d)^T phi_J(x),
// with H the monomial basis (linear: 1, xi; quadratic: also xi_i xi_j), phi_I the
// kernel of particle I with spherical support radius a_I, and d a length that only
// scales the basis so M is well conditioned. The correction makes the functions
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

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rkpm::particles {
struct Cloud;
}

namespace rkpm::rk {

enum class Basis { Linear, Quadratic };

struct RKSettings {
  KernelType kernel = KernelType::CubicBSpline;
  double support = 2.0;           // support radius / local particle spacing
  Basis basis = Basis::Linear;
  double max_condition = 1e10;    // reject moment matrices worse conditioned than this
};

// Raised when a moment matrix cannot be inverted reliably.
struct ApproximationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Shape-function values (and optionally gradients) at one evaluation point.
struct ShapeValues {
  std::vector<Index> ids;                          // particles whose support covers the point, sorted
  std::vector<double> psi;
  std::vector<Vec3> grad;                          // filled only when gradients are requested
  std::vector<std::pair<Index, double>> scratch;   // neighbour query buffer
  double condition = 0.0;                          // estimated condition number of M (1-norm)
  int n_neighbors = 0;
};

// Local particle spacing h_I: the longest mesh edge at particle I. Robust for the
// anisotropic cells of thin shells, where a volume-based spacing underestimates the
// in-plane distance and the support would miss neighbours.
std::vector<double> local_spacing(const particles::Cloud& cloud);

class RKApproximation {
 public:
  // support_radius[I] = a_I. Keeps references to `X`; both must outlive this object.
  RKApproximation(const std::vector<Vec3>& X, std::vector<double> support_radius, RKSettings settings);
  // Convenience: a_I = settings.support * local_spacing(cloud)[I].
  RKApproximation(const particles::Cloud& cloud, RKSettings settings);

  // Evaluates Psi (and grad Psi if with_gradient) at x. Returns false when the moment
  // matrix is singular or its condition exceeds settings.max_condition; out.condition
  // and out.n_neighbors then describe why. Thread-safe; reuses out's storage.
  bool evaluate(const Vec3& x, ShapeValues& out, bool with_gradient) const;

  // Same, but throws ApproximationError with a message naming `what` (e.g. "particle 12").
  void evaluate_or_throw(const Vec3& x, ShapeValues& out, bool with_gradient, const std::string& what) const;

  // For many evaluation points near one centre (the facets of one smoothing cell): the
  // particles that can reach any point within `reach` of `centre`, sorted by id, found
  // with one tree query; then `evaluate_among` evaluates at such a point from that list
  // alone, with the same result as `evaluate` (same neighbours, same order).
  void candidates(const Vec3& centre, double reach, std::vector<std::pair<Index, double>>& out) const;
  bool evaluate_among(const Vec3& x, const std::vector<std::pair<Index, double>>& candidates, ShapeValues& out,
                      bool with_gradient) const;

  const std::vector<Vec3>& points() const { return X_; }
  const std::vector<double>& support_radius() const { return a_; }
  const RKSettings& settings() const { return settings_; }
  int basis_size() const { return settings_.basis == Basis::Linear ? 4 : 10; }

 private:
  template <int N>
  bool evaluate_basis(const Vec3& x, const std::vector<std::pair<Index, double>>& candidates, ShapeValues& out,
                      bool with_gradient) const;

  const std::vector<Vec3>& X_;
  std::vector<double> a_;
  double a_max_ = 0.0;
  RKSettings settings_;
  NeighborSearch search_;
};

}  // namespace rkpm::rk
