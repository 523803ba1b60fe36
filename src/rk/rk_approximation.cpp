#include "rkpm/rk/rk_approximation.hpp"

#include "rkpm/particles/cloud.hpp"
#include "rkpm/rk/element_edges.hpp"

#include <Eigen/Cholesky>  // LLT
#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rkpm::rk {

std::vector<double> local_spacing(const particles::Cloud& cloud) {
  std::vector<double> h(cloud.size(), 0.0);
  const auto& mesh = cloud.mesh;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    const std::int32_t* nodes = mesh.element_nodes(e);
    for (const auto& edge : element_edges(mesh.type[static_cast<std::size_t>(e)])) {
      const Index a = nodes[edge[0]], b = nodes[edge[1]];
      const double len = (cloud.X[static_cast<std::size_t>(a)] - cloud.X[static_cast<std::size_t>(b)]).norm();
      h[static_cast<std::size_t>(a)] = std::max(h[static_cast<std::size_t>(a)], len);
      h[static_cast<std::size_t>(b)] = std::max(h[static_cast<std::size_t>(b)], len);
    }
  }
  return h;
}

SupportEllipsoids ellipsoidal_supports(const particles::Cloud& cloud, double support) {
  const std::size_t n = cloud.size();
  const auto& mesh = cloud.mesh;
  // Each edge is seen once per element that has it; the repeats weigh C_I but do not
  // change the max over edges, and a lattice's repeats are symmetric.
  const auto for_each_edge = [&](const auto& visit) {
    for (int e = 0; e < mesh.n_elements(); ++e) {
      const std::int32_t* nodes = mesh.element_nodes(e);
      for (const auto& edge : element_edges(mesh.type[static_cast<std::size_t>(e)])) {
        const Index a = nodes[edge[0]], b = nodes[edge[1]];
        visit(a, b, Vec3(cloud.X[static_cast<std::size_t>(b)] - cloud.X[static_cast<std::size_t>(a)]));
      }
    }
  };
  std::vector<Mat3> covariance(n, Mat3::Zero());
  for_each_edge([&](Index a, Index b, const Vec3& e) {
    const Mat3 ee = e * e.transpose();
    covariance[static_cast<std::size_t>(a)] += ee;
    covariance[static_cast<std::size_t>(b)] += ee;
  });
  SupportEllipsoids out;
  out.metric.resize(n);
  out.radius.assign(n, 0.0);
  out.min_axis.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::LDLT<Mat3> ldlt(covariance[i]);
    if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || !(ldlt.rcond() > 1e-12))
      throw ApproximationError(fmt::format(
          "cloud '{}', particle {}: its mesh edges do not span three dimensions, so no ellipsoidal support "
          "can be shaped from them (use support_shape = \"sphere\")",
          cloud.name, i));
    out.metric[i] = ldlt.solve(Mat3::Identity());
  }
  std::vector<double> reach(n, 0.0);  // s_I = max_e e^T C_I^-1 e
  for_each_edge([&](Index a, Index b, const Vec3& e) {
    for (const Index p : {a, b}) {
      const auto i = static_cast<std::size_t>(p);
      reach[i] = std::max(reach[i], e.dot(out.metric[i] * e));
    }
  });
  for (std::size_t i = 0; i < n; ++i) {
    out.metric[i] /= support * support * reach[i];
    // Semi-axes 1 / sqrt(lambda(G)), eigenvalues ascending.
    const Vec3 lambda = Eigen::SelfAdjointEigenSolver<Mat3>(out.metric[i], Eigen::EigenvaluesOnly).eigenvalues();
    out.radius[i] = 1.0 / std::sqrt(lambda(0));
    out.min_axis[i] = 1.0 / std::sqrt(lambda(2));
  }
  return out;
}

