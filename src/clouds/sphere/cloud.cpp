// generator = "sphere": the cloud and its size (compiled into rkpm_sim).
#include "clouds/sphere/spec.hpp"

#include "rkpm/scene/scene.hpp"

namespace rkpm::clouds::sphere {

particles::Cloud make(const scene::BodySpec& body) { return particles::make_sphere(spec(body)); }

CloudSize estimate(const scene::BodySpec& body) {
  const particles::SphereSpec s = spec(body);
  const auto n = static_cast<double>(s.cells);
  const double d = 2.0 * s.radius;
  CloudSize e;
  e.particles = (n + 1.0) * (n + 1.0) * (n + 1.0);
  e.elements = n * n * n;
  e.spacing = Vec3::Constant(d / n);
  e.extent = Vec3::Constant(d);
  // The cube-to-ball map stretches the cells near the cube's corners.
  e.longest_edge = 1.2 * d / n;
  e.size_key = key_at(body.cloud, "cells");
  return e;
}

}  // namespace rkpm::clouds::sphere
