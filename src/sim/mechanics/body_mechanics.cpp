// The forces of a step (compute_forces: every body's internal force, then the terms'),
// and the per-step mechanics of one body: kinematics, stress and internal force.
#include "rkpm/sim/body.hpp"
#include "rkpm/sim/world.hpp"

#include <omp.h>

#include <algorithm>
#include <functional>
#include <type_traits>
#include <utility>
#include <limits>

namespace rkpm::sim {

rk::RKApproximation approximation(const Body& body) { return rk::RKApproximation(body.cloud, body.rk_settings); }

// The order in which the force pass's row contributions reach each particle's sum
// (rk/row_scatter.hpp): per row, the gradient row's columns, then (stabilized) the row's
// own particle and its interpolation row; a second channel for a coupled field's flux
// divergence when the material tracks it. On one thread and rank every sum is already in
// the reference order (one block); otherwise the seams are planned in the one-thread
// order, so that the force has the same bits on any thread and rank count.
void plan_force_scatter(Body& body) {
  const auto& op = body.gradient;
  const auto& N = body.interpolation;
  const bool stabilized = body.stabilization.active();
  const materials::CoupledField field =
      std::visit([](auto& material) { return material.coupled_field(); }, body.material);
  const int channels = field.active() && field.flux != nullptr ? 2 : 1;
  const int threads = rk::RowScatter::team_threads();
  const auto n = static_cast<Index>(body.size());
  auto& scatter = body.force_scatter;
  if (threads == 1 && !body.distributed()) {
    std::vector<rk::RowScatter::Pattern> patterns{{&op.row_offset, &op.col}};
    if (stabilized) patterns.push_back({&N.row_offset, &N.col});
    scatter.plan(n, n, patterns, threads, channels);
    return;
  }
  // The columns of each row's contributions, in the order the force pass makes them.
  const auto columns = [&](Index L, int channel, const std::function<void(Index)>& emit) {
    rk::scatter_columns(op, L, emit);
    if (channel == 0 && stabilized) {
      emit(L);
      for (Index k = N.row_offset[L]; k < N.row_offset[L + 1]; ++k) emit(N.col[k]);
    }
  };
  const rk::RowScatter::Links links = body.distributed() ? body.ghosts.scatter_links() : rk::RowScatter::Links{};
  scatter.plan_ordered(body.owned_begin(), body.owned_end(), n, threads, channels, columns,
                       body.distributed() ? &links : nullptr);
}

namespace {
// Whether a material has a stress kernel that also returns its coupled field's flux.
template <class Material, class = void>
struct has_flux : std::false_type {};
template <class Material>
struct has_flux<Material, std::void_t<decltype(std::declval<const Material&>().stress_and_flux(
                              Index{}, std::declval<const Mat3&>(), std::declval<Mat3&>()))>> : std::true_type {};

// One pass over the rows of the gradient operator (and of the interpolation operator
// when the body is stabilized), so each row is read from memory once per step:
//   F_L = sum_I x_I (x) b_I(X_L)                 (and Grad_X of the material's coupled
//                                                 field, materials::CoupledField),
//   P_L = material.stress(L, F_L)                (or stress_and_flux when the flux's
//                                                 divergence is tracked),
//   f_I += V_L P_L b_I(X_L)                      (the internal force, scattered),
//   div_I += V_L flux_L b_I(X_L)                 (the coupled field's weak divergence,
//                                                 when tracked: CoupledField),
//   r_L = d_L - sum_I Psi_I(X_L) d_I,  f_L += W_L r_L,  f_I -= Psi_I(X_L) W_L r_L
//                                                (the stabilization, rk/stabilization.hpp).
// The scatter goes into per-thread buffers; on several threads or ranks it is ordered
// (rk/row_scatter.hpp): each particle's sum is made in the one-thread order, so the
// force has the same bits on any thread and rank count.
// `grad` is the operator's storage (op.grad or op.grad_float): the precision is
// dispatched once per pass, so the row loops inline without a branch per row.
template <class Stored, class Material>
void force_pass(Body& body, const std::vector<Stored>& grad, const Material& material,
                const materials::CoupledField& field) {
  const auto& op = body.gradient;
  const auto& N = body.interpolation;
  auto& stab = body.stabilization;
  const bool stabilized = stab.active();
  const bool coupled = field.active();
  // The coupled flux's divergence: a second scatter channel, made only when tracked.
  const bool divergence = coupled && field.flux != nullptr;
  const int threads = rk::RowScatter::team_threads();
  const int channels = divergence ? 2 : 1;
  auto& scatter = body.force_scatter;
  // Planned at set-up (plan_force_scatter); again only if the thread count changed since.
  if (!scatter.planned_for(threads, channels)) plan_force_scatter(body);
  if (body.distributed()) {
    body.ghosts.pull(body.d);
    if (coupled) body.ghosts.pull(*field.values);
  }
  std::vector<double> energy(static_cast<std::size_t>(threads), 0.0);
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    scatter.clear(t);
    double stabilization_energy = 0.0;
    for (Index L = scatter.row_begin(t); L < scatter.row_end(t); ++L) {
      Mat3 F;
      if (coupled) {
        Mat3 field_gradient;
        rk::deformation_and_field_gradients(op, grad, body.cloud.X, body.d, *field.values, L, F, field_gradient);
        (*field.gradient)[L] = field_gradient;  // before the stress, which reads it
      } else {
        F = rk::deformation_gradient(op, grad, body.cloud.X, body.d, L);
      }
      body.F[L] = F;
      Mat3 flux = Mat3::Zero();
      Mat3 P;
      if constexpr (has_flux<Material>::value)
        P = divergence ? material.stress_and_flux(L, F, flux) : material.stress(L, F);
      else
        P = material.stress(L, F);
      const double w = op.weight[L];
      if (divergence) (*field.flux)[L] = flux;
      Vec3 wr = Vec3::Zero();
      double weight_sum = 0.0;
      if (stabilized) {
        const auto residual = rk::interpolation_residual(N, body.d, L);
        stabilization_energy += 0.5 * stab.weight[L] * residual.r.squaredNorm();
        wr = stab.weight[L] * residual.r;
        weight_sum = residual.weight_sum;
      }
      // The row's contributions, in the order the scatter's plan lists them.
      const auto contribute = [&](const auto& add_force, const auto& add_divergence) {
        rk::scatter_row(op, grad, L, w, P, add_force);
        if (divergence) rk::scatter_row(op, grad, L, w, flux, add_divergence);
        if (stabilized) rk::scatter_residual(N, L, wr, weight_sum, add_force);
      };
      if (scatter.seam_row(L))
        contribute(scatter.sink(t, 0, L), scatter.sink(t, channels - 1, L));
      else
        contribute(rk::RowScatter::AddTo{scatter.buffer(t, 0)}, rk::RowScatter::AddTo{scatter.buffer(t, channels - 1)});
    }
    energy[static_cast<std::size_t>(t)] = stabilization_energy;
#pragma omp barrier
    // The sums hold f_int plus the stabilization's resistance; the body's force is minus that.
    scatter.reduce(t, 0, -1.0, body.force);
    if (divergence) scatter.reduce(t, 1, 1.0, *field.divergence);
  }
  // The seams (particles the rows of several threads or ranks reach), in order.
  scatter.fold(0, -1.0, body.force, false);
  if (divergence) {
    std::vector<Vec3>& div = *field.divergence;
    scatter.fold(1, 1.0, div, false);
    // Weak form: sum_L V_L flux_L b_I(X_L) = -V_I Div_X(flux)(X_I) away from the surface.
#pragma omp parallel for schedule(static)
    for (Index I = 0; I < static_cast<Index>(body.size()); ++I) div[I] /= -body.cloud.volume[I];
  }
  body.stabilization_energy = 0.0;
  for (double e : energy) body.stabilization_energy += e;
}
}  // namespace