namespace {
std::vector<double> scaled(std::vector<double> h, double factor) {
  for (double& v : h) v *= factor;
  return h;
}

// Monomial basis H(xi) and its derivatives dH/dxi_k, for N = 4 (linear) or 10 (quadratic).
template <int N>
struct MonomialBasis {
  using Vec = Eigen::Matrix<double, N, 1>;
  static Vec value(const Vec3& xi) {
    Vec h;
    h(0) = 1.0;
    h(1) = xi.x();
    h(2) = xi.y();
    h(3) = xi.z();
    if constexpr (N == 10) {
      h(4) = xi.x() * xi.x();
      h(5) = xi.y() * xi.y();
      h(6) = xi.z() * xi.z();
      h(7) = xi.x() * xi.y();
      h(8) = xi.y() * xi.z();
      h(9) = xi.z() * xi.x();
    }
    return h;
  }
  static Vec derivative(const Vec3& xi, int k) {
    Vec d = Vec::Zero();
    d(1 + k) = 1.0;
    if constexpr (N == 10) {
      d(4 + k) = 2.0 * xi(k);
      if (k == 0) { d(7) = xi.y(); d(9) = xi.z(); }
      if (k == 1) { d(7) = xi.x(); d(8) = xi.z(); }
      if (k == 2) { d(8) = xi.y(); d(9) = xi.x(); }
    }
    return d;
  }
};
}  // namespace

RKApproximation::RKApproximation(const std::vector<Vec3>& X, std::vector<double> support_radius, RKSettings settings)
    : X_(X), a_(std::move(support_radius)), settings_(settings) {
  if (a_.size() != X_.size()) throw std::invalid_argument("RKApproximation: one support radius per particle required");
  for (std::size_t i = 0; i < a_.size(); ++i) {
    if (!(a_[i] > 0.0) || !std::isfinite(a_[i]))
      throw ApproximationError(fmt::format("particle {}: support radius {} is not a positive number", i, a_[i]));
    a_max_ = std::max(a_max_, a_[i]);
  }
  bound_ = SupportBound(X_, a_);
  if (settings_.shape == SupportShape::Sphere) tree();
}

const NeighborSearch& RKApproximation::tree() const {
  std::call_once(tree_built_, [this] { search_ = std::make_unique<NeighborSearch>(X_); });
  return *search_;
}

RKApproximation::RKApproximation(const particles::Cloud& cloud, RKSettings settings)
    : RKApproximation(cloud.X, supports_of(cloud, settings), settings) {}

RKApproximation::RKApproximation(const std::vector<Vec3>& X, SupportEllipsoids supports, RKSettings settings)
    : RKApproximation(X, std::move(supports.radius), settings) {
  metric_.resize(supports.metric.size());
  for (std::size_t i = 0; i < metric_.size(); ++i) metric_[i] = symmetric_entries(supports.metric[i]);
  supports.metric = {};
  min_axis_ = std::move(supports.min_axis);
  if (!metric_.empty()) grid_ = OrientedGrids(X_, metric_, a_, min_axis_);
}

SupportEllipsoids RKApproximation::supports_of(const particles::Cloud& cloud, const RKSettings& settings) {
  if (settings.shape == SupportShape::Ellipsoid) return ellipsoidal_supports(cloud, settings.support);
  return {{}, scaled(local_spacing(cloud), settings.support), {}};
}

namespace {
// Sorts a candidate list by id: least-significant-digit radix sort on the ids' offsets
// from the smallest, one byte per pass and only as many passes as the offsets need
// (two or three for a cell's neighbours). A comparison sort of a list this short
// mispredicts about every other branch, and it showed in a sphere's set-up
// (docs/verification/performance.md measures the set-up).
void sort_ids(std::vector<Index>& ids, std::vector<Index>& buffer) {
  const std::size_t n = ids.size();
  if (n < 2) return;
  const auto [lo, hi] = std::minmax_element(ids.begin(), ids.end());
  const Index base = *lo;
  const auto span = static_cast<std::uint32_t>(*hi - base);
  buffer.resize(n);
  Index* from = ids.data();
  Index* to = buffer.data();
  for (int shift = 0; shift < 32 && (span >> shift) != 0; shift += 8) {
    std::uint32_t count[257] = {};
    for (std::size_t k = 0; k < n; ++k) ++count[((static_cast<std::uint32_t>(from[k] - base) >> shift) & 0xffu) + 1];
    for (int d = 0; d < 256; ++d) count[d + 1] += count[d];
    for (std::size_t k = 0; k < n; ++k) to[count[(static_cast<std::uint32_t>(from[k] - base) >> shift) & 0xffu]++] = from[k];
    std::swap(from, to);
  }
  if (from != ids.data()) std::copy(from, from + n, ids.data());
}
}  // namespace

