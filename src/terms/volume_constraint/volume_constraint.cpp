#include "terms/volume_constraint/volume_constraint.hpp"

#include "terms/catalog.hpp"
#include "terms/term_support.hpp"
#include "terms/volume_constraint/settings.hpp"

#include "rkpm/io/json.hpp"
#include "rkpm/sim/body_points.hpp"
#include "rkpm/common/parallel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace rkpm::sim {

namespace {
// J F^-T, the cofactor matrix of F: Nanson's map of reference area vectors.
Mat3 cofactor(const Mat3& F) {
  Mat3 c;
  c.col(0) = F.col(1).cross(F.col(2));
  c.col(1) = F.col(2).cross(F.col(0));
  c.col(2) = F.col(0).cross(F.col(1));
  return c;
}
}  // namespace

VolumeConstraint::VolumeConstraint(Body& body, std::uint32_t surface_bit, double bulk, double target,
                                   const par::Comm& comm)
    : body_(body), comm_(comm), bulk_(bulk), target_(target) {
  // Group the chosen facets by the cell that owns them (the boundary quadrature lists a
  // cell's facets together) and fold each cell's facets into one row:
  //   B_LI = sum_{f in L} Psi_I(X_f) A_f,   C_L = sum_{f in L} X_f (x) A_f.
  // The surface's quadrature is needed only here. It is built and folded in batches of
  // boundary particles, so that its shape functions (several times the folded rows) are
  // never held for the whole surface: on a large RBC shell they made the peak of the
  // set-up's memory (docs/verification/performance.md).
  constexpr std::size_t batch = 8192;
  Fold fold{std::vector<Vec3>(body.size(), Vec3::Zero()), std::vector<char>(body.size(), 0), {}};
  row_offset_.push_back(0);
  const particles::DualCells cells(body.cloud);
  const rk::RKApproximation rk = approximation(body);
  const std::size_t boundary = body.cloud.boundary_particles.size();
  for (std::size_t first = 0; first < boundary; first += batch)
    fold_facets(
        rk::build_boundary_quadrature(body.cloud, cells, rk, surface_bit, first, first + batch, body.cell_quadrature),
        fold);
  cofactor_.resize(owner_.size());
  cone_.resize(owner_.size());
  if (body.distributed()) {
    check_ghosts();
    std::tie(first_row_, end_row_) = owned_entries(body, owner_);
    plan_term_rows(push_, body, first_row_, end_row_, 1, [this](Index r, int, const std::function<void(Index)>& emit) {
      for (Index k = row_offset_[r]; k < row_offset_[r + 1]; ++k) emit(col_[k]);
    });
  } else {
    gather_by_particle();
  }
  const double v = measure_signed_volume();
  sign_ = v < 0.0 ? -1.0 : 1.0;
  initial_ = volume_ = std::abs(v);
}

void VolumeConstraint::fold_facets(const rk::BoundaryQuadrature& q, Fold& fold) {
  for (std::size_t f = 0; f < q.point.size();) {
    const Index owner = q.owner[f];
    Mat3 C = Mat3::Zero();
    for (; f < q.point.size() && q.owner[f] == owner; ++f) {
      C.noalias() += q.point[f] * q.area[f].transpose();
      for (Index k = q.row_offset[f]; k < q.row_offset[f + 1]; ++k) {
        const Index I = q.col[k];
        if (!fold.used[I]) {
          fold.used[I] = 1;
          fold.touched.push_back(I);
        }
        fold.value[I] += q.psi[k] * q.area[f];
      }
    }
    if (fold.touched.empty()) continue;
    std::sort(fold.touched.begin(), fold.touched.end());
    for (Index I : fold.touched) {
      col_.push_back(I);
      B_.push_back(fold.value[I]);
      fold.value[I].setZero();
      fold.used[I] = 0;
    }
    fold.touched.clear();
    owner_.push_back(owner);
    C_.push_back(C);
    row_offset_.push_back(static_cast<Index>(col_.size()));
  }
}

// One process gathers each particle's push over its rows (add_forces). B is copied in
// that order, so the gather streams it instead of reading it entry by entry across the
// rows, a scattered access that was a visible share of an RBC shell's step
// (docs/verification/relaxation.md measures it); the copy's entry index is then no
// longer needed. The sums keep their order and bits.
void VolumeConstraint::gather_by_particle() {
  by_particle_.build(row_offset_, col_, static_cast<Index>(body_.size()));
  B_by_particle_.resize(by_particle_.entry.size());
  for (std::size_t t = 0; t < by_particle_.entry.size(); ++t) B_by_particle_[t] = B_[by_particle_.entry[t]];
  std::vector<Index>().swap(by_particle_.entry);
}

