// The simulation side of the cloud-generator catalog (compiled into rkpm_sim): the
// cloud a body's [body.cloud] table declares, and its size before it is made.
#include "clouds/catalog.hpp"

#include "rkpm/scene/scene.hpp"

#include <stdexcept>

namespace rkpm::clouds {

particles::Cloud make_cloud(const scene::BodySpec& spec) {
  const std::string& generator = spec.generator();
#define RKPM_CLOUD(entry) \
  if (generator == #entry) return entry::make(spec);
#include "clouds/catalog.def"
#undef RKPM_CLOUD
  throw std::logic_error("generator \"" + generator + "\" is not in the cloud catalog");
}

CloudSize estimate_cloud(const scene::BodySpec& spec) {
  const std::string& generator = spec.generator();
#define RKPM_CLOUD(entry) \
  if (generator == #entry) return entry::estimate(spec);
#include "clouds/catalog.def"
#undef RKPM_CLOUD
  throw std::logic_error("generator \"" + generator + "\" is not in the cloud catalog");
}

}  // namespace rkpm::clouds
