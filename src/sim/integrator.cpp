#include "rkpm/sim/integrator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rkpm::sim {

namespace {

double body_volume(const Body& body) {
  double v = 0.0;
  for (double w : body.gradient.weight) v += w;
  return v;
}

// FIRE constants (Bitzek et al. 2006).
constexpr int kFireMinPositive = 5;
constexpr double kFireIncrease = 1.1, kFireDecrease = 0.5, kFireAlphaStart = 0.1, kFireAlphaShrink = 0.99;

}  // namespace

double EnergyLedger::relative_error() const {
  const double balance = total() - (initial + external + active + director - dissipated);
  const double scale = std::max({std::abs(initial), std::abs(kinetic), std::abs(strain), std::abs(interface),
                                 std::abs(external), std::abs(active), std::abs(director), std::abs(dissipated),
                                 std::numeric_limits<double>::min()});
  return std::abs(balance) / scale;
}

Integrator::Integrator(World& world, IntegratorSettings settings) : world_(world), settings_(settings) {}

double Integrator::estimate_stable_dt() const {
  double dt = std::numeric_limits<double>::infinity();
  for (const auto& b : world_.bodies) dt = std::min(dt, material_stable_dt(*b));
  for (const auto& t : world_.terms) dt = std::min(dt, t->stable_dt(world_));
  return dt;
}

void Integrator::forces_and_accelerations() {
  compute_forces(world_);
  support_power_ = 0.0;
  for (auto& bp : world_.bodies) {
    Body& b = *bp;
    support_power_ += b.constraints.transform_forces(b.force);
    const auto n = static_cast<Index>(b.size());
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) b.a[i] = b.force[i] / b.mass[i];
  }
  term_power_ = power_of_terms();
}

double Integrator::power_of_terms() const {
  double p = 0.0;
  for (const auto& t : world_.terms) p += t->power(world_);
  return p;
}

double Integrator::kinetic_energy() const {
  double ke = 0.0;
  for (const auto& bp : world_.bodies) {
    const Body& b = *bp;
    const auto n = static_cast<Index>(b.size());
#pragma omp parallel for schedule(static) reduction(+ : ke)
    for (Index i = 0; i < n; ++i) ke += 0.5 * b.mass[i] * b.v[i].squaredNorm();
  }
  return ke;
}

double Integrator::stored_energy() {
  ledger_.strain = 0.0;
  for (const auto& b : world_.bodies) ledger_.strain += strain_energy(*b);
  ledger_.interface = 0.0;
  for (const auto& t : world_.terms) ledger_.interface += t->stored_energy(world_);
  return ledger_.strain + ledger_.interface;
}

const EnergyLedger& Integrator::measure_energy() {
  ledger_.kinetic = kinetic_energy();
  stored_energy();
  return ledger_;
}

void Integrator::initialize() {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (auto& bp : world_.bodies) {
    Body& b = *bp;
    b.constraints.impose(b.d, b.v);
    update_positions(b);
    for (const auto& x : b.x) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
  }
  centre_ = 0.5 * (lo + hi);
  if (settings_.domain_size <= 0.0) settings_.domain_size = 50.0 * (hi - lo).norm();

  forces_and_accelerations();
  stable_dt_ = estimate_stable_dt();
  const double automatic = settings_.dt_safety * stable_dt_;
  if (settings_.dt > 0.0) {
    dt_ = settings_.dt;
    if (dt_ > stable_dt_ && !settings_.allow_unstable_dt) {
      dt_ = automatic;
      dt_clamped_ = true;
    }
  } else {
    dt_ = automatic;
  }
  ledger_ = EnergyLedger{};
  ledger_.kinetic = kinetic_energy();
  ledger_.initial = ledger_.kinetic + stored_energy();
  active_power_ = 0.0;
  check_state();
  update_convergence();
}

