// generator = "sphere": the generator's argument from a validated [body.cloud] table.
#pragma once

#include "clouds/catalog.hpp"
#include "rkpm/particles/generators.hpp"

namespace rkpm::clouds::sphere {
particles::SphereSpec spec(const scene::BodySpec& body);
}
