// An LCE body's material from its [body.material] and [body.director] tables (compiled
// into rkpm_sim): the model's parameters, the director field with the Frank term's
// arrays, and the activity.
#include "materials/lce/body_material.hpp"

#include "clouds/catalog.hpp"
#include "materials/catalog.hpp"
#include "materials/lce/body_material_activity.hpp"
#include "materials/lce/initial_director.hpp"
#include "materials/lce/settings.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/body.hpp"

namespace rkpm::materials::lce {

std::string build(const scene::BodySpec& spec, sim::Body& body) {
  const Settings s = settings_table().read(spec.material);
  BodyMaterial material;
  auto& model = material.model;
  model.mu = s.mu;
  model.K = s.bulk;
  model.s = s.s;
  model.kappa = s.kappa;
  model.mobility = s.mobility;
  model.zeta = s.zeta;
  model.validate();

  std::string warning;
  DirectorField& dir = material.director;
  dir = initial_director(spec, body, warning);
  // The Frank term (kappa > 0) needs Grad_X h, its flux and the flux's divergence.
  const std::size_t n = body.size();
  dir.frank = model.kappa > 0.0;
  if (dir.frank) {
    dir.grad_h.assign(n, Mat3::Zero());
    dir.frank_flux.assign(n, Mat3::Zero());
    dir.frank_divergence.assign(n, Vec3::Zero());
  }
  const double wall_thickness = clouds::wall_thickness(spec);
  material.activity = activity_field(s, spec.material, body, dir.h0, wall_thickness, model.zeta);
  body.material = std::move(material);
  return warning;
}

}  // namespace rkpm::materials::lce