void Integrator::step() {
  const double h = dt_;
  const double c = settings_.mode == Mode::Dynamic ? settings_.damping : 0.0;
  const double old_term_power = term_power_, old_active_power = active_power_;
  double damping_power = 0.0;

  // First half kick and drift: v_{n+1/2} = v_n + h/2 (a_n - c v_n), d_{n+1} = d_n + h v_{n+1/2}.
  for (auto& bp : world_.bodies) {
    Body& b = *bp;
    const auto n = static_cast<Index>(b.size());
#pragma omp parallel for schedule(static) reduction(+ : damping_power)
    for (Index i = 0; i < n; ++i) {
      b.v[i] += 0.5 * h * (b.a[i] - c * b.v[i]);
      damping_power += c * b.mass[i] * b.v[i].squaredNorm();
      b.d[i] += h * b.v[i];
    }
    b.constraints.advance(h, b.d, b.v);
    update_positions(b);
  }

  forces_and_accelerations();

  // Second half kick, damping implicit in it: v_{n+1} = (v_{n+1/2} + h/2 a_{n+1}) / (1 + c h/2).
  for (auto& bp : world_.bodies) {
    Body& b = *bp;
    const auto n = static_cast<Index>(b.size());
    const double factor = 1.0 / (1.0 + 0.5 * c * h);
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) b.v[i] = factor * (b.v[i] + 0.5 * h * b.a[i]);
    b.constraints.impose(b.d, b.v);
  }

  if (settings_.mode == Mode::Relax) fire_update();

  active_power_ = 0.0;
  for (auto& bp : world_.bodies)
    if (bp->director) {
      const DirectorStep d = advance_director(*bp, h);
      active_power_ += d.active_power;
      // The director moves at fixed positions: the stored energy it changes is booked apart.
      ledger_.director += d.energy_change;
    }
  term_power_ = power_of_terms();

  ledger_.external += 0.5 * h * (old_term_power + term_power_) + h * support_power_;
  ledger_.active += 0.5 * h * (old_active_power + active_power_);
  ledger_.dissipated += h * damping_power;
  world_.time += h;
  ++world_.step;

  check_state();
  update_convergence();

  // The stable step follows the state (stiffening, contact): re-estimate now and then.
  if (world_.step % 10 == 0) {
    stable_dt_ = estimate_stable_dt();
    const double automatic = settings_.dt_safety * stable_dt_;
    if (settings_.dt > 0.0 && !dt_clamped_) {
      // A user step is kept while it stays below the stable estimate, as at the start;
      // once clamped, the run follows the automatic step.
      if (dt_ > stable_dt_ && !settings_.allow_unstable_dt) {
        dt_ = automatic;
        dt_clamped_ = true;
      }
    } else if (settings_.mode == Mode::Dynamic || dt_clamped_) {
      dt_ = automatic;
    } else {
      dt_ = std::min(dt_, automatic);  // FIRE grows dt by itself, up to this ceiling
    }
  }
}

void Integrator::fire_update() {
  double power = 0.0, vv = 0.0, ff = 0.0;
  for (const auto& bp : world_.bodies) {
    const Body& b = *bp;
    const auto n = static_cast<Index>(b.size());
#pragma omp parallel for schedule(static) reduction(+ : power, vv, ff)
    for (Index i = 0; i < n; ++i) {
      power += b.force[i].dot(b.v[i]);
      vv += b.v[i].squaredNorm();
      ff += b.force[i].squaredNorm();
    }
  }
  const double dt_max = settings_.dt_safety * stable_dt_;
  if (power > 0.0) {
    // Steer the velocity toward the force direction, keeping its magnitude; the kinetic
    // energy this removes (|mixed| <= |v|) goes to the ledger as dissipation.
    const double kinetic_before = kinetic_energy();
    const double mix = ff > 0.0 ? fire_alpha_ * std::sqrt(vv / ff) : 0.0;
    for (auto& bp : world_.bodies) {
      Body& b = *bp;
      const auto n = static_cast<Index>(b.size());
#pragma omp parallel for schedule(static)
      for (Index i = 0; i < n; ++i) b.v[i] = (1.0 - fire_alpha_) * b.v[i] + mix * b.force[i];
      b.constraints.impose(b.d, b.v);
    }
    ledger_.dissipated += kinetic_before - kinetic_energy();
    if (++fire_positive_steps_ > kFireMinPositive) {
      dt_ = std::min(dt_ * kFireIncrease, dt_max);
      fire_alpha_ *= kFireAlphaShrink;
    }
  } else {
    // Moving uphill: stop, and take the kinetic energy out of the ledger.
    ledger_.dissipated += kinetic_energy();
    for (auto& bp : world_.bodies) {
      Body& b = *bp;
      std::fill(b.v.begin(), b.v.end(), Vec3::Zero());
      b.constraints.impose(b.d, b.v);
    }
    fire_positive_steps_ = 0;
    fire_alpha_ = kFireAlphaStart;
    dt_ *= kFireDecrease;
  }
}

