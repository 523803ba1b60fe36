// The initial director of an LCE body (Eq. 8 and the text around it).
#pragma once

#include "materials/lce/director_field.hpp"

#include <string>

namespace rkpm::scene {
struct BodySpec;
}
namespace rkpm::sim {
struct Body;
}

namespace rkpm::materials::lce {

// From the body's [body.director] table (spec.material_section("director")): h = h0 per particle, the
// evolve and anchoring flags, and the per-step arrays sized. `body` must have its cloud
// (and, distributed, its original ids). `warning` receives a note for the run log when
// the surface-normal choice is ambiguous somewhere.
DirectorField initial_director(const scene::BodySpec& spec, const sim::Body& body, std::string& warning);

}  // namespace rkpm::materials::lce
