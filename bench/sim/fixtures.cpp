#include "fixtures.hpp"

#include "../common/scenes.hpp"
#include "rkpm/sim/build.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>

namespace rkpm::bench {

namespace {

// Steps taken after initialize(): enough for non-zero velocities and director rates.
constexpr int kWarmSteps = 3;

std::unique_ptr<SceneFixture> build(scene::Scene scene, const char* label) {
  const auto start = std::chrono::steady_clock::now();
  auto f = std::make_unique<SceneFixture>();
  f->scene = std::move(scene);
  f->world = sim::build_world(f->scene);
  f->integrator = std::make_unique<sim::Integrator>(*f->world, sim::integrator_settings(f->scene));
  f->integrator->initialize();
  f->setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (int i = 0; i < kWarmSteps; ++i) f->integrator->step();
  // On stderr, so that CSV on stdout stays clean.
  fmt::print(stderr, "fixture {}: {} particles, set-up {:.1f} s\n", label, f->world->particle_count(),
             f->setup_seconds);
  return f;
}

}  // namespace

sim::Body& SceneFixture::body(const std::string& name) const {
  sim::Body* b = world->find_body(name);
  if (!b) throw std::logic_error("the scene has no body '" + name + "'");
  return *b;
}

SceneFixture& block_fixture() {
  static auto f = build(make_scene(Geometry::Block, resolution_for(Geometry::Block, 3e4), ""), "block");
  return *f;
}

SceneFixture& rbc_fixture() {
  static auto f = build(scene::load_scene(source_file("examples/rbc/rbc.toml")), "rbc");
  return *f;
}

SceneFixture& adhesion_fixture() {
  static auto f = build(scene::load_scene(source_file("examples/adhesion/adhesion.toml")), "adhesion");
  return *f;
}

SceneFixture& tension_fixture() {
  static auto f = build(make_scene(Geometry::Sphere, resolution_for(Geometry::Sphere, 3e4), ""), "tension sphere");
  return *f;
}

}  // namespace rkpm::bench
