// The initial director field of an LCE body from its [body.director] table (compiled
// into rkpm_sim).
#include "materials/lce/initial_director.hpp"

#include "rkpm/rk/neighbor_search.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/body.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace rkpm::materials::lce {

// Initial director (Eq. 8 and the text around it): the outward normal of the nearest
// surface particle, oriented away from the body's centre so that a shell's wall carries
// the outer normal through its thickness; or radial; or a fixed vector.
// A particle whose nearest surface particles tie (a mirror-symmetric cloud's centre)
// gets the normal of the lowest id among them, an arbitrary choice when their normals
// disagree: `warning` then names the first such particle.
DirectorField initial_director(const scene::BodySpec& spec, const sim::Body& body, std::string& warning) {
  const auto& p = spec.material_section("director");
  const auto& cloud = body.cloud;
  DirectorField dir;
  const std::size_t n = cloud.size();
  dir.h.resize(n);
  const Vec3 centre = sim::reference_centroid(body);
  const std::string initial = p.choice("initial");
  if (initial == "fixed") {
    const Vec3 h = p.vec3("vector").stableNormalized();  // finite for any non-zero components
    std::fill(dir.h.begin(), dir.h.end(), h);
  } else if (initial == "radial") {
    // A particle at the centre gets e_z. "At the centre" allows for the centroid's
    // round-off, which depends on the particle order: a plain r != 0 would give the
    // centre particle a round-off direction that changes with the numbering (Morton
    // order, the partition of a distributed run).
    double extent = 0.0;
    for (std::size_t i = 0; i < n; ++i) extent = std::max(extent, (cloud.X[i] - centre).norm());
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 r = cloud.X[i] - centre;
      dir.h[i] = r.norm() > 1e-9 * extent ? Vec3(r.normalized()) : Vec3::UnitZ();
    }
  } else {
    std::vector<Vec3> surface;
    for (Index b : cloud.boundary_particles) surface.push_back(cloud.X[b]);
    const rk::NeighborSearch search(surface);
    const auto oriented = [&](const Vec3& normal, std::size_t i) {
      return normal.dot(cloud.X[i] - centre) >= 0.0 ? normal : Vec3(-normal);
    };
    std::vector<char> ambiguous(n, 0);
#pragma omp parallel
    {
      std::vector<std::pair<Index, double>> found;
#pragma omp for schedule(static)
      for (std::int64_t k = 0; k < static_cast<std::int64_t>(n); ++k) {
        const auto i = static_cast<std::size_t>(k);
        const auto bi = cloud.boundary_index[i];
        if (bi >= 0) {
          dir.h[i] = oriented(cloud.boundary_normal[bi], i);
          continue;
        }
        // Inside: the normal of the nearest surface particle; among equals (`found` then
        // holds all of them) the lowest id in the one-rank numbering, so that the choice
        // does not depend on how a distributed run renumbered the particles.
        const auto nearest = search.nearest(cloud.X[i], found);
        Index pick = nearest.first;
        const auto id_of = [&](Index b) {
          return sim::one_rank_id(body, static_cast<Index>(cloud.boundary_particles[static_cast<std::size_t>(b)]));
        };
        for (const auto& f : found)
          if (f.second == nearest.second && id_of(f.first) < id_of(pick)) pick = f.first;
        dir.h[i] = oriented(cloud.boundary_normal[pick], i);
        for (const auto& f : found)
          if (oriented(cloud.boundary_normal[f.first], i).dot(dir.h[i]) < 0.5) ambiguous[i] = 1;  // > 60 deg apart
      }
    }
    const auto first = std::find(ambiguous.begin(), ambiguous.end(), 1);
    if (first != ambiguous.end()) {
      const auto i = static_cast<std::size_t>(first - ambiguous.begin());
      warning = fmt::format(
          "{}: body '{}': [body.director] initial = \"surface_normal\": {} particle(s) lie equally near surface "
          "particles whose normals differ by more than 60 deg (first: particle {} at ({:.4g}, {:.4g}, {:.4g}) m, "
          "e.g. the centre of a mirror-symmetric cloud); their director is the normal of the lowest id, an "
          "arbitrary tilt. An odd cell count puts no particle there.",
          spec.body.file(), body.name, std::count(ambiguous.begin(), ambiguous.end(), 1), i, cloud.X[i].x(),
          cloud.X[i].y(), cloud.X[i].z());
    }
  }
  dir.h0 = dir.h;
  dir.evolve = p.flag("evolve");
  dir.anchored = p.choice("boundary") == "normal";
  dir.rate.assign(n, Vec3::Zero());
  dir.F_start.assign(n, Mat3::Identity());
  return dir;
}

}  // namespace rkpm::materials::lce
