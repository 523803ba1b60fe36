#include "rkpm/sim/essential_bc.hpp"

#include "rkpm/par/ghost_exchange.hpp"
#include "rkpm/par/shared_particles.hpp"
#include "sim/integration/constraint_solver.hpp"

#include <Eigen/SparseCore>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>

namespace rkpm::sim {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The axes that constrain one set of particles C, and what their transformation needs.
struct EssentialBC::Group {
  std::vector<int> axes;               // ascending; column j of the matrices below is axes[j]
  std::vector<Index> particles;        // C, ascending
  Eigen::MatrixXd velocity;            // prescribed d ubar / dt, |C| x axes
  Eigen::MatrixXd target;              // ubar at the current time, |C| x axes
  std::vector<Index> cf_offset;        // Lambda_CF by rows of C (CSR)
  std::vector<Index> cf_col;
  std::vector<double> cf_val;
  // Lambda_CC, factored once in parts that the ranks share (constraint_solver.hpp): its
  // transpose solves through the same factors (SparseLU::transpose()). A second
  // factorization of Lambda_CC^T held as much again, which showed in a large block's peak
  // memory (docs/verification/performance.md).
  ConstraintSolver solver;
  // The rows whose free part this rank forms: all of them on one rank, those of the
  // particles it owns when distributed (a run of C: ranks own increasing ranges).
  std::size_t row_begin = 0, row_end = 0;
  // The entries of Lambda_CF whose column this rank owns, in row order: (row, entry).
  std::vector<std::pair<std::size_t, Index>> owned_entries;
  par::SharedParticles shared;         // distributed: C on every rank
  par::GhostExchange columns;          // distributed: the columns of this rank's rows it does not own

  Index size() const { return static_cast<Index>(particles.size()); }

  // This rank's share of the work per row, for particles [begin, end): the rows of its
  // constrained particles and the entries whose column it owns.
  void own(Index begin, Index end) {
    row_begin = static_cast<std::size_t>(std::lower_bound(particles.begin(), particles.end(), begin) - particles.begin());
    row_end = static_cast<std::size_t>(std::lower_bound(particles.begin(), particles.end(), end) - particles.begin());
    owned_entries.clear();
    for (std::size_t r = 0; r < particles.size(); ++r)
      for (Index k = cf_offset[r]; k < cf_offset[r + 1]; ++k)
        if (cf_col[static_cast<std::size_t>(k)] >= begin && cf_col[static_cast<std::size_t>(k)] < end)
          owned_entries.emplace_back(r, k);
  }

  // max |Lambda_CC^-1 Lambda_CF z| over four fixed patterns z of +-1 on the free
  // particles (the columns of Lambda_CF) (EssentialBC::amplification): a pattern per bit of a
  // hash of the particle's number, so that neighbours move alike and apart in turn.
  double amplification() const {
    constexpr int kPatterns = 4;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(size(), kPatterns);
    for (std::size_t r = 0; r < particles.size(); ++r)
      for (Index k = cf_offset[r]; k < cf_offset[r + 1]; ++k) {
        const auto I = static_cast<std::uint64_t>(cf_col[static_cast<std::size_t>(k)]);
        const std::uint64_t hash = (I + 1) * 0x9e3779b97f4a7c15ULL;
        for (int p = 0; p < kPatterns; ++p)
          rhs(static_cast<Eigen::Index>(r), p) += ((hash >> (59 - p)) & 1u ? 1.0 : -1.0) * cf_val[static_cast<std::size_t>(k)];
      }
    return size() == 0 ? 0.0 : solver.solve(rhs).cwiseAbs().maxCoeff();
  }

