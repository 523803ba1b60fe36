// generator = "shell": the generator's argument from a validated [body.cloud] table.
#pragma once

#include "clouds/catalog.hpp"
#include "rkpm/particles/generators.hpp"

namespace rkpm::clouds::shell {
particles::ShellSpec spec(const scene::BodySpec& body);
}
