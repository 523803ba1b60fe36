// Thick ellipsoidal shell: a cubed sphere of unit directions, mapped onto nested
// ellipsoids and joined layer to layer by hexahedra.
#include "rkpm/particles/generators.hpp"

#include "cube_sphere.hpp"
#include "structured_grid.hpp"
#include "meridian_sampling.hpp"
#include "node_merge.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace rkpm::particles {
namespace {

// Share of the meridian's particles placed by the turning of the normal rather
// than by arc length (see MeridianSampling). For the seed's shell (inner rim
// radius of curvature 0.22 um against a mean spacing of 0.16 um at 32 face cells)
// pure arc length leaves the inner normals 2.7 deg off next to the rim; 0.05
// brings both surfaces under 0.5 deg while the longest meridional spacing stays
// within 1.7 times the shortest. Larger weights starve the caps (0.1: spacing
// ratio 2.4, normals slightly worse). A sphere is unaffected: its normal turns at a
// constant rate along the arc, so the blend is arc length again.
constexpr double kTurningWeight = 0.05;

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

// A point of the ellipsoid with semi-axes s along the unit direction d, by the
// sphere's longitude and remapped colatitude. The meridian at longitude phi has
// equatorial radius rho = |(a cos phi, b sin phi)|; for a spheroid (a = b) every
// meridian is the same ellipse and `spheroid_meridian` serves them all. Every layer
// samples its own ellipse with the same blend, so the particles of one column stay
// at matching places of their meridians (same share of arc length and turning).
Vec3 on_ellipsoid(const Vec3& s, const Vec3& d, const detail::MeridianSampling* spheroid_meridian) {
  const double theta = std::atan2(std::hypot(d.x(), d.y()), d.z());
  const double phi = std::atan2(d.y(), d.x());
  const double cp = std::cos(phi), sp = std::sin(phi);
  const double psi =
      spheroid_meridian
          ? spheroid_meridian->psi(theta)
          : detail::MeridianSampling(std::hypot(s.x() * cp, s.y() * sp), s.z(), kTurningWeight).psi(theta);
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
  // Particles: layers x (6 n^2 + 2), counted in 64 bits before any array is sized.
  const double n = spec.face_cells, count = spec.layers * (6.0 * n * n + 2.0);
  detail::check_index_range(count > 9e18 ? std::numeric_limits<std::int64_t>::max() : static_cast<std::int64_t>(count),
                            "make_shell");
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
    const detail::MeridianSampling meridian(axes.x(), axes.z(), kTurningWeight);
    for (const Vec3& d : sphere.directions) {
      cloud.X.push_back(spec.center + on_ellipsoid(axes, d, spheroid ? &meridian : nullptr));
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
