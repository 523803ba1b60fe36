#include "terms/wall_contact/wall_contact.hpp"

#include "terms/catalog.hpp"
#include "terms/term_support.hpp"

#include "rkpm/sim/body_points.hpp"

#include "rkpm/io/json.hpp"
#include "rkpm/common/parallel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace rkpm::sim {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Passes of scale_inertia_to, each making a particle whose row g exceeds the bound
// heavier by g / bound. A row falls by that factor when its partners are raised alike
// (two facing walls), by less when they stay light; the later passes finish those. The
// result need not reach the bound exactly: the term's own stable_dt still limits the
// step.
constexpr int kInertiaPasses = 3;

const WallContactSettings& checked(const WallContactSettings& s) {
  if (!(s.distance > 0.0) || !(s.pressure > 0.0) || !(s.exclusion > s.distance) || !(s.skin >= 0.0))
    throw std::invalid_argument(fmt::format("wall_contact: expected distance > 0, pressure > 0, exclusion > distance "
                                            "and skin >= 0, got distance = {}, pressure = {}, exclusion = {}, skin = {}",
                                            s.distance, s.pressure, s.exclusion, s.skin));
  return s;
}
}  // namespace

WallContact::WallContact(Body& body, const WallContactSettings& settings)
    : body_(body), surface_(checked(settings).surface), lj_{1.0, settings.distance}, pressure_(settings.pressure),
      exclusion2_(settings.exclusion * settings.exclusion),
      // Excluded pairs (neighbours in the reference wall) never interact: they are not
      // stored. Within distance + skin on one wall they are nearly all of the candidates,
      // so listing them dominated a large shell's memory (docs/verification/performance.md).
      // Only the rows are read.
      pairs_(settings.distance, settings.skin, [this](Index i, Index j) { return !excluded(i, j); }, false) {
  const std::uint32_t bit = body.cloud.surface_bit(surface_);
  if (bit == 0u)
    throw std::invalid_argument("wall_contact: body '" + body.name + "' has no surface named '" + surface_ + "'");
  const auto& boundary = body.cloud.boundary_particles;
  for (std::size_t b = 0; b < boundary.size(); ++b) {
    const auto I = static_cast<Index>(boundary[b]);
    if (!(body.cloud.surface_mask[static_cast<std::size_t>(I)] & bit)) continue;
    particles_.push_back(I);
    area_.push_back(body.cloud.boundary_area[b]);
    reference_.push_back(body.cloud.X[static_cast<std::size_t>(I)]);
  }
  points_.resize(particles_.size());
  force_.assign(particles_.size(), Vec3::Zero());
  row_energy_.resize(particles_.size());
  row_closest_.resize(particles_.size());
}

double WallContact::surface_spacing() const {
  if (area_.empty()) return 0.0;
  double total = 0.0;
  for (double a : area_) total += a;
  return std::sqrt(total / static_cast<double>(area_.size()));
}

bool WallContact::excluded(Index i, Index j) const { return (reference_[i] - reference_[j]).squaredNorm() < exclusion2_; }

void WallContact::add_forces(World& world) {
  const auto start = std::chrono::steady_clock::now();
  const auto n = static_cast<Index>(particles_.size());
#pragma omp parallel for schedule(static) if (worth_threads(n))
  for (Index i = 0; i < n; ++i) points_[i] = physical_point(body_, particles_[i]);
  // Distributed: each rank computes the points of its own particles (it holds their
  // interpolation rows) and gathers the others', then evaluates every pair as a single
  // process would: the surface is small next to the body, and the pair list, the energy
  // and the step limit are then the same on every rank. Only the transfer of the point
  // forces to the generalized coordinates is split (add_point_forces).
  if (body_.distributed()) {
    if (!shared_.built()) shared_.build(*world.comm, body_.ghosts.offset(), particles_);
    shared_.update_packed(points_);
  }
  pairs_.update(points_, points_);  // symmetric: row i lists every j near i, i itself included
  const auto& offset = pairs_.row_offset();
  const auto& partner = pairs_.partner();
  const double s2 = lj_.s0 * lj_.s0;
  std::size_t active = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : active) if (worth_threads(n))
  for (Index i = 0; i < n; ++i) {
    double e = 0.0, closest2 = kInfinity;
    Vec3 f = Vec3::Zero();
    for (Index k = offset[i]; k < offset[i + 1]; ++k) {
      const Index j = partner[k];  // never excluded: the list keeps no such pair
      const Vec3 rij = points_[i] - points_[j];
      const double r2 = rij.squaredNorm();
      closest2 = std::min(closest2, r2);
      if (r2 >= s2) continue;
      ++active;
      double slope_over_r = 0.0;
      const double c = pair_energy_scale(i, j);
      e += c * (lj_.energy_and_slope(r2, slope_over_r) + 1.0);  // shifted: w(s0) = 0
      f -= (c * slope_over_r) * rij;
    }
    row_energy_[i] = e;
    row_closest_[i] = closest2;
    force_[i] = f;
  }
  // Generalized forces sum_J Psi_I(X_J) f_J: only particles in contact carry a force,
  // so a serial scatter over them is cheap and keeps a fixed order.
  add_point_forces(body_, particles_, 1.0, [&](std::size_t i) -> const Vec3& { return force_[i]; }, transfer_);
  double energy = 0.0, closest2 = kInfinity;  // serial, in particle order
  for (Index i = 0; i < n; ++i) {
    energy += row_energy_[i];
    closest2 = std::min(closest2, row_closest_[i]);
  }
  energy_ = 0.5 * energy;  // every pair sits in two rows
  active_pairs_ = active / 2;
  max_active_pairs_ = std::max(max_active_pairs_, active_pairs_);
  closest_ = std::sqrt(closest2);
  closest_over_run_ = std::min(closest_over_run_, closest_);
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Pairs listed within s0 + skin count with their stiffness at min(r, s0): the estimate
// is refreshed only every few steps, and the stiffness jumps from 0 to 72 c / s0^2 the
// moment a pair crosses s0, so a pair about to touch must already limit the step.
double WallContact::gershgorin_row(Index i) const {
  const auto& offset = pairs_.row_offset();
  const auto& partner = pairs_.partner();
  const double mi = body_.inertia[particles_[i]];
  double g = 0.0;
  for (Index k = offset[i]; k < offset[i + 1]; ++k) {
    const Index j = partner[k];  // never excluded: the list keeps no such pair
    const double r = std::min((points_[i] - points_[j]).norm(), lj_.s0);
    g += pair_energy_scale(i, j) * lj_.stiffness(r) * (1.0 / mi + 1.0 / std::sqrt(mi * body_.inertia[particles_[j]]));
  }
  return g;
}

