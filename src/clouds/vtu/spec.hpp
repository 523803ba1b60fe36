// generator = "vtu": a cloud read from a .vtu file and scaled about the origin (1e-6 for
// a mesh written in micrometres).
#pragma once

#include "clouds/catalog.hpp"

#include <string>

namespace rkpm::clouds::vtu {
struct Import {
  std::string path;   // resolved against the scene file's directory
  double scale = 1.0;
};
Import spec(const scene::BodySpec& body);
}  // namespace rkpm::clouds::vtu
