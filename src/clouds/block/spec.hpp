// generator = "block": the generator's argument from a validated [body.cloud] table.
#pragma once

#include "clouds/catalog.hpp"
#include "rkpm/particles/generators.hpp"

namespace rkpm::clouds::block {
particles::BlockSpec spec(const scene::BodySpec& body);
}