  // y[r] = (Lambda_CF z)_r for this rank's rows, every component; on several ranks the
  // other rows' sums are then gathered from their owners.
  void free_part(const std::vector<Vec3>& z, std::vector<Vec3>& y) const {
    y.assign(particles.size(), Vec3::Zero());
    for (std::size_t r = row_begin; r < row_end; ++r) {
      Vec3 s = Vec3::Zero();
      for (Index k = cf_offset[r]; k < cf_offset[r + 1]; ++k) s += cf_val[static_cast<std::size_t>(k)] * z[cf_col[k]];
      y[r] = s;
    }
    if (shared.built()) shared.update_packed(y);
  }
};

EssentialBC::EssentialBC() = default;
EssentialBC::~EssentialBC() = default;
EssentialBC::EssentialBC(EssentialBC&&) noexcept = default;
EssentialBC& EssentialBC::operator=(EssentialBC&&) noexcept = default;

EssentialBC::EssentialBC(const rk::NodalInterpolation& interp, std::vector<ConstrainedComponent> components,
                         const std::vector<Vec3>& d) {
  const std::size_t n = interp.row_offset.size() - 1;
  mask_.assign(n, {0, 0, 0});
  for (const auto& c : components) {
    if (c.particle < 0 || static_cast<std::size_t>(c.particle) >= n || c.axis < 0 || c.axis > 2)
      throw std::invalid_argument("EssentialBC: constrained component out of range");
    mask_[c.particle][c.axis] = 1;
  }
  std::array<std::vector<Index>, 3> set;
  std::array<std::vector<double>, 3> velocity_of;
  for (int a = 0; a < 3; ++a) {
    velocity_of[a].assign(n, 0.0);
    for (const auto& c : components)
      if (c.axis == a) velocity_of[a][c.particle] = c.velocity;  // the last declaration wins
    for (std::size_t i = 0; i < n; ++i)
      if (mask_[i][a]) set[a].push_back(static_cast<Index>(i));
  }
  for (int a = 0; a < 3; ++a) {
    if (set[a].empty()) continue;
    const auto same =
        std::find_if(groups_.begin(), groups_.end(), [&](const auto& g) { return g->particles == set[a]; });
    if (same != groups_.end()) {
      (*same)->axes.push_back(a);
      continue;
    }
    auto g = std::make_unique<Group>();
    g->axes = {a};
    g->particles = set[a];
    std::vector<Index> local(n, -1);
    for (std::size_t r = 0; r < g->particles.size(); ++r) local[g->particles[r]] = static_cast<Index>(r);
    std::vector<Eigen::Triplet<double>> cc;
    g->cf_offset.push_back(0);
    for (std::size_t r = 0; r < g->particles.size(); ++r) {
      const Index J = g->particles[r];
      // The row's weights with the own-particle correction (rk::for_each_weight), so the
      // constraint is the same interpolation the output and the forces use; setFromTriplets
      // adds the correction to J's own entry.
      rk::for_each_weight(interp, J, [&](Index I, double w) {
        if (local[I] >= 0) {
          cc.emplace_back(static_cast<Eigen::Index>(r), local[I], w);
        } else {
          g->cf_col.push_back(I);
          g->cf_val.push_back(w);
        }
      });
      g->cf_offset.push_back(static_cast<Index>(g->cf_col.size()));
    }
    const auto m = g->size();
    SparseMatrix Lcc(m, m);
    Lcc.setFromTriplets(cc.begin(), cc.end());
    if (!g->solver.factor(Lcc))
      throw std::runtime_error("essential boundary conditions: the shape-function matrix of the constrained "
                               "particles is singular (axis " + std::string(1, "xyz"[a]) + ")");
    g->own(0, static_cast<Index>(n));
    groups_.push_back(std::move(g));
  }
  for (auto& g : groups_) {
    const auto m = g->size();
    const auto axes = static_cast<Eigen::Index>(g->axes.size());
    g->velocity.resize(m, axes);
    g->target.resize(m, axes);
    for (Eigen::Index r = 0; r < m; ++r) {
      const Index J = g->particles[static_cast<std::size_t>(r)];
      const Vec3 u = rk::interpolate(interp, d, J);  // the physical displacement at J now: the initial targets
      for (Eigen::Index j = 0; j < axes; ++j) {
        const int a = g->axes[static_cast<std::size_t>(j)];
        g->velocity(r, j) = velocity_of[a][J];
        g->target(r, j) = u[a];
      }
    }
    components_ += g->particles.size() * g->axes.size();
    amplification_ = std::max(amplification_, g->amplification());
  }
}

void EssentialBC::distribute(const par::Comm& comm, const std::vector<Index>& offset) {
  const Index begin = offset[static_cast<std::size_t>(comm.rank())];
  const Index end = offset[static_cast<std::size_t>(comm.rank()) + 1];
  for (auto& g : groups_) {
    g->own(begin, end);
    std::vector<Index> columns;
    for (std::size_t r = g->row_begin; r < g->row_end; ++r)
      columns.insert(columns.end(), g->cf_col.begin() + g->cf_offset[r], g->cf_col.begin() + g->cf_offset[r + 1]);
    g->columns.build(comm, offset, std::move(columns));
    g->shared.build(comm, offset, g->particles);
    g->solver.distribute(comm);
  }
}

double EssentialBC::transform_forces(std::vector<Vec3>& f) const {
  double support_power = 0.0;
  for (const auto& g : groups_) {
    if (g->shared.built()) g->shared.update(f);
    const auto m = g->size();
    const auto axes = static_cast<Eigen::Index>(g->axes.size());
    Eigen::MatrixXd fc(m, axes);
    for (Eigen::Index r = 0; r < m; ++r)
      for (Eigen::Index j = 0; j < axes; ++j)
        fc(r, j) = f[g->particles[static_cast<std::size_t>(r)]][g->axes[static_cast<std::size_t>(j)]];
    const Eigen::MatrixXd reaction = g->solver.solve_transposed(fc);  // Lambda_CC^-T f_C
    for (const auto& [r, k] : g->owned_entries)
      for (Eigen::Index j = 0; j < axes; ++j)
        f[g->cf_col[static_cast<std::size_t>(k)]][g->axes[static_cast<std::size_t>(j)]] -=
            g->cf_val[static_cast<std::size_t>(k)] * reaction(static_cast<Eigen::Index>(r), j);
    for (Eigen::Index r = 0; r < m; ++r)
      for (int a : g->axes) f[g->particles[static_cast<std::size_t>(r)]][a] = 0.0;
    // The supports hold the constrained points against the net force r: their force is -r.
    for (Eigen::Index j = 0; j < axes; ++j) support_power -= reaction.col(j).dot(g->velocity.col(j));
  }
  return support_power;
}

void EssentialBC::impose(std::vector<Vec3>& d, std::vector<Vec3>& v) const {
  for (const auto& g : groups_) {
    if (g->columns.built()) {
      g->columns.pull(d);
      g->columns.pull(v);
    }
    std::vector<Vec3> free_d, free_v;
    g->free_part(d, free_d);
    g->free_part(v, free_v);
    // d_C and v_C in one solve: a column per axis for each.
    const auto m = g->size();
    const auto axes = static_cast<Eigen::Index>(g->axes.size());
    Eigen::MatrixXd rhs(m, 2 * axes);
    for (Eigen::Index r = 0; r < m; ++r)
      for (Eigen::Index j = 0; j < axes; ++j) {
        const int a = g->axes[static_cast<std::size_t>(j)];
        rhs(r, j) = g->target(r, j) - free_d[static_cast<std::size_t>(r)][a];
        rhs(r, axes + j) = g->velocity(r, j) - free_v[static_cast<std::size_t>(r)][a];
      }
    const Eigen::MatrixXd solution = g->solver.solve(rhs);
    for (Eigen::Index r = 0; r < m; ++r)
      for (Eigen::Index j = 0; j < axes; ++j) {
        const int a = g->axes[static_cast<std::size_t>(j)];
        d[g->particles[static_cast<std::size_t>(r)]][a] = solution(r, j);
        v[g->particles[static_cast<std::size_t>(r)]][a] = solution(r, axes + j);
      }
  }
}

void EssentialBC::advance(double dt, std::vector<Vec3>& d, std::vector<Vec3>& v) {
  for (auto& g : groups_) g->target += dt * g->velocity;
  impose(d, v);
}

bool EssentialBC::constrained(Index particle, int axis) const {
  return !mask_.empty() && mask_[particle][axis];
}

// Per axis in order x, y, z, its constrained particles in ascending order (the order
// checkpoints store).
std::vector<double> EssentialBC::targets() const {
  std::vector<double> t;
  for (int a = 0; a < 3; ++a)
    for (const auto& g : groups_)
      for (std::size_t j = 0; j < g->axes.size(); ++j)
        if (g->axes[j] == a)
          for (Eigen::Index r = 0; r < g->size(); ++r) t.push_back(g->target(r, static_cast<Eigen::Index>(j)));
  return t;
}

void EssentialBC::set_targets(const std::vector<double>& t) {
  std::size_t k = 0;
  for (int a = 0; a < 3; ++a)
    for (auto& g : groups_)
      for (std::size_t j = 0; j < g->axes.size(); ++j)
        if (g->axes[j] == a)
          for (Eigen::Index r = 0; r < g->size(); ++r) {
            if (k >= t.size()) throw std::invalid_argument("EssentialBC::set_targets: too few values");
            g->target(r, static_cast<Eigen::Index>(j)) = t[k++];
          }
  if (k != t.size()) throw std::invalid_argument("EssentialBC::set_targets: too many values");
}

}  // namespace rkpm::sim