// The rows a rank measures read d at their columns: each must be the rank's own particle
// or one of its ghosts (the facets are part of the cell's SCNI boundary, so their
// supports are within the gradient row's columns).
void VolumeConstraint::check_ghosts() const {
  const std::vector<char> readable = readable_particles(body_);
  for (std::size_t r = 0; r < owner_.size(); ++r) {
    if (!owns_row(r)) continue;
    for (Index k = row_offset_[r]; k < row_offset_[r + 1]; ++k)
      if (!readable[static_cast<std::size_t>(col_[k])])
        throw std::logic_error(fmt::format("volume constraint on body '{}': the surface row of particle {} reads "
                                           "particle {}, which its rank neither owns nor holds as a ghost",
                                           body_.name, owner_[r], col_[k]));
  }
}

bool VolumeConstraint::owns_row(std::size_t r) const {
  return owner_[r] >= body_.owned_begin() && owner_[r] < body_.owned_end();
}

double VolumeConstraint::measure_signed_volume() {
  // V = (1/3) sum_L cof(F_L) : (C_L + sum_I d_I (x) B_LI), the facet sum x_f . a_f regrouped.
  const auto m = static_cast<Index>(owner_.size());
#pragma omp parallel for schedule(static) if (worth_threads(m))
  for (Index r = 0; r < m; ++r) {
    if (!owns_row(static_cast<std::size_t>(r))) {
      cone_[r] = 0.0;  // another rank's cell
      continue;
    }
    Mat3 G = C_[r];
    for (Index k = row_offset_[r]; k < row_offset_[r + 1]; ++k) G.noalias() += body_.d[col_[k]] * B_[k].transpose();
    cofactor_[r] = cofactor(body_.F[owner_[r]]);
    cone_[r] = cofactor_[r].cwiseProduct(G).sum() / 3.0;
  }
  ExactSum v;  // exact: the same bits on any rank count
  for (double c : cone_) v.add(c);
  return comm_.sum(v);
}

void VolumeConstraint::add_forces(World&) {
  volume_ = sign_ * measure_signed_volume();
  pressure_ = -bulk_ * std::log(volume_ / (target_ * initial_));
  // f_I = p s sum_L cof(F_L) B_LI, each particle's sum over its rows in increasing order.
  const double scale = pressure_ * sign_;
  if (body_.distributed()) {
    // The owned rows scattered, ordered over the ranks (plan_term_rows).
    push_.clear(0);
    for (Index r = first_row_; r < end_row_; ++r) {
      const auto sink = push_.sink(0, 0, r);
      for (Index k = row_offset_[r]; k < row_offset_[r + 1]; ++k) sink(col_[k], Vec3(cofactor_[r] * B_[k]));
    }
    add_term_rows(push_, 0, scale, body_.force);
    return;
  }
  // One process: a gather per particle over the transposed rows, in parallel.
  const auto& T = by_particle_;
  const auto n = static_cast<Index>(body_.size());
#pragma omp parallel for schedule(static) if (worth_threads(n))
  for (Index I = 0; I < n; ++I) {
    if (T.offset[I] == T.offset[I + 1]) continue;
    Vec3 push = Vec3::Zero();
    for (Index t = T.offset[I]; t < T.offset[I + 1]; ++t) push += Vec3(cofactor_[T.row[t]] * B_by_particle_[t]);
    body_.force[I] += scale * push;
  }
}

double VolumeConstraint::stored_energy(const World&) const {
  const double target_volume = target_ * initial_;
  return bulk_ * (volume_ * std::log(volume_ / target_volume) - volume_ + target_volume);
}

void VolumeConstraint::report(const World&, io::Json& summary) const {
  io::Json j = io::Json::object();
  j.set("body", body_.name);
  j.set("initial_volume", initial_);
  j.set("volume", volume_);
  j.set("volume_ratio", volume_ / initial_);
  j.set("pressure", pressure_);
  summary.set("volume_constraint", j);
}

std::string VolumeConstraint::history_values(const World&) const {
  return fmt::format(",{:.10g},{:.6g}", volume() / initial_volume(), pressure());
}

}  // namespace rkpm::sim

namespace rkpm::terms::volume_constraint {

std::unique_ptr<sim::Term> build(const scene::ParamSet& params, sim::World& world) {
  const sim::VolumeConstraintSettings s = settings_table().read(params);
  sim::Body& body = named_body(world, params, s.body);
  return std::make_unique<sim::VolumeConstraint>(body, surface_selector(body, s.surface), s.bulk, s.target,
                                                 *world.comm);
}

}  // namespace rkpm::terms::volume_constraint
