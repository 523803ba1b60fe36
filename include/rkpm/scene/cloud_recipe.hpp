// Turns a body's validated [body.cloud] table into the argument of the particle
// generator that makes it (rkpm/particles/generators.hpp).
#pragma once

#include "rkpm/particles/generators.hpp"
#include "rkpm/scene/scene.hpp"

#include <string>
#include <variant>

namespace rkpm::scene {

// A cloud read from a .vtu file and scaled about the origin (e.g. 1e-6 for a mesh
// written in micrometres).
struct VtuImport {
  std::string path;   // resolved against the scene file's directory
  double scale = 1.0;
};

using CloudRecipe = std::variant<particles::BlockSpec, particles::SphereSpec, particles::ShellSpec, VtuImport,
                                 particles::GmshImportSpec>;

CloudRecipe cloud_recipe(const BodySpec& body);

}  // namespace rkpm::scene
