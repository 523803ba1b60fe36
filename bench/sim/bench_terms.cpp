// Physics terms: the adhesion scene's contact (pair-list rebuild and force
// evaluation separately) and surface tension on a sphere.
#include "counters.hpp"
#include "fixtures.hpp"

#include "rkpm/sim/body.hpp"
#include "terms/contact/contact.hpp"
#include "terms/surface_tension/surface_tension.hpp"

#include <algorithm>
#include <vector>

namespace rkpm::bench {

namespace {

// The physical positions X + u(X) the contact term pairs (contact.hpp).
std::vector<Vec3> physical_positions(const sim::Body& body) {
  std::vector<Vec3> u;
  sim::physical_displacement(body, u);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] += body.cloud.X[i];
  return u;
}

// A kd-tree over the substrate and a radius query (cutoff + skin) per cell particle:
// what the Verlet list costs each time a particle has moved skin/2. Built with the
// term's own cutoff and skin on a list of our own, since the term's is private.
void BM_ContactPairRebuild_Adhesion(benchmark::State& state) {
  SceneFixture& f = adhesion_fixture();
  const auto& term = f.term<sim::Contact>();
  const std::vector<Vec3> xa = physical_positions(f.body("cell"));
  const std::vector<Vec3> xb = physical_positions(f.body("substrate"));
  sim::ContactPairs pairs(term.pairs().cutoff(), term.pairs().skin());
  for (auto _ : state) {
    pairs.rebuild(xa, xb);
    benchmark::DoNotOptimize(pairs.partner().data());
  }
  set_counters(state, static_cast<double>(xa.size() + xb.size()), static_cast<double>(pairs.size()),
               bytes_per_particle(*f.world));
  state.counters["listed_pairs"] = static_cast<double>(pairs.size());
}
BENCHMARK(BM_ContactPairRebuild_Adhesion)->Unit(benchmark::kMillisecond)->UseRealTime();

// Contact::add_forces at fixed positions: the list stays valid, so this is the
// movement check (no rebuild), the physical positions of both bodies, the pair
// forces over the list and their transfer to the generalized coordinates.
void BM_ContactForces_Adhesion(benchmark::State& state) {
  SceneFixture& f = adhesion_fixture();
  auto& term = f.term<sim::Contact>();
  term.add_forces(*f.world);  // (re)build the list outside the timed loop
  const std::size_t builds = term.pairs().builds();
  for (auto _ : state) {
    term.add_forces(*f.world);
    benchmark::ClobberMemory();
  }
  if (term.pairs().builds() != builds) state.SkipWithError("the pair list was rebuilt inside the timed loop");
  sim::compute_forces(*f.world);  // the forces accumulated: restore the world's
  set_counters(state, static_cast<double>(f.world->particle_count()), static_cast<double>(term.pairs().size()),
               bytes_per_particle(*f.world));
  state.counters["listed_pairs"] = static_cast<double>(term.pairs().size());
  state.counters["active_pairs"] = static_cast<double>(term.active_pairs());
}
BENCHMARK(BM_ContactForces_Adhesion)->Unit(benchmark::kMillisecond)->UseRealTime();

// SurfaceTension::add_forces on every boundary face of an LCE sphere: physical
// positions of the face nodes, area gradients, transfer through Psi^T.
void BM_SurfaceTension_Sphere(benchmark::State& state) {
  SceneFixture& f = tension_fixture();
  auto& term = f.term<sim::SurfaceTension>();
  const sim::Body& body = f.body("cell");
  // Interpolation entries of the face nodes, read once for the positions and once
  // for the force transfer.
  std::vector<char> on_face(body.size(), 0);
  for (const auto& face : body.cloud.boundary_faces)
    for (int k = 0; k < face.n_nodes; ++k) on_face[face.nodes[k]] = 1;
  double entries = 0.0;
  const auto& N = body.interpolation;
  for (std::size_t j = 0; j < body.size(); ++j)
    if (on_face[j]) entries += 2.0 * (N.row_offset[j + 1] - N.row_offset[j]);
  for (auto _ : state) {
    term.add_forces(*f.world);
    benchmark::ClobberMemory();
  }
  sim::compute_forces(*f.world);
  set_counters(state, static_cast<double>(std::count(on_face.begin(), on_face.end(), 1)), entries,
               bytes_per_particle(*f.world));
  state.counters["faces"] = static_cast<double>(body.cloud.boundary_faces.size());
}
BENCHMARK(BM_SurfaceTension_Sphere)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

}  // namespace rkpm::bench
