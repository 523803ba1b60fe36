// A neo-Hookean body's parameters from its [body.material] table (compiled into rkpm_sim).
#include "materials/neo_hookean/body_material.hpp"

#include "materials/catalog.hpp"
#include "materials/neo_hookean/settings.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/body.hpp"

namespace rkpm::materials::neo_hookean {

std::string build(const scene::BodySpec& spec, sim::Body& body) {
  BodyMaterial material;
  material.model = settings_table().read(spec.material);
  material.model.validate();
  body.material = std::move(material);
  return {};
}

}  // namespace rkpm::materials::neo_hookean
