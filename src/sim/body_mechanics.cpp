// The per-step mechanics of one body: kinematics, stress and internal force.
#include "rkpm/sim/body.hpp"

#include <algorithm>
#include <limits>

namespace rkpm::sim {

namespace {
template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

materials::DirectorPoint director_at(const DirectorField& dir, std::size_t L) {
  materials::DirectorPoint p;
  p.h = dir.h[L];
  p.h0 = dir.h0[L];
  p.grad_h = dir.frank ? dir.grad_h[L] : Mat3::Zero();
  return p;
}
}  // namespace

void update_positions(Body& body) {
  const auto n = static_cast<Index>(body.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) body.x[i] = body.cloud.X[i] + body.d[i];
}

void compute_internal_forces(Body& body) {
  rk::deformation_gradients(body.gradient, body.x, body.F);
  const auto n = static_cast<Index>(body.F.size());
  std::visit(Overloaded{
                 [&](const MooneyRivlinMaterial& m) {
#pragma omp parallel for schedule(static)
                   for (Index L = 0; L < n; ++L) body.P[L] = m.at_point[L].first_piola(body.F[L]);
                 },
                 [&](const LCEMaterial& m) {
                   DirectorField& dir = *body.director;
                   // Grad_X h = sum_I h_I (x) b_I: the same gather as F, applied to h.
                   if (dir.frank) rk::deformation_gradients(body.gradient, dir.h, dir.grad_h);
#pragma omp parallel for schedule(static)
                   for (Index L = 0; L < n; ++L) {
                     const auto p = director_at(dir, static_cast<std::size_t>(L));
                     if (m.activity.empty()) {
                       body.P[L] = m.model.first_piola(body.F[L], p);
                     } else {
                       body.P[L] = m.model.first_piola_passive(body.F[L], p) +
                                   m.activity[L] * m.model.first_piola_active(body.F[L], p.h);
                     }
                     if (dir.frank) dir.frank_flux[L] = m.model.frank_flux(body.F[L], p);
                   }
                   if (dir.frank) {
                     // Weak form: sum_L V_L flux_L b_I(X_L) = -V_I Div_X(flux)(X_I) away from the surface.
                     rk::internal_forces(body.gradient, dir.frank_flux, dir.frank_divergence);
#pragma omp parallel for schedule(static)
                     for (Index I = 0; I < n; ++I) dir.frank_divergence[I] /= -body.cloud.volume[I];
                   }
                 }},
             body.material);
  rk::internal_forces(body.gradient, body.P, body.force);
  const auto np = static_cast<Index>(body.size());
#pragma omp parallel for schedule(static)
  for (Index I = 0; I < np; ++I) body.force[I] = -body.force[I];
  if (body.stabilization.active())
    body.stabilization_energy = rk::add_stabilization_forces(body.interpolation, body.stabilization, body.d, body.force);
}

double strain_energy(const Body& body) {
  const auto n = static_cast<Index>(body.F.size());
  double total = 0.0;
  std::visit(Overloaded{
                 [&](const MooneyRivlinMaterial& m) {
#pragma omp parallel for schedule(static) reduction(+ : total)
                   for (Index L = 0; L < n; ++L) total += body.gradient.weight[L] * m.at_point[L].energy(body.F[L]);
                 },
                 [&](const LCEMaterial& m) {
#pragma omp parallel for schedule(static) reduction(+ : total)
                   for (Index L = 0; L < n; ++L)
                     total += body.gradient.weight[L] *
                              m.model.energy(body.F[L], director_at(*body.director, static_cast<std::size_t>(L)));
                 }},
             body.material);
  return total + body.stabilization_energy;
}

void physical_displacement(const Body& body, std::vector<Vec3>& u) {
  const auto& N = body.interpolation;
  const auto n = static_cast<Index>(body.size());
  u.resize(body.size());
#pragma omp parallel for schedule(static)
  for (Index J = 0; J < n; ++J) {
    Vec3 s = Vec3::Zero();
    for (Index k = N.row_offset[J]; k < N.row_offset[J + 1]; ++k) s += N.psi[k] * body.d[N.col[k]];
    u[J] = s;
  }
}

void current_boundary_normals(const Body& body, std::vector<Vec3>& normals) {
  const auto& cloud = body.cloud;
  normals.assign(cloud.boundary_particles.size(), Vec3::Zero());
  for (const auto& face : cloud.boundary_faces) {
    const Vec3* p[4];
    for (int k = 0; k < face.n_nodes; ++k) p[k] = &body.x[face.nodes[k]];
    // Area vector of the (possibly warped) face: half the cross product of its diagonals.
    const Vec3 area = face.n_nodes == 3 ? Vec3(0.5 * (*p[1] - *p[0]).cross(*p[2] - *p[0]))
                                        : Vec3(0.5 * (*p[2] - *p[0]).cross(*p[3] - *p[1]));
    for (int k = 0; k < face.n_nodes; ++k) normals[cloud.boundary_index[face.nodes[k]]] += area;
  }
  for (auto& n : normals) {
    const double len = n.norm();
    if (len > 0.0) n /= len;
  }
}

double material_stable_dt(const Body& body) {
  const auto n = static_cast<Index>(body.F.size());
  double dt = std::numeric_limits<double>::infinity();
  std::visit(Overloaded{
                 [&](const MooneyRivlinMaterial& m) {
#pragma omp parallel for schedule(static) reduction(min : dt)
                   for (Index L = 0; L < n; ++L)
                     dt = std::min(dt, body.spacing[L] / m.at_point[L].wave_speed(body.F[L], body.density));
                 },
                 [&](const LCEMaterial& m) {
#pragma omp parallel for schedule(static) reduction(min : dt)
                   for (Index L = 0; L < n; ++L)
                     dt = std::min(dt, body.spacing[L] / m.model.wave_speed(
                                                             body.F[L],
                                                             director_at(*body.director, static_cast<std::size_t>(L)),
                                                             body.density));
                 }},
             body.material);
  return dt;
}

}  // namespace rkpm::sim
