#include "rigid_modes.hpp"

#include <cmath>
#include <stdexcept>

namespace rkpm::study {

RigidModes::RigidModes(const std::vector<Vec3>& X, std::vector<double> weight) : weight_(std::move(weight)) {
  if (weight_.size() != X.size()) throw std::invalid_argument("RigidModes: one weight per particle required");
  // Rotations about the weighted centroid are already orthogonal to translations
  // in exact arithmetic; centring keeps Gram-Schmidt well conditioned.
  Vec3 centroid = Vec3::Zero();
  double total = 0.0;
  for (std::size_t i = 0; i < X.size(); ++i) {
    centroid += weight_[i] * X[i];
    total += weight_[i];
  }
  centroid /= total;
  for (int k = 0; k < 6; ++k) {
    Field& q = basis_[static_cast<std::size_t>(k)];
    q.resize(X.size());
    for (std::size_t i = 0; i < X.size(); ++i)
      q[i] = k < 3 ? Vec3(Vec3::Unit(k)) : Vec3(Vec3::Unit(k - 3).cross(X[i] - centroid));
    // Modified Gram-Schmidt, two passes for orthogonality to round-off.
    for (int pass = 0; pass < 2; ++pass)
      for (int j = 0; j < k; ++j) {
        const Field& p = basis_[static_cast<std::size_t>(j)];
        const double c = inner(p, q);
        for (std::size_t i = 0; i < X.size(); ++i) q[i] -= c * p[i];
      }
    const double norm = std::sqrt(inner(q, q));
    for (auto& v : q) v /= norm;
  }
}

double RigidModes::inner(const Field& u, const Field& v) const {
  double sum = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) sum += weight_[i] * u[i].dot(v[i]);
  return sum;
}

Field RigidModes::fit(const Field& v) const {
  Field r(v.size(), Vec3::Zero());
  for (const Field& q : basis_) {
    const double c = inner(q, v);
    for (std::size_t i = 0; i < v.size(); ++i) r[i] += c * q[i];
  }
  return r;
}

void RigidModes::remove_from(Field& v) const {
  const Field r = fit(v);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] -= r[i];
}

}  // namespace rkpm::study