std::array<double, 6> RKApproximation::metric_entries(Index id) const {
  const auto i = static_cast<std::size_t>(id);
  if (metric_.empty()) {
    const double g = 1.0 / (a_[i] * a_[i]);
    return {g, g, g, 0.0, 0.0, 0.0};
  }
  return metric_[i];
}

double RKApproximation::squared_normalized_distance(Index id, const Vec3& x) const {
  const Vec3 r = x - X_[static_cast<std::size_t>(id)];
  const auto g = metric_entries(id);
  return quadratic_form(g[0], g[1], g[2], g[3], g[4], g[5], r.x(), r.y(), r.z());
}

double RKApproximation::normalized_distance(Index id, const Vec3& x) const {
  const double q2 = squared_normalized_distance(id, x);
  if (metric_.empty() && q2 >= 1.0) return 1.0;
  return std::sqrt(q2);
}

Vec3 RKApproximation::kernel_gradient(Index id, const Vec3& x, double q, double dw_dq) const {
  const auto i = static_cast<std::size_t>(id);
  const Vec3 r = x - X_[i];
  if (q <= 0.0) return Vec3::Zero();
  // d q / d x = r / (a |r|) for a ball, G r / q for an ellipsoid.
  if (metric_.empty()) return dw_dq / (a_[i] * r.norm()) * r;
  const auto& g = metric_[i];  // 00, 11, 22, 01, 02, 12
  const Vec3 Gr(g[0] * r.x() + g[3] * r.y() + g[4] * r.z(), g[3] * r.x() + g[1] * r.y() + g[5] * r.z(),
                g[4] * r.x() + g[5] * r.y() + g[2] * r.z());
  return dw_dq / q * Gr;
}

bool RKApproximation::evaluate(const Vec3& x, ShapeValues& out, bool with_gradient) const {
  candidates(x, 0.0, out.near);
  return evaluate_among(x, out.near, out, with_gradient);
}

void RKApproximation::candidates(const Vec3& centre, double reach, CandidateSet& out) const {
  collect_candidates(centre, reach, nullptr, 0, out);
}

void RKApproximation::candidates(const Vec3& centre, const Vec3* points, std::size_t count, CandidateSet& out) const {
  double reach = 0.0;
  for (std::size_t p = 0; p < count; ++p) reach = std::max(reach, (points[p] - centre).norm());
  collect_candidates(centre, reach, points, count, out);
}

void RKApproximation::collect_candidates(const Vec3& centre, double reach, const Vec3* points, std::size_t count,
                                         CandidateSet& out) const {
  // A point within `reach` of the centre is reached only by particles within
  // a_I + reach of the centre, a_I at most the largest support near it; the relative
  // slack covers the rounding of that bound.
  const double ball = (bound_.near(centre, reach) + reach) * (1.0 + 1e-9);
  // Of those, keep the ones whose own support reaches that far: q_I is a norm, so
  // q_I(x) <= q_I(centre) + reach / b_I with b_I the support's smallest semi-axis (its
  // radius for a ball). What is dropped has phi_I = 0 at every such point, so the
  // evaluations give the same result, bit for bit, from a shorter list.
  const double slack = 1.0 + 1e-9;
  out.id.clear();
  if (!grid_.empty() && grid_.covers(reach)) {
    // Ellipsoids: the grids of their orientations (rk/oriented_grids.hpp), tested in the
    // order they store them, from contiguous arrays. A refined thin wall's ball holds
    // several times the particles its supports can reach, and the tree hands them out
    // one by one from wherever it keeps them; the grids visit little more than what
    // reaches (docs/verification/performance.md measures the set-up).
    grid_.candidates(centre, reach, ball, slack, out.id, out.ranges, points, count);
  } else {
    auto& found = out.found;
    tree().query_unordered(centre, ball, found);
    for (const auto& c : found) {
      const auto i = static_cast<std::size_t>(c.first);
      const double b = metric_.empty() ? a_[i] : min_axis_[i];
      const double limit = (1.0 + reach / b) * slack;  // q_I(centre) must be below this
      if (squared_normalized_distance(c.first, centre) < limit * limit) out.id.push_back(c.first);
    }
  }
  // Sorted by id (the ids alone: a quarter of the bytes of the query's pairs).
  sort_ids(out.id, out.sort_buffer);
  const std::size_t m = out.id.size();
  out.x.resize(m);
  out.y.resize(m);
  out.z.resize(m);
  for (auto& g : out.g) g.resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    const Index id = out.id[k];
    const Vec3& X = X_[static_cast<std::size_t>(id)];
    out.x[k] = X.x();
    out.y[k] = X.y();
    out.z[k] = X.z();
    const auto g = metric_entries(id);
    for (int e = 0; e < 6; ++e) out.g[e][k] = g[e];
  }
}