void compute_forces(World& world) {
  for (auto& body : world.bodies) compute_internal_forces(*body);
  // Terms in declaration order: each adds to Body::force, so the sum is deterministic.
  for (auto& term : world.terms) term->add_forces(world);
}

// Each function below dispatches once per body (std::visit over the material catalog)
// and calls the model's inline kernel per point (sim::Material's interface).
void compute_internal_forces(Body& body) {
  std::visit(
      [&](auto& material) {
        const materials::CoupledField field = material.coupled_field();
        if (body.gradient.single_precision())
          force_pass(body, body.gradient.grad_float, material, field);
        else
          force_pass(body, body.gradient.grad, material, field);
      },
      body.material);
}

void update_deformation_gradients(Body& body) {
  if (body.distributed()) body.ghosts.pull(body.d);
  const auto& op = body.gradient;
#pragma omp parallel for schedule(static)
  for (Index L = body.owned_begin(); L < body.owned_end(); ++L)
    body.F[L] = rk::deformation_gradient(op, body.cloud.X, body.d, L);
}

Mat3 first_piola_at(const Body& body, Index L) {
  return std::visit([&](const auto& material) { return material.stress(L, body.F[L]); }, body.material);
}

double strain_energy(const Body& body) {
  ExactSum total;
  std::visit(
      [&](const auto& material) {
#pragma omp parallel for schedule(static) reduction(+ : total)
        for (Index L = body.owned_begin(); L < body.owned_end(); ++L)
          total.add(body.gradient.weight[L] * material.energy(L, body.F[L]));
      },
      body.material);
  return total.value() + body.stabilization_energy;
}

