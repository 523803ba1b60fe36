#include "lame_study.hpp"

#include "elastic_stiffness.hpp"
#include "rigid_modes.hpp"

#include "rkpm/particles/generators.hpp"
#include "rkpm/rk/nodal_integration.hpp"
#include "rkpm/rk/rk_approximation.hpp"
#include "rkpm/rk/stabilization.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace rkpm::study {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// f_I = sum_p Psi_I(x_p) t_p |A_p| over the quadrature points on the inner surface,
// with the pressure traction t = -p n (n the body's outward normal, pointing to the
// centre there). Exactly self-equilibrated on the faceted surface: sum_p A_p = 0 and
// sum_p x_p x A_p = 0 over a closed polyhedron, and Psi reproduces 1 and x.
Field pressure_load(const particles::Cloud& cloud, const rk::BoundaryQuadrature& q, double pressure) {
  const std::uint32_t inner = cloud.surface_bit("inner");
  if (inner == 0) throw std::runtime_error("pressure_load: the cloud has no surface named 'inner'");
  Field f(cloud.size(), Vec3::Zero());
  for (std::size_t p = 0; p < q.point.size(); ++p) {
    if (!(q.surface_mask[p] & inner)) continue;
    const Vec3 traction_times_area = -pressure * q.area[p];
    for (Index k = q.row_offset[p]; k < q.row_offset[p + 1]; ++k) f[q.col[k]] += q.psi[k] * traction_times_area;
  }
  return f;
}

// u_h(X_J) = sum_I Psi_I(X_J) d_I.
Field interpolate(const rk::NodalInterpolation& N, const Field& d) {
  const auto n = static_cast<Index>(d.size());
  Field u(d.size());
#pragma omp parallel for schedule(static)
  for (Index j = 0; j < n; ++j) u[j] = rk::interpolate(N, d, j);
  return u;
}

}  // namespace

std::string scheme_name(Scheme s) {
  switch (s) {
    case Scheme::StabilizedSCNI: return "scni-stabilized";
    case Scheme::SCNI: return "scni";
    case Scheme::Direct: return "direct";
  }
  return "?";
}

Scheme parse_scheme(const std::string& name) {
  for (Scheme s : {Scheme::StabilizedSCNI, Scheme::SCNI, Scheme::Direct})
    if (scheme_name(s) == name) return s;
  throw std::invalid_argument("unknown scheme '" + name + "', expected scni-stabilized, scni or direct");
}

CaseResult run_lame_case(Scheme scheme, Resolution resolution, const CaseSettings& settings) {
  const LameSphere& lame = settings.problem;
  particles::ShellSpec spec;
  spec.center = Vec3::Zero();
  spec.semi_axes = Vec3::Constant(lame.b);
  spec.thickness = lame.b - lame.a;
  spec.face_cells = resolution.face_cells;
  spec.layers = resolution.layers;
  const particles::Cloud cloud = particles::make_shell(spec);
  const IsotropicElasticity material = IsotropicElasticity::from_young_poisson(lame.E, lame.nu);

  CaseResult result;
  result.scheme = scheme;
  result.resolution = resolution;
  result.particles = cloud.size();
  double volume = 0.0;
  for (double v : cloud.volume) volume += v;
  result.h = std::cbrt(volume / static_cast<double>(cloud.size()));

  const auto setup_start = std::chrono::steady_clock::now();
  rk::RKSettings rk_settings;
  rk_settings.support = settings.support;
  rk_settings.shape = settings.support_shape;
  const rk::RKApproximation rk(cloud, rk_settings);
  const rk::GradientOperator gradient = rk::build_gradient_operator(
      cloud, rk, scheme == Scheme::Direct ? rk::Integration::Direct : rk::Integration::SCNI,
      settings.gradient_precision, {}, settings.cell_quadrature);
  const rk::BoundaryQuadrature boundary = rk::build_boundary_quadrature(cloud, rk, 0u, settings.cell_quadrature);
  const rk::NodalInterpolation interpolation = rk::build_nodal_interpolation(cloud, rk);
  const double alpha = scheme == Scheme::StabilizedSCNI ? settings.alpha : 0.0;
  rk::Stabilization stabilization =
      rk::build_stabilization(cloud.volume, std::vector<double>(cloud.size(), material.mu), alpha);
  ElasticStiffness K(gradient, interpolation, stabilization, material);
  const RigidModes euclidean_rigid(cloud.X, std::vector<double>(cloud.size(), 1.0));
  const Field load = pressure_load(cloud, boundary, lame.p);
  result.setup_seconds = seconds_since(setup_start);

  const auto solve_start = std::chrono::steady_clock::now();
  Field d;
  result.solver = solve_projected_cg(K, euclidean_rigid, load, d, settings.solver);
  result.solve_seconds = seconds_since(solve_start);

  // The solution is fixed only up to a rigid motion. The exact field has none in the
  // volume-weighted sense (radial, and the cloud has the cube's symmetry), so compare
  // the representative whose interpolated displacement has none either. Psi
  // reproduces linear fields, so removing the motion from d removes it from u_h.
  Field u = interpolate(interpolation, d);
  const RigidModes weighted_rigid(cloud.X, cloud.volume);
  const Field motion = weighted_rigid.fit(u);
  for (std::size_t i = 0; i < d.size(); ++i) {
    d[i] -= motion[i];
    u[i] -= motion[i];
  }

  double l2_num = 0.0, l2_den = 0.0;
  for (std::size_t L = 0; L < cloud.size(); ++L) {
    const Vec3 exact = lame.displacement(cloud.X[L]);
    l2_num += cloud.volume[L] * (u[L] - exact).squaredNorm();
    l2_den += cloud.volume[L] * exact.squaredNorm();
  }
  std::vector<Mat3> eps;
  K.strains(d, eps);
  double en_num = 0.0, en_den = 0.0, strain_energy = 0.0;
  for (std::size_t L = 0; L < eps.size(); ++L) {
    const Mat3 exact = lame.strain(cloud.X[L]);
    en_num += gradient.weight[L] * material.energy_product(eps[L] - exact);
    en_den += gradient.weight[L] * material.energy_product(exact);
    strain_energy += 0.5 * gradient.weight[L] * material.energy_product(eps[L]);
  }
  result.l2_error = std::sqrt(l2_num / l2_den);
  result.energy_error = std::sqrt(en_num / en_den);
  if (stabilization.active()) {
    Field scratch(d.size(), Vec3::Zero());
    const double stabilization_energy = rk::add_stabilization_forces(interpolation, stabilization, d, scratch);
    result.stabilization_energy_fraction = stabilization_energy / strain_energy;
  }
  return result;
}

}  // namespace rkpm::study
