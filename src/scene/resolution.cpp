#include "rkpm/scene/resolution.hpp"

#include <algorithm>
#include <cmath>

namespace rkpm::scene {
namespace {

std::int64_t scaled(std::int64_t cells, double factor, std::int64_t smallest) {
  return std::max(smallest, static_cast<std::int64_t>(std::lround(static_cast<double>(cells) * factor)));
}

void rescale_cloud(ParamSet& cloud, double factor) {
  const std::string generator = cloud.choice("generator");
  const int line = cloud.table_line();
  if (generator == "block") {
    Int3 cells = cloud.int3("cells");
    for (auto& c : cells) c = scaled(c, factor, 1);
    cloud.set("cells", cells, line, true);
  } else if (generator == "sphere") {
    cloud.set("cells", scaled(cloud.integer("cells"), factor, 2), line, true);
  } else if (generator == "shell") {
    cloud.set("face_cells", scaled(cloud.integer("face_cells"), factor, 2), line, true);
  }
}

}  // namespace

Scene at_resolution(const Scene& scene, double factor) {
  Scene level = scene;
  for (auto& body : level.bodies) rescale_cloud(body.cloud, factor);
  level.integrator.set("nested_levels", std::vector<double>{}, level.integrator.table_line(), false);
  return level;
}

}  // namespace rkpm::scene
