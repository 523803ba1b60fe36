#include "rkpm/sim/volume_constraint.hpp"

#include "rkpm/io/json.hpp"

#include <cmath>

namespace rkpm::sim {

VolumeConstraint::VolumeConstraint(Body& body, std::uint32_t surface_bit, double bulk, double target)
    : body_(body), bulk_(bulk), target_(target) {
  const auto& q = body.boundary;
  for (std::size_t f = 0; f < q.point.size(); ++f)
    if (surface_bit == 0u || (q.surface_mask[f] & surface_bit)) facets_.push_back(f);
  const double v = measure_signed_volume();
  sign_ = v < 0.0 ? -1.0 : 1.0;
  initial_ = volume_ = std::abs(v);
}

double VolumeConstraint::measure_signed_volume() const {
  const auto& q = body_.boundary;
  double v = 0.0;
  for (std::size_t f : facets_) {
    const Mat3& F = body_.F[q.owner[f]];
    const Vec3 area = F.determinant() * F.inverse().transpose() * q.area[f];
    Vec3 x = q.point[f];
    for (Index k = q.row_offset[f]; k < q.row_offset[f + 1]; ++k) x += q.psi[k] * body_.d[q.col[k]];
    v += x.dot(area) / 3.0;
  }
  return v;
}

void VolumeConstraint::add_forces(World&) {
  volume_ = sign_ * measure_signed_volume();
  pressure_ = -bulk_ * std::log(volume_ / (target_ * initial_));
  const auto& q = body_.boundary;
  for (std::size_t f : facets_) {
    const Mat3& F = body_.F[q.owner[f]];
    const Vec3 push = (pressure_ * sign_ * F.determinant()) * (F.inverse().transpose() * q.area[f]);
    for (Index k = q.row_offset[f]; k < q.row_offset[f + 1]; ++k) body_.force[q.col[k]] += q.psi[k] * push;
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
