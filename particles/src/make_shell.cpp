// Thick ellipsoidal shell: a cubed sphere of unit directions, mapped onto nested
// ellipsoids and joined layer to layer by hexahedra.
#include "rkpm/particles/generators.hpp"

#include "cube_sphere.hpp"
#include "gauss_legendre.hpp"
#include "node_merge.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <vector>

namespace rkpm::particles {
namespace {

// Unit directions of the cubed sphere and its quads (outward counter-clockwise).
struct SphereGrid {
  std::vector<Vec3> directions;
  std::vector<std::array<std::int32_t, 4>> quads;
};

SphereGrid cubed_sphere(int n) {
  std::vector<Vec3> points;
  std::vector<std::array<std::int32_t, 4>> quads;
  for (int axis = 0; axis < 3; ++axis) {
    for (const double sign : {1.0, -1.0}) {
      // Tangent axes with e_u x e_v = sign * e_axis, so (i, j) quads face outward.
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if (sign < 0) std::swap(u, v);
      const auto base = static_cast<std::int32_t>(points.size());
      for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
          Vec3 p;
          p[axis] = sign;
          p[u] = double(2 * i - n) / n;
          p[v] = double(2 * j - n) / n;
          points.push_back(detail::equiangular_direction(p));
        }
      }
      auto at = [&](int i, int j) { return base + static_cast<std::int32_t>(i + (n + 1) * j); };
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  // Seam nodes are bit-identical copies (equiangular() is exact at the cube edges).
  detail::MergedNodes merged = detail::merge_coincident_nodes(points, 1e-9);
  for (auto& q : quads) {
    for (auto& id : q) id = merged.id[id];
  }
  return {std::move(merged.points), std::move(quads)};
}

// Colatitude remap along a meridian of the ellipse (rho sin psi, c cos psi):
// returns psi with s(psi) / s(pi) = theta / pi, s the arc length, so equal steps
// in the sphere's colatitude theta give equal arc lengths on the ellipsoid and
// the cells at a flat spheroid's rim are not stretched.
class MeridianRemap {
 public:
  MeridianRemap(double rho, double c) : rho_(rho), c_(c), cumulative_(kIntervals + 1, 0.0) {
    for (int k = 0; k < kIntervals; ++k) cumulative_[k + 1] = cumulative_[k] + arc(k * kStep, (k + 1) * kStep);
  }

  double psi(double theta) const {
    if (theta > 0.5 * M_PI) return M_PI - psi(M_PI - theta);  // mirror symmetry about the equator
    const double target = theta / (0.5 * M_PI) * cumulative_.back();
    // Newton on s(psi) = target; s' = speed > 0 and s is smooth, so a handful of
    // steps from psi = theta reach machine precision.
    double psi = theta;
    for (int it = 0; it < 50; ++it) {
      const double next = std::clamp(psi - (arc_from_pole(psi) - target) / speed(psi), 0.0, 0.5 * M_PI);
      const bool converged = std::abs(next - psi) <= 1e-15;
      psi = next;
      if (converged) break;
    }
    return psi;
  }

 private:
  // Table intervals of pi/128: one 8-point Gauss panel each integrates the speed
  // to machine precision even for flat spheroids, whose integrand has complex
  // singularities at distance atanh(c/rho) (0.22 for the seed's inner surface).
  static constexpr int kIntervals = 64;
  static constexpr double kStep = 0.5 * M_PI / kIntervals;

  double speed(double psi) const {
    const double co = std::cos(psi), si = std::sin(psi);
    return std::sqrt(rho_ * rho_ * co * co + c_ * c_ * si * si);
  }
  double arc(double from, double to) const {
    return detail::integrate([this](double p) { return speed(p); }, from, to, kStep);
  }
  double arc_from_pole(double psi) const {
    const int k = std::min(kIntervals - 1, static_cast<int>(psi / kStep));
    return cumulative_[k] + arc(k * kStep, psi);
  }

  double rho_, c_;
  std::vector<double> cumulative_;  // arc length from the pole to k * kStep
};

// A point of the ellipsoid with semi-axes s along the unit direction d, by the
// sphere's longitude and remapped colatitude. The meridian at longitude phi has
// equatorial radius rho = |(a cos phi, b sin phi)|; for a spheroid (a = b) every
// meridian is the same ellipse and `spheroid_remap` serves them all.
Vec3 on_ellipsoid(const Vec3& s, const Vec3& d, const MeridianRemap* spheroid_remap) {
  const double theta = std::atan2(std::hypot(d.x(), d.y()), d.z());
  const double phi = std::atan2(d.y(), d.x());
  const double cp = std::cos(phi), sp = std::sin(phi);
  const double psi = spheroid_remap ? spheroid_remap->psi(theta)
                                    : MeridianRemap(std::hypot(s.x() * cp, s.y() * sp), s.z()).psi(theta);
  return Vec3(s.x() * std::sin(psi) * cp, s.y() * std::sin(psi) * sp, s.z() * std::cos(psi));
}

void check(const ShellSpec& spec) {
  std::ostringstream msg;
  if (spec.face_cells < 1) msg << "face_cells = " << spec.face_cells << ", expected >= 1";
  else if (spec.layers < 2) msg << "layers = " << spec.layers << ", expected >= 2";
  else if (!(spec.thickness > 0.0)) msg << "thickness = " << spec.thickness << ", expected > 0";
  else if (!(spec.semi_axes.minCoeff() > spec.thickness)) {
    msg << "thickness = " << spec.thickness << " must be smaller than every semi-axis ("
        << spec.semi_axes.transpose() << ")";
  }
  if (!msg.str().empty()) throw CloudError("make_shell: " + msg.str());
}

}  // namespace

Cloud make_shell(const ShellSpec& spec) {
  check(spec);
  const SphereGrid sphere = cubed_sphere(spec.face_cells);
  const auto per_layer = static_cast<std::int32_t>(sphere.directions.size());

  Cloud cloud;
  cloud.name = "shell";
  cloud.surface_names = {"outer", "inner"};
  cloud.X.reserve(std::size_t(per_layer) * spec.layers);
  cloud.surface_mask.assign(std::size_t(per_layer) * spec.layers, 0);
  for (int k = 0; k < spec.layers; ++k) {
    // Layer 0 is the inner surface, layer `layers - 1` the outer one.
    const double t = double(k) / (spec.layers - 1);
    const Vec3 axes = (spec.semi_axes.array() - spec.thickness * (1.0 - t)).matrix();
    const bool spheroid = axes.x() == axes.y();
    const MeridianRemap remap(axes.x(), axes.z());
    for (const Vec3& d : sphere.directions) {
      cloud.X.push_back(spec.center + on_ellipsoid(axes, d, spheroid ? &remap : nullptr));
    }
  }
  for (std::int32_t m = 0; m < per_layer; ++m) {
    cloud.surface_mask[m] |= cloud.surface_bit("inner");
    cloud.surface_mask[std::size_t(spec.layers - 1) * per_layer + m] |= cloud.surface_bit("outer");
  }
  // Quads face outward, so inner layer = VTK bottom face, outer layer = top face.
  for (int k = 0; k + 1 < spec.layers; ++k) {
    for (const auto& q : sphere.quads) {
      std::int32_t ids[8];
      for (int a = 0; a < 4; ++a) {
        ids[a] = k * per_layer + q[a];
        ids[a + 4] = (k + 1) * per_layer + q[a];
      }
      cloud.mesh.add_element(ElementType::Hex8, ids);
    }
  }
  finalize_cloud(cloud);
  return cloud;
}

}  // namespace rkpm::particles