void Integrator::update_convergence() {
  double residual = 0.0, reference_energy = 0.0;
  for (const auto& bp : world_.bodies) {
    const Body& b = *bp;
    const double mu = mean_shear_modulus(b);
    reference_energy += mu * body_volume(b);
    const auto n = static_cast<Index>(b.size());
#pragma omp parallel for schedule(static) reduction(max : residual)
    for (Index i = 0; i < n; ++i)
      residual = std::max(residual, b.force[i].norm() / (mu * std::cbrt(b.cloud.volume[i] * b.cloud.volume[i])));
  }
  residual_ = residual;
  kinetic_measure_ = kinetic_energy() / reference_energy;
}

bool Integrator::converged() const {
  return residual_ < settings_.relax_force_tol && kinetic_measure_ < settings_.relax_velocity_tol;
}

void Integrator::check_state() {
  enum Reason { None = 0, NonFinitePosition, NonFiniteVelocity, Inverted, Runaway };
  const double limit2 = settings_.domain_size * settings_.domain_size;
  double min_J = std::numeric_limits<double>::infinity();
  for (const auto& bp : world_.bodies) {
    const Body& b = *bp;
    const auto n = static_cast<Index>(b.size());
    Index first = std::numeric_limits<Index>::max();
#pragma omp parallel for schedule(static) reduction(min : first, min_J)
    for (Index i = 0; i < n; ++i) {
      const double J = b.F[i].determinant();
      min_J = std::min(min_J, J);
      const bool bad = !b.x[i].allFinite() || !b.v[i].allFinite() || !(J > 0.0) ||
                       (b.x[i] - centre_).squaredNorm() > limit2;
      if (bad) first = std::min(first, i);
    }
    if (first == std::numeric_limits<Index>::max()) continue;
    const double J = b.F[first].determinant();
    const Reason why = !b.x[first].allFinite()   ? NonFinitePosition
                       : !b.v[first].allFinite() ? NonFiniteVelocity
                       : !(J > 0.0)              ? Inverted
                                                 : Runaway;
    const char* what[] = {"", "position is not finite", "velocity is not finite",
                          "the deformation gradient is inverted or degenerate (J <= 0 or NaN)",
                          "the particle left the domain (runaway motion)"};
    const Vec3 X = b.cloud.X[first];
    throw BlowUp(fmt::format(
        "unstable at step {} (t = {:.6g} s, dt = {:.3g} s): body '{}', particle {} (reference position "
        "({:.4g}, {:.4g}, {:.4g}) m, current ({:.4g}, {:.4g}, {:.4g}) m): {}; J = {:.4g}, |v| = {:.4g} m/s. "
        "The stable step estimate is {:.3g} s.",
        world_.step, world_.time, dt_, b.name, first, X.x(), X.y(), X.z(), b.x[first].x(), b.x[first].y(),
        b.x[first].z(), what[why], J, b.v[first].norm(), stable_dt_));
  }
  min_J_ = min_J;
}

std::vector<double> Integrator::save_state() const {
  return {dt_,
          stable_dt_,
          ledger_.external,
          ledger_.active,
          ledger_.dissipated,
          ledger_.initial,
          ledger_.director,
          term_power_,
          active_power_,
          support_power_,
          fire_alpha_,
          static_cast<double>(fire_positive_steps_),
          settings_.domain_size,
          centre_.x(),
          centre_.y(),
          centre_.z(),
          dt_clamped_ ? 1.0 : 0.0};
}

void Integrator::load_state(const std::vector<double>& s) {
  if (s.size() != 17) throw std::invalid_argument("checkpoint: integrator state has the wrong size");
  dt_ = s[0];
  stable_dt_ = s[1];
  ledger_.external = s[2];
  ledger_.active = s[3];
  ledger_.dissipated = s[4];
  ledger_.initial = s[5];
  ledger_.director = s[6];
  term_power_ = s[7];
  active_power_ = s[8];
  support_power_ = s[9];
  fire_alpha_ = s[10];
  fire_positive_steps_ = static_cast<std::int64_t>(s[11]);
  settings_.domain_size = s[12];
  centre_ = Vec3(s[13], s[14], s[15]);
  dt_clamped_ = s[16] != 0.0;
}

}  // namespace rkpm::sim
