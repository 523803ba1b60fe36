#include "rkpm/scene/resolution.hpp"

#include "clouds/catalog.hpp"

namespace rkpm::scene {

Scene at_resolution(const Scene& scene, double factor) {
  Scene level = scene;
  for (auto& body : level.bodies) clouds::rescale_cloud(body.cloud, factor);
  level.integrator.set("nested_levels", std::vector<double>{}, level.integrator.table_line(), false);
  return level;
}

}  // namespace rkpm::scene