void physical_displacement(const Body& body, std::vector<Vec3>& u) {
  const auto& N = body.interpolation;
  const auto n = static_cast<Index>(body.size());
  u.resize(body.size());
#pragma omp parallel for schedule(static)
  for (Index J = 0; J < n; ++J) u[J] = rk::interpolate(N, body.d, J);
}

void current_boundary_normals(const Body& body, std::vector<Vec3>& normals) {
  const auto& cloud = body.cloud;
  normals.assign(cloud.boundary_particles.size(), Vec3::Zero());
  for (const auto& face : cloud.boundary_faces) {
    Vec3 p[4];
    for (int k = 0; k < face.n_nodes; ++k) p[k] = nodal_position(body, face.nodes[k]);
    // Area vector of the (possibly warped) face: half the cross product of its diagonals.
    const Vec3 area = face.n_nodes == 3 ? Vec3(0.5 * (p[1] - p[0]).cross(p[2] - p[0]))
                                        : Vec3(0.5 * (p[2] - p[0]).cross(p[3] - p[1]));
    for (int k = 0; k < face.n_nodes; ++k) normals[cloud.boundary_index[face.nodes[k]]] += area;
  }
  for (auto& n : normals) {
    const double len = n.norm();
    if (len > 0.0) n /= len;
  }
}

double shear_modulus(const Body& body, Index L) {
  return std::visit([L](const auto& material) { return material.shear_modulus(L); }, body.material);
}

Vec3 reference_centroid(const Body& body) {
  const auto& c = body.cloud;
  Vec3 sum = Vec3::Zero();
  double v = 0.0;
  for (Index i : one_rank_order(body)) {
    sum += c.volume[i] * c.X[i];
    v += c.volume[i];
  }
  return sum / v;
}

std::vector<Index> one_rank_order(const Body& body) {
  std::vector<Index> order(body.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[body.original_id.empty() ? i : static_cast<std::size_t>(body.original_id[i])] = static_cast<Index>(i);
  return order;
}

double mean_shear_modulus(const Body& body) {
  double weighted = 0.0, volume = 0.0;
  for (Index i : one_rank_order(body)) {
    weighted += body.cloud.volume[i] * shear_modulus(body, i);
    volume += body.cloud.volume[i];
  }
  return weighted / volume;
}

void particle_wave_steps(const Body& body, std::vector<double>& steps) {
  const auto n = static_cast<Index>(body.F.size());
  steps.resize(static_cast<std::size_t>(n));
  std::visit(
      [&](const auto& material) {
#pragma omp parallel for schedule(static)
        for (Index L = 0; L < n; ++L) steps[L] = body.spacing[L] / material.wave_speed(L, body.F[L], body.density);
      },
      body.material);
}

double material_stable_dt(const Body& body) {
  double dt = std::numeric_limits<double>::infinity();
  std::visit(
      [&](const auto& material) {
#pragma omp parallel for schedule(static) reduction(min : dt)
        for (Index L = body.owned_begin(); L < body.owned_end(); ++L)
          dt = std::min(dt, body.spacing[L] / material.wave_speed(L, body.F[L], body.density) *
                                std::sqrt(body.inertia[L] / body.mass[L]));
      },
      body.material);
  return dt;
}

void scale_inertia(Body& body, double target, const std::vector<double>& steps) {
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double ratio = target / steps[i];
    body.inertia[i] = body.mass[i] * std::max(1.0, ratio * ratio);
  }
}

}  // namespace rkpm::sim
