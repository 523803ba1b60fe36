// The worlds the step benchmarks run on, each built once per program (lazily, so a
// filtered run builds only what it measures) and advanced a few steps so that the
// state is not the trivial reference one (stress, director rates, contact pairs).
#pragma once

#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/world.hpp"

#include <memory>
#include <stdexcept>
#include <string>

namespace rkpm::bench {

struct SceneFixture {
  scene::Scene scene;
  std::unique_ptr<sim::World> world;
  std::unique_ptr<sim::Integrator> integrator;
  double setup_seconds = 0.0;  // build_world + Integrator::initialize

  sim::Body& body(const std::string& name) const;
  template <class T>
  T& term() const;  // the first term of type T; throws if the scene has none
};

// Mooney-Rivlin cube, about 30k particles (bench/common/scenes.hpp).
SceneFixture& block_fixture();
// examples/rbc/rbc.toml as it is: the 30,730-particle LCE shell (Frank term, volume constraint).
SceneFixture& rbc_fixture();
// examples/adhesion/adhesion.toml as it is: LCE sphere on a Mooney-Rivlin block.
SceneFixture& adhesion_fixture();
// LCE sphere with surface tension, about 30k particles.
SceneFixture& tension_fixture();

template <class T>
T& SceneFixture::term() const {
  for (const auto& t : world->terms)
    if (auto* found = dynamic_cast<T*>(t.get())) return *found;
  throw std::logic_error("the benchmark's scene lacks the term it measures");
}

}  // namespace rkpm::bench
