#include "footprint.hpp"

#include <variant>

namespace rkpm::bench {

namespace {

template <class T>
std::size_t bytes(const std::vector<T>& v) {
  return v.size() * sizeof(T);
}

std::size_t gradient_bytes(const rk::GradientOperator& g) {
  return bytes(g.row_offset) + bytes(g.col) + bytes(g.grad) + bytes(g.grad_float) + bytes(g.weight);
}

// The rows of Psi_I(X_L): all that is stored (transposed products are scattered from
// them) and all the stabilization reads.
std::size_t interpolation_bytes(const rk::NodalInterpolation& n) {
  return bytes(n.row_offset) + bytes(n.col) + bytes(n.psi);
}

std::size_t material_bytes(const sim::Material& material) {
  return std::visit([](const auto& m) { return m.state_bytes(); }, material);
}

template <class Measure>
auto sum_over_bodies(const sim::World& world, Measure measure) {
  decltype(measure(*world.bodies.front())) sum{};
  for (const auto& b : world.bodies) sum += measure(*b);
  return sum;
}

}  // namespace

Footprint footprint(const sim::Body& b) {
  Footprint f;
  f.operators = gradient_bytes(b.gradient) + interpolation_bytes(b.interpolation);
  f.state = bytes(b.d) + bytes(b.v) + bytes(b.force) + bytes(b.F) +
            bytes(b.mass) + bytes(b.inertia) + bytes(b.spacing) + bytes(b.stabilization.weight) +
            material_bytes(b.material) + b.force_scatter.bytes() + b.point_force_scatter.bytes();
  if (materials::lce::material_of(b)) {
    const auto& d = materials::lce::material_of(b)->director;
    f.state += bytes(d.h) + bytes(d.h0) + bytes(d.grad_h) + bytes(d.frank_flux) + bytes(d.frank_divergence) +
               bytes(d.rate) + bytes(d.F_start) + bytes(d.normals);
  }
  const auto& c = b.cloud;
  f.cloud = bytes(c.X) + bytes(c.volume) + bytes(c.mesh.type) + bytes(c.mesh.offset) + bytes(c.mesh.nodes) +
            bytes(c.boundary_faces) + bytes(c.boundary_particles) + bytes(c.boundary_normal) +
            bytes(c.boundary_area) + bytes(c.boundary_index) + bytes(c.surface_mask);
  return f;
}

Footprint footprint(const sim::World& world) {
  return sum_over_bodies(world, [](const sim::Body& b) { return footprint(b); });
}

Traffic internal_force_traffic(const sim::Body& b) {
  Traffic t;
  // F_L = sum_I x_I (x) b_I(X_L) and f_I = sum_L V_L P_L b_I(X_L): the operator's rows,
  // each array once. Scatter buffers are the kernel's own scratch, not compulsory traffic.
  // F reads d (single storage, relative form) or X and d (double storage).
  t.operators = gradient_bytes(b.gradient);
  t.state_read = bytes(b.d) + (b.gradient.single_precision() ? 0 : bytes(b.cloud.X));
  t.state_written = bytes(b.F) + bytes(b.force);
  t.state_read += material_bytes(b.material);
  if (materials::lce::material_of(b)) {
    const auto& d = materials::lce::material_of(b)->director;
    t.state_read += bytes(d.h) + bytes(d.h0);
    if (d.frank) {
      // Grad h (a gather like F), the Frank flux, and its divergence at the particles
      // (a transposed product, divided by the particle volumes).
      t.state_written += bytes(d.grad_h) + bytes(d.frank_flux) + bytes(d.frank_divergence);
      t.state_read += bytes(b.cloud.volume);
    }
  }
  if (b.stabilization.active()) {
    // r = (I - N) d, then f -= (I - N)^T W r, both from the rows of N; d is counted
    // once, with F's gather.
    t.operators += interpolation_bytes(b.interpolation) + bytes(b.stabilization.weight);
  }
  return t;
}

Traffic internal_force_traffic(const sim::World& world) {
  return sum_over_bodies(world, [](const sim::Body& b) { return internal_force_traffic(b); });
}

double internal_force_pair_updates(const sim::Body& b) {
  double entries = 2.0 * static_cast<double>(b.gradient.col.size());
  if (materials::lce::material_of(b) && materials::lce::material_of(b)->director.frank) entries *= 2.0;  // Grad h and the flux divergence: two more passes
  if (b.stabilization.active()) entries += 2.0 * static_cast<double>(b.interpolation.col.size());
  return entries;
}

double internal_force_flops(const sim::Body& b) {
  constexpr double kGatherPerEntry = 21, kScatterPerEntry = 21, kResidualPerEntry = 10, kStabilizationScatter = 6;
  // Per row: I + Grad u (9); per scatter w M (9), (w M) sum_k b~_k (15), added at L (3);
  // per stabilized row W_L r_L (3) and its share at L (6).
  constexpr double kIdentity = 9, kScatterPerRow = 27, kStabilizationPerRow = 9;
  const auto* lce = materials::lce::material_of(b);
  const bool frank = lce && lce->director.frank;
  const double fields = frank ? 2.0 : 1.0;  // F, and Grad h with the Frank term
  const double entries = static_cast<double>(b.gradient.col.size());
  const double rows = b.gradient.row_offset.empty() ? 0.0 : static_cast<double>(b.gradient.row_offset.size() - 1);
  double flops = entries * fields * (kGatherPerEntry + kScatterPerEntry) + rows * (kIdentity + fields * kScatterPerRow);
  if (b.stabilization.active())
    flops += static_cast<double>(b.interpolation.col.size()) * (kResidualPerEntry + kStabilizationScatter) +
             rows * kStabilizationPerRow;
  return flops;
}

double internal_force_flops(const sim::World& world) {
  return sum_over_bodies(world, [](const sim::Body& b) { return internal_force_flops(b); });
}

}  // namespace rkpm::bench
