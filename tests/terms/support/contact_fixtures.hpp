// Shared helpers of the contact and surface-tension tests: bodies made of bare
// particles (positions, volumes, masses: all the contact term reads), worlds built
// from inline scene text, and a deterministic random generator.
#pragma once

#include "rkpm/common/split_mix64.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rkpm::sim::testing {

// A body of particles at X (x = X, d = 0) with the given reference volumes and
// density, a uniform Mooney-Rivlin material (shear modulus 2 (c1 + c2)) and no RK
// operators: enough for terms that act on positions only.
std::unique_ptr<Body> particle_body(const std::string& name, const std::vector<Vec3>& X,
                                    const std::vector<double>& volume, double density = 1.0);

// Sets x = X + d after the test changed d.
void move_to(Body& body, const std::vector<Vec3>& d);

// A world built from scene text (parse, validate, build).
struct BuiltWorld {
  scene::Scene scene;
  std::unique_ptr<World> world;
};
BuiltWorld world_from_text(const std::string& toml);

// Random numbers uniform in [-1, 1), the same on every platform.
struct Random {
  explicit Random(std::uint64_t seed) : generator(seed) {}
  double uniform() { return generator.symmetric_unit(); }
  Vec3 vector() { return Vec3(uniform(), uniform(), uniform()); }
  SplitMix64 generator;
};

}  // namespace rkpm::sim::testing
