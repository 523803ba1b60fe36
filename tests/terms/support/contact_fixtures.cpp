#include "contact_fixtures.hpp"

#include "rkpm/sim/build.hpp"

namespace rkpm::sim::testing {

std::unique_ptr<Body> particle_body(const std::string& name, const std::vector<Vec3>& X,
                                    const std::vector<double>& volume, double density) {
  auto body = std::make_unique<Body>();
  body->name = name;
  body->density = density;
  body->cloud.name = name;
  body->cloud.X = X;
  body->cloud.volume = volume;
  const std::size_t n = X.size();
  body->mass.resize(n);
  for (std::size_t i = 0; i < n; ++i) body->mass[i] = density * volume[i];
  body->inertia = body->mass;
  body->d.assign(n, Vec3::Zero());
  body->v.assign(n, Vec3::Zero());
  body->force.assign(n, Vec3::Zero());
  materials::MooneyRivlin mr;
  mr.c1 = 400.0;
  mr.c2 = 100.0;
  mr.lambda = 2000.0;
  materials::mooney_rivlin::BodyMaterial material;
  material.at_point.assign(n, mr);
  body->material = std::move(material);
  return body;
}

void move_to(Body& body, const std::vector<Vec3>& d) { body.d = d; }

BuiltWorld world_from_text(const std::string& toml) {
  BuiltWorld w;
  w.scene = scene::parse_scene(toml, "test.toml");
  w.world = build_world(w.scene);
  return w;
}

}  // namespace rkpm::sim::testing