double WallContact::stable_dt(const World&) const {
  if (pairs_.builds() == 0 || pairs_.size() == 0) return kInfinity;
  double omega2 = 0.0;
  const auto n = static_cast<Index>(particles_.size());
#pragma omp parallel for schedule(dynamic, 64) reduction(max : omega2) if (worth_threads(n))
  for (Index i = 0; i < n; ++i) omega2 = std::max(omega2, gershgorin_row(i));
  return omega2 > 0.0 ? 2.0 / std::sqrt(omega2) : kInfinity;
}

// Every rank holds every surface point and the same pair list (add_forces), so every
// rank raises the same inertia, that of one process. A raised inertia is never lowered
// again: a relaxation needs no particular masses, and lowering it when a pair
// separates would only bring the limit back when the pair closes again. The velocities
// are left as they are, so the velocity field stays continuous across the contact (the
// caller books the kinetic energy this adds). Scaling them down to keep each particle's
// kinetic energy left the pressed particles lagging their neighbours, and the default
// RBC run's own cloud kept moving long after the run with the velocities kept had
// stopped (docs/verification/relaxation.md compares the two).
void WallContact::scale_inertia_to(World&, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt) || pairs_.builds() == 0 || pairs_.size() == 0) return;
  const double bound = 4.0 / (dt * dt);  // omega^2 at which 2 / omega = dt
  const auto n = static_cast<Index>(particles_.size());
  std::vector<double> factor(particles_.size());
  for (int pass = 0; pass < kInertiaPasses; ++pass) {
    int raised = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : raised) if (worth_threads(n))
    for (Index i = 0; i < n; ++i) {
      const double g = gershgorin_row(i);
      factor[i] = g > bound ? g / bound : 1.0;
      raised += factor[i] > 1.0 ? 1 : 0;
    }
    if (raised == 0) return;
    for (Index i = 0; i < n; ++i) body_.inertia[particles_[i]] *= factor[i];
  }
}

void WallContact::report(const World&, io::Json& summary) const {
  io::Json j = io::Json::object();
  j.set("energy", energy_);
  j.set("active_pairs", active_pairs_);
  j.set("max_active_pairs", max_active_pairs_);
  j.set("surface_particles", particles_.size());
  j.set("pair_list_builds", pairs_.builds());
  // Closest approach of two non-excluded particles within distance + skin; the keys are
  // left out while no such pair has been listed.
  if (std::isfinite(closest_)) j.set("closest", closest_);
  if (std::isfinite(closest_over_run_)) j.set("closest_over_run", closest_over_run_);
  j.set("seconds", seconds_);
  // What contact_mass_scaling (or mass_scaling) left on the surface: how many of its
  // particles are heavier than their mass, and by how much at most.
  std::int64_t heavier = 0;
  double largest = 1.0;
  for (const Index I : particles_) {
    const double ratio = body_.inertia[I] / body_.mass[I];
    if (ratio > 1.0) ++heavier;
    largest = std::max(largest, ratio);
  }
  j.set("heavier_particles", heavier);
  j.set("largest_inertia_over_mass", largest);
  summary.set("wall_contact " + body_.name + " " + surface_, j);
}

}  // namespace rkpm::sim

namespace rkpm::terms::wall_contact {

std::unique_ptr<sim::Term> build(const scene::ParamSet& params, sim::World& world) {
  const sim::WallContactSettings s = settings_table().read(params);
  sim::Body& body = named_body(world, params, s.body);
  auto term = constructed(params, [&] { return std::make_unique<sim::WallContact>(body, s); });
  // A square lattice of spacing a has holes a / sqrt(2) from their corners: beyond
  // a = sqrt(2) s0 a particle of one wall can pass between those of the other.
  if (term->surface_spacing() > std::sqrt(2.0) * s.distance)
    world.setup_warnings.push_back(fmt::format(
        "{}:{}: [term] wall_contact: distance = {:.3g} m is below the particle spacing of surface \"{}\" "
        "divided by sqrt(2) (spacing {:.3g} m, the root of the mean particle area): a particle of one wall can "
        "pass between the particles of the other. Use distance >= {:.3g} m or a finer cloud.",
        params.file(), params.line("distance"), s.distance, s.surface, term->surface_spacing(),
        term->surface_spacing() / std::sqrt(2.0)));
  return term;
}

}  // namespace rkpm::terms::wall_contact
