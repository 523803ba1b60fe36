// generator = "shell": the cloud and its size (compiled into rkpm_sim).
#include "clouds/shell/spec.hpp"

#include "rkpm/scene/scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rkpm::clouds::shell {

particles::Cloud make(const scene::BodySpec& body) { return particles::make_shell(spec(body)); }

CloudSize estimate(const scene::BodySpec& body) {
  const particles::ShellSpec s = spec(body);
  const auto n = static_cast<double>(s.face_cells);
  const auto layers = static_cast<double>(s.layers);
  const double per_layer = 6.0 * n * n + 2.0;
  CloudSize e;
  e.particles = layers * per_layer;
  e.elements = 6.0 * n * n * (layers - 1.0);
  const double in_plane = std::sqrt(particles::ellipsoid_area(s.semi_axes) / per_layer);
  const double through = s.thickness / std::max(layers - 1.0, 1.0);
  e.spacing = Vec3(in_plane, in_plane, through);
  e.extent = Vec3(2.0 * s.semi_axes.maxCoeff(), 2.0 * s.semi_axes.maxCoeff(), s.thickness);
  // The cubed sphere's edges near its cube corners are the longest.
  e.longest_edge = std::max(1.4 * in_plane, through);
  e.size_key = fmt::format("{} and layers", key_at(body.cloud, "face_cells"));
  return e;
}

}  // namespace rkpm::clouds::shell
