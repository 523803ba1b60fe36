// The integrator's energy ledger: stored energy, the terms' power, the materials' state
// work, and the books kept each step (docs/theory/numerics.md).
#include "rkpm/sim/integrator.hpp"

#include "rkpm/sim/body_state.hpp"
#include "rkpm/sim/stable_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rkpm::sim {

double EnergyLedger::relative_error() const {
  const double balance = total() - (initial + external + active + state - dissipated);
  const double scale = std::max({std::abs(initial), std::abs(kinetic), std::abs(strain), std::abs(interface),
                                 std::abs(external), std::abs(active), std::abs(state), std::abs(dissipated),
                                 std::numeric_limits<double>::min()});
  return std::abs(balance) / scale;
}

// The stored energy an update changed, over every rank: the exact sums merged, then
// differenced (the same bits on any rank count).
double Integrator::state_energy_change(const materials::StateUpdate& update) const {
  return world_.comm->sum(update.energy_after) - world_.comm->sum(update.energy_before);
}

double Integrator::power_of_terms() const {
  double p = 0.0;
  for (const auto& t : world_.terms) p += t->power(world_);
  return p;
}

double Integrator::stored_energy() {
  ledger_.strain = 0.0;
  for (const auto& b : world_.bodies) ledger_.strain += world_.comm->sum(strain_energy(*b));
  ledger_.interface = 0.0;
  for (const auto& t : world_.terms) ledger_.interface += t->stored_energy(world_);
  return ledger_.strain + ledger_.interface;
}

const EnergyLedger& Integrator::measure_energy() {
  ledger_.kinetic = kinetic_energy(world_);
  stored_energy();
  return ledger_;
}

// The energy ledger: the work of the terms and of the moving supports by the trapezoidal
// rule over the step, the materials' active work (trapezoidal in F, end_state_step),
// their states' energy change, and the dissipation by FIRE and by damping.
void Integrator::ledger(const StepBook& book) {
  const double h = book.h;
  term_power_ = power_of_terms();
  if (settings_.mode == Mode::Relax) ledger_.dissipated += book.fire_dissipated;
  for (double e : book.state_energy) ledger_.state += e;
  ledger_.external += 0.5 * h * (book.old_term_power + term_power_) + h * support_power_;
  ledger_.active += book.active_work;
  ledger_.dissipated += h * book.damping_power;
}

}  // namespace rkpm::sim
