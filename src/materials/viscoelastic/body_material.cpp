// A viscoelastic body's material from its [body.material] table (compiled into rkpm_sim).
#include "materials/viscoelastic/body_material.hpp"

#include "materials/catalog.hpp"
#include "materials/viscoelastic/settings.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/body.hpp"

namespace rkpm::materials::viscoelastic {

std::string build(const scene::BodySpec& spec, sim::Body& body) {
  const Settings s = settings_table().read(spec.material);
  BodyMaterial material;
  material.model.equilibrium.mu = s.mu;
  material.model.equilibrium.lambda = s.lambda;
  material.model.branch_count = static_cast<int>(s.beta.size());
  for (std::size_t i = 0; i < s.beta.size(); ++i) material.model.branches[i] = {s.beta[i], s.tau[i]};
  material.model.validate();
  // Every point starts unstrained in every branch (Cv = I): the reference state is
  // stress-free, and an initial stretch of the scene loads the branches as a step strain.
  material.state.assign(body.size(), ViscousState::reference());
  body.material = std::move(material);
  return {};
}

}  // namespace rkpm::materials::viscoelastic
