#include "rkpm/particles/generators.hpp"

#include "rkpm/common/split_mix64.hpp"
#include "structured_grid.hpp"

#include <sstream>

namespace rkpm::particles {

Cloud make_block(const BlockSpec& spec) {
  const auto& c = spec.cells;
  if (c[0] < 1 || c[1] < 1 || c[2] < 1) {
    std::ostringstream msg;
    msg << "make_block: cells = [" << c[0] << ", " << c[1] << ", " << c[2] << "], expected >= 1 per axis";
    throw CloudError(msg.str());
  }
  if (!(spec.size.minCoeff() > 0.0)) {
    throw CloudError("make_block: every component of size must be positive");
  }
  if (!(spec.jitter >= 0.0 && spec.jitter <= 0.3)) {
    throw CloudError("make_block: jitter = " + std::to_string(spec.jitter) + ", expected a value in [0, 0.3]");
  }

  const detail::StructuredGrid grid{c};
  grid.check("make_block");
  const Vec3 h = spec.size.cwiseQuotient(Vec3(c[0], c[1], c[2]));
  SplitMix64 rng(spec.seed);

  Cloud cloud;
  cloud.name = "block";
  cloud.surface_names = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  cloud.X.resize(grid.n_nodes());
  cloud.surface_mask.assign(grid.n_nodes(), 0);
  for (int k = 0; k <= c[2]; ++k) {
    for (int j = 0; j <= c[1]; ++j) {
      for (int i = 0; i <= c[0]; ++i) {
        const int index[3] = {i, j, k};
        const std::int32_t id = grid.node(i, j, k);
        std::uint32_t mask = 0;
        Vec3 x;
        for (int a = 0; a < 3; ++a) {
          // Three draws per node whether used or not, so a node's offset does not
          // depend on how many of its neighbours lie on faces.
          const double u = rng.symmetric_unit();
          const bool at_min = index[a] == 0, at_max = index[a] == c[a];
          if (at_min) mask |= 1u << (2 * a);
          if (at_max) mask |= 1u << (2 * a + 1);
          // A boundary particle moves only within its face, never across it.
          const double offset = at_min || at_max ? 0.0 : spec.jitter * h[a] * u;
          x[a] = at_max ? spec.origin[a] + spec.size[a] : spec.origin[a] + index[a] * h[a] + offset;
        }
        cloud.X[id] = x;
        cloud.surface_mask[id] = mask;
      }
    }
  }
  grid.add_hexahedra(cloud.mesh);
  finalize_cloud(cloud);
  return cloud;
}

}  // namespace rkpm::particles
