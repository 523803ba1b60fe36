// generator = "vtu": the cloud and its size (compiled into rkpm_sim).
#include "clouds/vtu/spec.hpp"

#include "rkpm/particles/generators.hpp"
#include "rkpm/scene/scene.hpp"

#include <fmt/format.h>

#include <fstream>
#include <limits>

namespace rkpm::clouds::vtu {

namespace {
// The points a .vtu file declares (its pieces' NumberOfPoints, read from its first
// 64 KiB), without parsing it.
double declared_points(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(1 << 16, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  double total = 0.0;
  const std::string key = "NumberOfPoints=\"";
  for (std::size_t at = head.find(key); at != std::string::npos; at = head.find(key, at + key.size()))
    total += std::strtod(head.c_str() + at + key.size(), nullptr);
  return total;
}
}  // namespace

particles::Cloud make(const scene::BodySpec& body) {
  const Import s = spec(body);
  particles::Cloud c = particles::import_vtu(s.path);
  if (s.scale != 1.0) {
    for (auto& x : c.X) x *= s.scale;
    for (auto& v : c.volume) v *= s.scale * s.scale * s.scale;
    for (auto& a : c.boundary_area) a *= s.scale * s.scale;
  }
  return c;
}

// Its declared points; its spacing is unknown here, so the rows are taken as those of
// a uniform cloud (support^3 (4/3) pi particles).
CloudSize estimate(const scene::BodySpec& body) {
  CloudSize e;
  e.particles = declared_points(body.cloud_file);
  e.elements = e.particles;
  e.extent = Vec3::Constant(std::numeric_limits<double>::infinity());
  e.size_key = fmt::format("{} (\"{}\")", key_at(body.cloud, "file"), body.cloud_file);
  return e;
}

}  // namespace rkpm::clouds::vtu
