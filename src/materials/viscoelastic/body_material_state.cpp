// The viscous strains as the viscoelastic material's per-point state: the hooks of
// materials/state_hooks.hpp (compiled into rkpm_sim).
#include "materials/viscoelastic/body_material.hpp"

#include "rkpm/sim/body.hpp"
#include "rkpm/sim/state_record.hpp"

#include <fmt/format.h>

#include <cmath>
#include <tuple>
#include <limits>

namespace rkpm::materials::viscoelastic {

namespace {
// Per point: each branch's packed symmetric Cv^-1, the branches in order.
constexpr std::size_t kPacked = std::tuple_size<PackedSymmetric>::value;
constexpr std::size_t kStateValues = kMaxPronyBranches * kPacked;

// sum_L V_L W(F_L, state_L) over this rank's points, summed exactly (the same bits on any
// thread and rank count).
ExactSum stored_energy(const sim::Body& body, const BodyMaterial& m) {
  ExactSum total;
#pragma omp parallel for schedule(static) reduction(+ : total)
  for (Index L = body.owned_begin(); L < body.owned_end(); ++L)
    total.add(body.gradient.weight[L] * m.energy(L, body.F[L]));
  return total;
}
}  // namespace

// Each branch relaxes at the step's final F over dt (the exact flow, Eq. 4 of
// prony_neo_hookean.hpp). The stress of the step's force pass used the state from
// before; the energy the update releases is the viscous dissipation of the step, booked
// as the state's energy change (< 0).
StateUpdate BodyMaterial::end_step(sim::Body& body, double dt) {
  StateUpdate result;
  if (model.branch_count == 0) return result;
  result.energy_before = stored_energy(body, *this);
#pragma omp parallel for schedule(static)
  for (Index L = body.owned_begin(); L < body.owned_end(); ++L) state[L] = model.relax(body.F[L], state[L], dt);
  result.energy_after = stored_energy(body, *this);
  return result;
}

double BodyMaterial::stable_dt(const sim::Body& /*body*/) const { return std::numeric_limits<double>::infinity(); }

// How far the branches are from having relaxed at the present F: the largest energy the
// Maxwell branches hold at a point over the long-term shear modulus (0 once relaxed).
double BodyMaterial::residual(const sim::Body& body) const {
  double largest = 0.0;
#pragma omp parallel for schedule(static) reduction(max : largest)
  for (Index L = body.owned_begin(); L < body.owned_end(); ++L)
    largest = std::max(largest, model.viscous_energy(body.F[L], state[L]));
  return largest / model.shear_modulus();
}

void BodyMaterial::save_state(sim::StateRecord& record, const std::string& prefix) const {
  std::vector<double> values(state.size() * kStateValues);
  for (std::size_t i = 0; i < state.size(); ++i)
    for (std::size_t b = 0; b < kMaxPronyBranches; ++b)
      for (std::size_t k = 0; k < kPacked; ++k)
        values[i * kStateValues + b * kPacked + k] = state[i].inverse_viscous_cauchy_green[b][k];
  record.put_reals(prefix + "viscous_state", values);
}

// Each branch's Cv^-1 must be positive definite with det 1 (the update keeps
// it so to round-off): anything else is a damaged file, named with its particle.
void BodyMaterial::load_state(const sim::StateRecord& record, const std::string& prefix, const sim::Body& body) {
  const std::vector<double> values = record.reals(prefix + "viscous_state", body.size() * kStateValues);
  state.resize(body.size());
  for (std::size_t i = 0; i < state.size(); ++i) {
    for (std::size_t b = 0; b < kMaxPronyBranches; ++b)
      for (std::size_t k = 0; k < kPacked; ++k)
        state[i].inverse_viscous_cauchy_green[b][k] = values[i * kStateValues + b * kPacked + k];
    for (int b = 0; b < model.branch_count; ++b) {
      const Mat3 Cv_inv = state[i].inverse_viscous(b);
      const double det = Cv_inv.determinant();
      const double smallest = symmetric_eigenvalues(Cv_inv)[0];
      if (!(std::abs(det - 1.0) <= 1e-9) || !(smallest > 0.0))
        throw sim::StateError(fmt::format("body '{}' particle {} has a viscous strain of branch {} with det {} and "
                                          "smallest eigenvalue {}, expected det 1 and positive eigenvalues",
                                          body.name, i, b, det, smallest));
    }
  }
}

// A finer level starts from the unstrained branches: nested iteration runs in relax
// mode, whose end, the long-term equilibrium, holds no energy in the branches whatever
// their state on the way.
void BodyMaterial::transfer_state(const BodyMaterial& /*from*/, const VectorInterpolation& /*interpolate*/) {}

}  // namespace rkpm::materials::viscoelastic
