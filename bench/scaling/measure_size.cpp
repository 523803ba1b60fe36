#include "measure_size.hpp"

#include "../common/footprint.hpp"
#include "memory.hpp"
#include "rkpm/particles/cloud.hpp"
#include "rkpm/rk/neighbor_search.hpp"
#include "rkpm/sim/build.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace rkpm::scaling {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_of(const std::function<void()>& work) {
  const auto start = Clock::now();
  work();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// build_world's RK stages for every body, timed one by one (2 threads, as the run).
void time_stages(const scene::Scene& scene, SizeResult& r) {
  for (const auto& spec : scene.bodies) {
    particles::Cloud cloud;
    r.cloud_s += seconds_of([&] { cloud = sim::build_cloud(spec); });
    std::unique_ptr<rk::RKApproximation> approx;
    r.tree_s += seconds_of([&] { approx = std::make_unique<rk::RKApproximation>(cloud, sim::rk_settings(spec)); });
    const auto scheme = sim::integration_scheme(spec.rk);
    r.gradient_s += seconds_of([&] {
      (void)rk::build_gradient_operator(cloud, *approx, scheme, sim::gradient_precision(spec.rk), {},
                                        sim::cell_quadrature(spec.rk));
    });
    r.interpolation_s += seconds_of([&] { (void)rk::build_nodal_interpolation(cloud, *approx); });
    r.boundary_s += seconds_of(
        [&] { (void)rk::build_boundary_quadrature(cloud, *approx, 0u, sim::cell_quadrature(spec.rk)); });
    // The neighbour search inside the interpolation build, bounded from above: the same
    // queries with the cloud's largest support radius around each point (the build
    // itself queries the largest support near the point, rk/support_bound.hpp), on a
    // tree of our own (its build not timed).
    const rk::NeighborSearch search(cloud.X);
    const double radius = *std::max_element(approx->support_radius().begin(), approx->support_radius().end());
    const auto n = static_cast<Index>(cloud.size());
    std::size_t found_total = 0;
    r.query_s += seconds_of([&] {
#pragma omp parallel reduction(+ : found_total)
      {
        std::vector<std::pair<Index, double>> found;
#pragma omp for schedule(dynamic, 64)
        for (Index i = 0; i < n; ++i) {
          search.query(cloud.X[i], radius, found);
          found_total += found.size();
        }
      }
    });
    if (found_total == 0) r.note += "(no neighbours found?) ";
  }
}

// The row-length distribution of the built operators (support sizes made visible).
void record_row_lengths(const sim::World& world, SizeResult& r) {
  std::vector<double> lengths;
  double interpolation_entries = 0, rows = 0;
  for (const auto& body : world.bodies) {
    const auto& off = body->gradient.row_offset;
    for (std::size_t L = 0; L + 1 < off.size(); ++L) lengths.push_back(off[L + 1] - off[L]);
    interpolation_entries += static_cast<double>(body->interpolation.col.size());
    rows += static_cast<double>(body->interpolation.row_offset.empty() ? 0 : body->interpolation.row_offset.size() - 1);
  }
  if (lengths.empty()) return;
  std::sort(lengths.begin(), lengths.end());
  double sum = 0;
  for (double l : lengths) sum += l;
  r.gradient_row_mean = sum / static_cast<double>(lengths.size());
  r.gradient_row_p95 = lengths[static_cast<std::size_t>(0.95 * static_cast<double>(lengths.size() - 1))];
  r.gradient_row_max = lengths.back();
  r.interpolation_row_mean = rows > 0 ? interpolation_entries / rows : 0.0;
}

}  // namespace

SizeResult measure_size(bench::Geometry geometry, int resolution, const MeasureSettings& settings) {
  SizeResult r;
  r.geometry = bench::geometry_name(geometry);
  r.resolution = resolution;
  // Everything after this point is the size's own memory: scene, world, scratch.
  r.baseline_bytes = static_cast<double>(peak_rss_bytes());
  const scene::Scene scene = bench::make_scene(geometry, resolution, settings.rbc_scene, settings.rk);

  omp_set_num_threads(2);
  {
    std::unique_ptr<sim::World> world;
    r.setup_s = seconds_of([&] { world = sim::build_world(scene); });
    sim::Integrator integrator(*world, sim::integrator_settings(scene));
    r.init_s = seconds_of([&] { integrator.initialize(); });
    r.particles = static_cast<double>(world->particle_count());
    // A child asked for the set-up alone (no steps: the study's repeated set-ups) stops here.
    if (settings.steps == 0 && settings.steps_1t == 0 && settings.warmup == 0) return r;
    const bench::Footprint fp = bench::footprint(*world);
    r.operators_bytes = static_cast<double>(fp.operators);
    r.state_bytes = static_cast<double>(fp.state);
    r.cloud_bytes = static_cast<double>(fp.cloud);
    r.traffic_bytes = static_cast<double>(bench::internal_force_traffic(*world).total());
    r.force_flops = bench::internal_force_flops(*world);
    record_row_lengths(*world, r);

    const auto timed_steps = [&](int threads, int warmup, int count) {
      omp_set_num_threads(threads);
      for (int i = 0; i < warmup; ++i) integrator.step();
      std::vector<double> t;
      for (int i = 0; i < count; ++i) t.push_back(seconds_of([&] { integrator.step(); }));
      return median(t);
    };
    r.step_2t_s = timed_steps(2, settings.warmup, settings.steps);
    r.step_1t_s = timed_steps(1, 1, settings.steps_1t);
    r.steps_timed = settings.steps;

    // The internal force alone, after the steps (it leaves Body::force without the
    // terms' share, which the integrator would otherwise read). One untimed pass each.
    const auto timed_force = [&](int threads, int count) {
      omp_set_num_threads(threads);
      std::vector<double> t;
      for (int i = 0; i <= count; ++i) {
        const double s = seconds_of([&] {
          for (auto& b : world->bodies) sim::compute_internal_forces(*b);
        });
        if (i > 0) t.push_back(s);
      }
      return median(t);
    };
    r.force_2t_s = timed_force(2, settings.steps);
    r.force_1t_s = timed_force(1, settings.steps_1t);

    r.peak_bytes = static_cast<double>(peak_rss_bytes()) - r.baseline_bytes;
  }  // the world is freed before the stages are built again

  if (settings.split) {
    omp_set_num_threads(2);
    time_stages(scene, r);
  }
  return r;
}

}  // namespace rkpm::scaling
