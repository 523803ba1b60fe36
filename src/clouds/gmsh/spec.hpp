// generator = "gmsh": the importer's argument from a validated [body.cloud] table.
#pragma once

#include "clouds/catalog.hpp"
#include "rkpm/particles/generators.hpp"

namespace rkpm::clouds::gmsh {
particles::GmshImportSpec spec(const scene::BodySpec& body);
}
