#include "rkpm/sim/essential_bc.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <stdexcept>

namespace rkpm::sim {

using SparseMatrix = Eigen::SparseMatrix<double>;

struct EssentialBC::Axis {
  std::vector<Index> particles;        // constrained particles of this axis, ascending
  std::vector<Index> local;            // particle -> position in `particles`, or -1
  Eigen::VectorXd velocity;            // prescribed d ubar / dt
  Eigen::VectorXd target;              // ubar at the current time
  std::vector<Index> cf_offset;        // Lambda_CF by rows of C (CSR)
  std::vector<Index> cf_col;
  std::vector<double> cf_val;
  Eigen::SparseLU<SparseMatrix> lu;    // Lambda_CC
  Eigen::SparseLU<SparseMatrix> lu_t;  // Lambda_CC^T

  // y = Lambda_CF z (the free part of the constraint rows), for one component.
  Eigen::VectorXd free_part(const std::vector<Vec3>& z, int axis) const {
    Eigen::VectorXd y(static_cast<Eigen::Index>(particles.size()));
    for (std::size_t r = 0; r < particles.size(); ++r) {
      double s = 0.0;
      for (Index k = cf_offset[r]; k < cf_offset[r + 1]; ++k) s += cf_val[k] * z[cf_col[k]][axis];
      y(static_cast<Eigen::Index>(r)) = s;
    }
    return y;
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
  for (int a = 0; a < 3; ++a) {
    auto ax = std::make_unique<Axis>();
    ax->local.assign(n, -1);
    std::vector<double> vel_of(n, 0.0);
    for (const auto& c : components)
      if (c.axis == a) vel_of[c.particle] = c.velocity;  // the last declaration wins
    for (std::size_t i = 0; i < n; ++i)
      if (mask_[i][a]) {
        ax->local[i] = static_cast<Index>(ax->particles.size());
        ax->particles.push_back(static_cast<Index>(i));
      }
    if (ax->particles.empty()) continue;
    const auto m = static_cast<Eigen::Index>(ax->particles.size());
    ax->velocity.resize(m);
    ax->target.resize(m);
    std::vector<Eigen::Triplet<double>> cc;
    ax->cf_offset.push_back(0);
    for (Eigen::Index r = 0; r < m; ++r) {
      const Index J = ax->particles[static_cast<std::size_t>(r)];
      ax->velocity(r) = vel_of[J];
      double u = 0.0;  // physical displacement at J now: the initial target
      for (Index k = interp.row_offset[J]; k < interp.row_offset[J + 1]; ++k) {
        const Index I = interp.col[k];
        u += interp.psi[k] * d[I][a];
        if (ax->local[I] >= 0) {
          cc.emplace_back(r, ax->local[I], interp.psi[k]);
        } else {
          ax->cf_col.push_back(I);
          ax->cf_val.push_back(interp.psi[k]);
        }
      }
      ax->target(r) = u;
      ax->cf_offset.push_back(static_cast<Index>(ax->cf_col.size()));
    }
    SparseMatrix Lcc(m, m);
    Lcc.setFromTriplets(cc.begin(), cc.end());
    ax->lu.compute(Lcc);
    SparseMatrix Lcc_t = Lcc.transpose();
    ax->lu_t.compute(Lcc_t);
    if (ax->lu.info() != Eigen::Success || ax->lu_t.info() != Eigen::Success)
      throw std::runtime_error("essential boundary conditions: the shape-function matrix of the constrained "
                               "particles is singular (axis " + std::string(1, "xyz"[a]) + ")");
    components_ += ax->particles.size();
    axes_[static_cast<std::size_t>(a)] = std::move(ax);
  }
}

void EssentialBC::distribute(const par::Comm& comm, const std::vector<Index>& offset) {
  std::vector<Index> constrained, rows;
  for (const auto& ax : axes_) {
    if (!ax) continue;
    constrained.insert(constrained.end(), ax->particles.begin(), ax->particles.end());
    rows.insert(rows.end(), ax->cf_col.begin(), ax->cf_col.end());
  }
  rows.insert(rows.end(), constrained.begin(), constrained.end());
  constrained_.build(comm, offset, std::move(constrained));
  rows_.build(comm, offset, std::move(rows));
}

double EssentialBC::transform_forces(std::vector<Vec3>& f) const {
  if (constrained_.built()) constrained_.update(f);
  double support_power = 0.0;
  for (int a = 0; a < 3; ++a) {
    const Axis* ax = axes_[static_cast<std::size_t>(a)].get();
    if (!ax) continue;
    Eigen::VectorXd fc(static_cast<Eigen::Index>(ax->particles.size()));
    for (std::size_t r = 0; r < ax->particles.size(); ++r) fc(static_cast<Eigen::Index>(r)) = f[ax->particles[r]][a];
    const Eigen::VectorXd reaction = ax->lu_t.solve(fc);  // Lambda_CC^-T f_C
    for (std::size_t r = 0; r < ax->particles.size(); ++r) {
      const double rr = reaction(static_cast<Eigen::Index>(r));
      for (Index k = ax->cf_offset[r]; k < ax->cf_offset[r + 1]; ++k) f[ax->cf_col[k]][a] -= ax->cf_val[k] * rr;
      f[ax->particles[r]][a] = 0.0;
    }
    // The supports hold the constrained points against the net force r: their force is -r.
    support_power -= reaction.dot(ax->velocity);
  }
  return support_power;
}

void EssentialBC::impose(std::vector<Vec3>& d, std::vector<Vec3>& v) const {
  if (rows_.built()) {
    rows_.update(d);
    rows_.update(v);
  }
  for (int a = 0; a < 3; ++a) {
    const Axis* ax = axes_[static_cast<std::size_t>(a)].get();
    if (!ax) continue;
    const Eigen::VectorXd dc = ax->lu.solve(ax->target - ax->free_part(d, a));
    const Eigen::VectorXd vc = ax->lu.solve(ax->velocity - ax->free_part(v, a));
    for (std::size_t r = 0; r < ax->particles.size(); ++r) {
      d[ax->particles[r]][a] = dc(static_cast<Eigen::Index>(r));
      v[ax->particles[r]][a] = vc(static_cast<Eigen::Index>(r));
    }
  }
}

void EssentialBC::advance(double dt, std::vector<Vec3>& d, std::vector<Vec3>& v) {
  for (auto& ax : axes_)
    if (ax) ax->target += dt * ax->velocity;
  impose(d, v);
}

bool EssentialBC::constrained(Index particle, int axis) const {
  return !mask_.empty() && mask_[particle][axis];
}

std::vector<double> EssentialBC::targets() const {
  std::vector<double> t;
  for (const auto& ax : axes_)
    if (ax) t.insert(t.end(), ax->target.data(), ax->target.data() + ax->target.size());
  return t;
}

void EssentialBC::set_targets(const std::vector<double>& t) {
  std::size_t k = 0;
  for (auto& ax : axes_) {
    if (!ax) continue;
    for (Eigen::Index r = 0; r < ax->target.size(); ++r) {
      if (k >= t.size()) throw std::invalid_argument("EssentialBC::set_targets: too few values");
      ax->target(r) = t[k++];
    }
  }
  if (k != t.size()) throw std::invalid_argument("EssentialBC::set_targets: too many values");
}

}  // namespace rkpm::sim
