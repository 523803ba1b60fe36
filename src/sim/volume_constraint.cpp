#include "rkpm/sim/volume_constraint.hpp"

#include "rkpm/io/json.hpp"

#include <cmath>

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

VolumeConstraint::VolumeConstraint(Body& body, std::uint32_t surface_bit, double bulk, double target)
    : body_(body), bulk_(bulk), target_(target) {
  const auto& q = body.boundary;
  for (std::size_t f = 0; f < q.point.size(); ++f)
    if (surface_bit == 0u || (q.surface_mask[f] & surface_bit)) facets_.push_back(f);
  area_.resize(facets_.size());
  cone_.resize(facets_.size());
  // The shape-function rows of the chosen facets, transposed once: the force becomes a
  // gather per particle. Rows are numbered by position in facets_.
  std::vector<Index> row_offset(facets_.size() + 1, 0), col;
  for (std::size_t i = 0; i < facets_.size(); ++i) {
    const std::size_t f = facets_[i];
    for (Index k = q.row_offset[f]; k < q.row_offset[f + 1]; ++k) {
      col.push_back(q.col[k]);
      psi_.push_back(q.psi[k]);
    }
    row_offset[i + 1] = static_cast<Index>(col.size());
  }
  by_particle_.build(row_offset, col, static_cast<Index>(body.size()));
  const double v = measure_signed_volume();
  sign_ = v < 0.0 ? -1.0 : 1.0;
  initial_ = volume_ = std::abs(v);
}

double VolumeConstraint::measure_signed_volume() {
  const auto& q = body_.boundary;
  const auto m = static_cast<std::int64_t>(facets_.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < m; ++i) {
    const std::size_t f = facets_[static_cast<std::size_t>(i)];
    const Vec3 area = cofactor(body_.F[q.owner[f]]) * q.area[f];
    Vec3 x = q.point[f];
    for (Index k = q.row_offset[f]; k < q.row_offset[f + 1]; ++k) x += q.psi[k] * body_.d[q.col[k]];
    area_[static_cast<std::size_t>(i)] = area;
    cone_[static_cast<std::size_t>(i)] = x.dot(area) / 3.0;
  }
  double v = 0.0;
  for (double c : cone_) v += c;  // in facet order: deterministic
  return v;
}

void VolumeConstraint::add_forces(World&) {
  volume_ = sign_ * measure_signed_volume();
  pressure_ = -bulk_ * std::log(volume_ / (target_ * initial_));
  const auto& T = by_particle_;
  const double scale = pressure_ * sign_;
  const auto n = static_cast<Index>(body_.size());
#pragma omp parallel for schedule(static)
  for (Index I = 0; I < n; ++I) {
    if (T.offset[I] == T.offset[I + 1]) continue;
    Vec3 push = Vec3::Zero();
    for (Index t = T.offset[I]; t < T.offset[I + 1]; ++t) push += psi_[T.entry[t]] * area_[T.row[t]];
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

}  // namespace rkpm::sim