bool RKApproximation::evaluate_among(const Vec3& x, const CandidateSet& candidates, ShapeValues& out,
                                     bool with_gradient) const {
  return settings_.basis == Basis::Linear ? evaluate_basis<4>(x, candidates, out, with_gradient)
                                          : evaluate_basis<10>(x, candidates, out, with_gradient);
}

void RKApproximation::evaluate_or_throw(const Vec3& x, ShapeValues& out, bool with_gradient,
                                        const std::string& what) const {
  if (evaluate(x, out, with_gradient)) return;
  throw ApproximationError(fmt::format(
      "{}: the reproducing-kernel moment matrix at ({:.6g}, {:.6g}, {:.6g}) is {} "
      "({} particles in reach, {} needed for the {} basis; condition number {:.3g}, limit {:.3g}). "
      "Increase the support size or refine the cloud.",
      what, x.x(), x.y(), x.z(), out.condition > 0 && std::isfinite(out.condition) ? "badly conditioned" : "singular",
      out.n_neighbors, basis_size(), settings_.basis == Basis::Linear ? "linear" : "quadratic", out.condition,
      settings_.max_condition));
}

template <int N>
bool RKApproximation::evaluate_basis(const Vec3& x, const CandidateSet& candidates, ShapeValues& out,
                                     bool with_gradient) const {
  using Basis = MonomialBasis<N>;
  using VecN = Eigen::Matrix<double, N, 1>;
  using MatN = Eigen::Matrix<double, N, N>;

  out.ids.clear();
  out.psi.clear();
  out.grad.clear();
  out.offsets.clear();
  // Keep only the particles whose own support covers x; phi_I(x) > 0 for those.
  const double inv_scale = 1.0 / a_max_;
  MatN M = MatN::Zero();
  // The linear basis's ten distinct moments in registers: the Eigen matrix in memory
  // made each sum wait for the store of the one before.
  double mom[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  // Every candidate's q^2 first, in one pass of straight-line arithmetic over the
  // gathered arrays; then the few inside their supports.
  const std::size_t m = candidates.size();
  out.q2.resize(m);
  {
    const double px = x.x(), py = x.y(), pz = x.z();
    const double *cx = candidates.x.data(), *cy = candidates.y.data(), *cz = candidates.z.data();
    const double *g00 = candidates.g[0].data(), *g11 = candidates.g[1].data(), *g22 = candidates.g[2].data();
    const double *g01 = candidates.g[3].data(), *g02 = candidates.g[4].data(), *g12 = candidates.g[5].data();
    double* q2 = out.q2.data();
    for (std::size_t k = 0; k < m; ++k)
      q2[k] = quadratic_form(g00[k], g11[k], g22[k], g01[k], g02[k], g12[k], px - cx[k], py - cy[k], pz - cz[k]);
  }
  for (std::size_t k = 0; k < m; ++k) {
    const double q2 = out.q2[k];
    if (q2 >= 1.0) continue;
    const double w = evaluate_kernel(settings_.kernel, std::sqrt(q2)).w;
    if (w <= 0.0) continue;
    const Index id = candidates.id[k];
    const Vec3 xi = Vec3(candidates.x[k] - x.x(), candidates.y[k] - x.y(), candidates.z[k] - x.z()) * inv_scale;
    out.ids.push_back(id);
    out.psi.push_back(w);  // phi_I for now; corrected below
    out.offsets.push_back(xi);
    if constexpr (N == 4) {
      const double wx = w * xi.x(), wy = w * xi.y(), wz = w * xi.z();
      mom[0] += w;
      mom[1] += wx;
      mom[2] += wy;
      mom[3] += wz;
      mom[4] += wx * xi.x();
      mom[5] += wy * xi.x();
      mom[6] += wz * xi.x();
      mom[7] += wy * xi.y();
      mom[8] += wz * xi.y();
      mom[9] += wz * xi.z();
    } else {
      const VecN h = Basis::value(xi);
      const VecN wh = w * h;
      // The lower triangle only (what LDLT reads); mirrored below.
      for (int j = 0; j < N; ++j)
        for (int i = j; i < N; ++i) M(i, j) += wh(i) * h(j);
    }
  }
  if constexpr (N == 4) {
    M << mom[0], mom[1], mom[2], mom[3],  //
        mom[1], mom[4], mom[5], mom[6],   //
        mom[2], mom[5], mom[7], mom[8],   //
        mom[3], mom[6], mom[8], mom[9];
  } else {
    M.template triangularView<Eigen::StrictlyUpper>() = M.transpose();
  }
  out.n_neighbors = static_cast<int>(out.ids.size());
  out.condition = 0.0;
  if (out.n_neighbors < N) return false;

  // M is a sum of w_I H_I H_I^T with w_I > 0: positive definite unless the particles
  // in reach lie on a plane (or fewer), so a Cholesky factorisation without pivoting
  // either succeeds or says it is singular. Its inverse is cheap at this size and gives
  // the 1-norm condition number exactly (an estimate, such as LDLT::rcond, cost more).
  const Eigen::LLT<MatN> llt(M);
  if (llt.info() != Eigen::Success) return false;
  const MatN M_inv = llt.solve(MatN::Identity());
  out.condition = M.cwiseAbs().colwise().sum().maxCoeff() * M_inv.cwiseAbs().colwise().sum().maxCoeff();
  if (!std::isfinite(out.condition) || out.condition > settings_.max_condition) return false;

  const VecN c = M_inv.col(0);  // correction coefficients: Psi_I = c . H_I phi_I

  const std::size_t n = out.ids.size();
  if (!with_gradient) {
    if constexpr (N == 4) {
      // c . H written out: through a basis vector on the stack, each product waited
      // for two 8-byte stores to forward into one 16-byte load.
      for (std::size_t k = 0; k < n; ++k) {
        const Vec3& xi = out.offsets[k];
        out.psi[k] *= c(0) + c(1) * xi.x() + c(2) * xi.y() + c(3) * xi.z();
      }
    } else {
      for (std::size_t k = 0; k < n; ++k) out.psi[k] *= c.dot(Basis::value(out.offsets[k]));
    }
    return true;
  }

  // Gradients: d/dx_k of c(x) . H((X_I - x)/d) phi_I(x), with dc = -M^-1 (dM) c.
  MatN dM[3] = {MatN::Zero(), MatN::Zero(), MatN::Zero()};
  out.grad.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Index id = out.ids[k];
    const double q = normalized_distance(id, x);
    const auto kv = evaluate_kernel(settings_.kernel, q);
    const Vec3 dphi = kernel_gradient(id, x, q, kv.dw_dq);
    out.grad[k] = dphi;  // d phi_I / dx for now
    const Vec3& xi = out.offsets[k];
    const VecN h = Basis::value(xi);
    for (int j = 0; j < 3; ++j) {
      const VecN dh = -Basis::derivative(xi, j) * inv_scale;  // d xi / dx = -1/d
      dM[j].noalias() += kv.w * (dh * h.transpose() + h * dh.transpose()) + dphi(j) * h * h.transpose();
    }
  }
  VecN dc[3];
  for (int j = 0; j < 3; ++j) dc[j] = -M_inv * (dM[j] * c);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& xi = out.offsets[k];
    const VecN h = Basis::value(xi);
    const double phi = out.psi[k];
    const double ch = c.dot(h);
    Vec3 g;
    for (int j = 0; j < 3; ++j)
      g(j) = dc[j].dot(h) * phi - c.dot(Basis::derivative(xi, j)) * inv_scale * phi + ch * out.grad[k](j);
    out.grad[k] = g;
    out.psi[k] = ch * phi;
  }
  return true;
}

}  // namespace rkpm::rk
