#include "terms/contact/contact.hpp"
#include "terms/contact/holding.hpp"
#include "terms/contact/surface_contact.hpp"

#include "terms/catalog.hpp"
#include "terms/term_support.hpp"

#include "rkpm/sim/body_points.hpp"

#include "rkpm/io/json.hpp"
#include "rkpm/common/parallel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rkpm::sim {

double LennardJones::energy(double r) const {
  const double u6 = std::pow(s0 / r, 6);
  return eps * (u6 * u6 - 2.0 * u6);
}

double LennardJones::derivative(double r) const {
  const double u6 = std::pow(s0 / r, 6);
  return eps * (-12.0 * u6 * u6 + 12.0 * u6) / r;
}

double LennardJones::second_derivative(double r) const {
  const double u6 = std::pow(s0 / r, 6);
  return eps * (156.0 * u6 * u6 - 84.0 * u6) / (r * r);
}

double LennardJones::stiffness(double r) const {
  return std::max(std::abs(second_derivative(r)), std::abs(derivative(r)) / r);
}

namespace {

// n_I = beta V_I (molecule_density: beta = 0 means one molecule per particle).
std::vector<double> molecules_of(const Body& body, double beta) {
  const double density = molecule_density(body, beta);
  const auto& V = body.cloud.volume;
  std::vector<double> n(V.size());
  for (std::size_t i = 0; i < V.size(); ++i) n[i] = density * V[i];
  return n;
}

}  // namespace

Contact::Contact(Body& a, Body& b, const ContactSettings& s, const par::Comm& comm)
    : a_(a), b_(b), comm_(comm), lj_{s.epsilon, s.s0}, cutoff_(s.cutoff), energy_shift_(lj_.energy(s.cutoff)),
      pairs_(s.cutoff, s.skin, {}, false), law_(s.law), substrate_(s.substrate == a.name ? 0 : 1),
      log_(a, b, s, comm), s0_(s.s0) {
  if (&a == &b) throw std::invalid_argument("contact: the two bodies must be different (got '" + a.name + "' twice)");
  molecules_[0] = molecules_of(a, s.beta[0]);
  molecules_[1] = molecules_of(b, s.beta[1]);
  if (law_ == StiffnessLaw::linear) {
    const Body& sub = substrate_ == 0 ? a : b;
    mu_reference_ = s.stiffness_reference;
    if (mu_reference_ == 0.0) mu_reference_ = mean_shear_modulus(sub);
    auto& n = molecules_[substrate_];
    for (std::size_t i = 0; i < n.size(); ++i) n[i] *= shear_modulus(sub, static_cast<Index>(i)) / mu_reference_;
  }
  force_[0].assign(a.size(), Vec3::Zero());
  force_[1].assign(b.size(), Vec3::Zero());
  if (!b.distributed())
    for (Index j = 0; j < static_cast<Index>(b.size()); ++j) columns_.push_back(j);
  if (!a.cloud.boundary_faces.empty() && !b.cloud.boundary_faces.empty()) {
    overlap_[0].emplace(a, b, "all", s.s0, 4.0 * s.cutoff, comm);
    overlap_[1].emplace(b, a, "all", s.s0, 4.0 * s.cutoff, comm);
  }
}

std::string Contact::diagnose(const World& world) {
  if (pairs_.builds() == diagnosed_builds_) return {};
  diagnosed_builds_ = pairs_.builds();
  const std::array<const Body*, 2> bodies = {&a_, &b_};
  for (int k = 0; k < 2; ++k) {
    if (!overlap_[k]) continue;
    const ContactSample s = overlap_[k]->measure();
    if (s.deepest < 0 || s.min_gap >= -0.5 * s0_ || !overlap_[k]->encloses(s.deepest_position)) continue;
    const Body& inside = *bodies[k];
    return interpenetration_message(world.step, inside, *bodies[1 - k], one_rank_id(inside, s.deepest),
                                    inside.cloud.X[s.deepest], s.deepest_position, -s.min_gap, s0_);
  }
  return {};
}

void Contact::choose_partner_ghosts() {
  // This rank's A points, grown by the list's radius: the B particles it may pair with
  // until the next rebuild lie inside.
  const double grow = pairs_.cutoff() + pairs_.skin();
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (Index i = a_.owned_begin(); i < a_.owned_end(); ++i) {
    lo = lo.cwiseMin(points_[0][i]);
    hi = hi.cwiseMax(points_[0][i]);
  }
  std::vector<double> box(6);
  for (int c = 0; c < 3; ++c) {
    box[c] = lo[c] - grow;
    box[3 + c] = hi[c] + grow;
  }
  const std::vector<double> boxes = comm_.gather(box);
  // Each owner of B sends every other rank the ids of its particles inside that rank's box.
  const auto ranks = static_cast<std::size_t>(comm_.size());
  std::vector<std::vector<std::int64_t>> send(ranks), received;
  for (std::size_t r = 0; r < ranks; ++r) {
    if (static_cast<int>(r) == comm_.rank()) continue;
    const double* bx = boxes.data() + 6 * r;
    for (Index j = b_.owned_begin(); j < b_.owned_end(); ++j) {
      const Vec3& p = points_[1][j];
      bool inside = true;
      for (int c = 0; c < 3; ++c) inside = inside && p[c] >= bx[c] && p[c] <= bx[3 + c];
      if (inside) send[r].push_back(j);
    }
  }
  comm_.exchange(send, received);
  std::vector<Index> ghosts;
  for (const auto& from : received) ghosts.insert(ghosts.end(), from.begin(), from.end());
  partner_ghosts_ = par::GhostExchange();
  partner_ghosts_.build(comm_, b_.ghosts.offset(), ghosts);
  columns_.clear();
  for (Index j = b_.owned_begin(); j < b_.owned_end(); ++j) columns_.push_back(j);
  for (const auto& group : partner_ghosts_.ghosts_by_owner()) columns_.insert(columns_.end(), group.begin(), group.end());
  std::sort(columns_.begin(), columns_.end());
}

void Contact::add_forces(World&) {
  const auto start = std::chrono::steady_clock::now();
  physical_points(a_, points_[0]);  // distributed: the owned particles'
  physical_points(b_, points_[1]);
  const bool split = b_.distributed();
  const Index row_begin = a_.owned_begin(), row_end = a_.owned_end();
  const double moved = comm_.max(
      pairs_.largest_move(points_[0], row_begin, row_end, points_[1], b_.owned_begin(), b_.owned_end()));
  const bool stale = moved > 0.5 * pairs_.skin();
  if (split && stale) choose_partner_ghosts();
  if (split) partner_ghosts_.pull(points_[1]);
  if (stale) {
    pairs_.rebuild(points_[0], row_begin, row_end, points_[1], columns_);
    // B's sums run over A's rows in increasing order, each row's partners in the list's.
    plan_term_rows(
        b_sums_, b_, row_begin, row_end, 2,
        [this](Index i, int, const std::function<void(Index)>& emit) {
          for (Index k = pairs_.row_offset()[i]; k < pairs_.row_offset()[i + 1]; ++k) emit(pairs_.partner()[k]);
        },
        split ? &partner_ghosts_ : nullptr);
  }
  const auto& pa = points_[0];
  const auto& pb = points_[1];
  const auto& offset = pairs_.row_offset();
  const auto& partner = pairs_.partner();
  const auto& na = molecules_[0];
  const auto& nb = molecules_[1];
  const double rc2 = cutoff_ * cutoff_;
  pair_force_.resize(pairs_.size());
  row_energy_.resize(a_.size());  // only the owned rows are written and read
  std::size_t active = 0;

#pragma omp parallel for schedule(dynamic, 64) reduction(+ : active) if (worth_threads(row_end - row_begin))
  for (Index i = row_begin; i < row_end; ++i) {
    double e = 0.0;
    Vec3 fi = Vec3::Zero();
    for (Index k = offset[i]; k < offset[i + 1]; ++k) {
      const Index j = partner[k];
      const Vec3 rij = pa[i] - pb[j];
      const double r2 = rij.squaredNorm();
      if (r2 >= rc2) {
        pair_force_[k].setZero();
        continue;
      }
      ++active;
      const double c = na[i] * nb[j];
      double slope_over_r = 0.0;
      e += c * (lj_.energy_and_slope(r2, slope_over_r) - energy_shift_);
      pair_force_[k] = (-c * slope_over_r) * rij;  // on A's particle: -d(c phi)/dx_I
      fi += pair_force_[k];
    }
    row_energy_[i] = e;
    force_[0][i] = fi;
  }
  // B's particles sum their pairs in A's order, across the ranks too (plan_term_rows).
  std::fill(force_[1].begin(), force_[1].end(), Vec3::Zero());
  b_sums_.clear(0);
  for (Index i = row_begin; i < row_end; ++i) {
    const auto sink = b_sums_.sink(0, 0, i);
    for (Index k = offset[i]; k < offset[i + 1]; ++k) sink(partner[k], Vec3(-pair_force_[k]));
  }
  add_term_rows(b_sums_, 0, 1.0, force_[1]);
  add_point_forces(a_, force_[0]);
  add_point_forces(b_, force_[1]);

  ExactSum energy;
  for (Index i = row_begin; i < row_end; ++i) energy.add(row_energy_[i]);
  energy_ = comm_.sum(energy);
  active_pairs_ = static_cast<std::size_t>(comm_.sum(static_cast<std::int64_t>(active)));
  ++evaluations_;
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Distributed: each rank sums the pairs it evaluates; a B ghost's partial sum goes to
// its owner before the maximum.
double Contact::stable_dt(const World&) const {
  if (pairs_.builds() == 0 || comm_.sum(static_cast<std::int64_t>(pairs_.size())) == 0)
    return std::numeric_limits<double>::infinity();
  const auto& offset = pairs_.row_offset();
  const auto& partner = pairs_.partner();
  const auto& na = molecules_[0];
  const auto& nb = molecules_[1];
  const double rc2 = cutoff_ * cutoff_;
  // Per listed pair inside the cutoff: k_IJ; per particle the Gershgorin row sum.
  std::vector<double> row_a(a_.size(), 0.0);
#pragma omp parallel for schedule(dynamic, 64) if (worth_threads(a_.owned_end() - a_.owned_begin()))
  for (Index i = a_.owned_begin(); i < a_.owned_end(); ++i) {
    double g = 0.0;
    for (Index k = offset[i]; k < offset[i + 1]; ++k) {
      const Index j = partner[k];
      const double r2 = (points_[0][i] - points_[1][j]).squaredNorm();
      if (r2 >= rc2) continue;
      const double kij = na[i] * nb[j] * lj_.stiffness(std::sqrt(r2));
      g += kij * (1.0 / a_.inertia[i] + 1.0 / std::sqrt(a_.inertia[i] * b_.inertia[j]));
    }
    row_a[i] = g;
  }
  // B's row sums in x, in A's order over the ranks (plan_term_rows); pairs beyond the
  // cutoff add zero.
  std::vector<Vec3> b_rows(b_.size(), Vec3::Zero());
  b_sums_.clear(0);
  for (Index i = a_.owned_begin(); i < a_.owned_end(); ++i) {
    const auto sink = b_sums_.sink(0, 1, i);
    for (Index k = offset[i]; k < offset[i + 1]; ++k) {
      const Index j = partner[k];
      const double r2 = (points_[0][i] - points_[1][j]).squaredNorm();
      double g = 0.0;
      if (r2 < rc2) {
        const double kij = na[i] * nb[j] * lj_.stiffness(std::sqrt(r2));
        g = kij * (1.0 / b_.inertia[j] + 1.0 / std::sqrt(a_.inertia[i] * b_.inertia[j]));
      }
      sink(j, Vec3(g, 0.0, 0.0));
    }
  }
  add_term_rows(b_sums_, 1, 1.0, b_rows);
  double omega2 = 0.0;
  for (Index i = a_.owned_begin(); i < a_.owned_end(); ++i) omega2 = std::max(omega2, row_a[i]);
  for (Index j = b_.owned_begin(); j < b_.owned_end(); ++j) omega2 = std::max(omega2, b_rows[j].x());
  omega2 = comm_.max(omega2);
  return omega2 > 0.0 ? 2.0 / std::sqrt(omega2) : std::numeric_limits<double>::infinity();
}

void Contact::report(const World&, io::Json& summary) const {
  io::Json j = io::Json::object();
  j.set("energy", energy_);
  j.set("active_pairs", active_pairs_);
  j.set("listed_pairs", comm_.sum(static_cast<std::int64_t>(pairs_.size())));
  j.set("pair_list_builds", pairs_.builds());
  Vec3 total = Vec3::Zero();
  for (Index i = a_.owned_begin(); i < a_.owned_end(); ++i) total += force_[0][i];
  io::Json force = io::Json::array();
  for (int k = 0; k < 3; ++k) force.push_back(comm_.sum(total[k]));
  j.set("force_on_" + a_.name, force);
  if (law_ == StiffnessLaw::linear) j.set("stiffness_reference", mu_reference_);
  j.set("force_evaluations", evaluations_);
  j.set("seconds", seconds_);  // wall time of add_forces: compare with the run's wall_time
  log_.add_to(j);
  summary.set("contact " + a_.name + " " + b_.name, j);
}

std::vector<materials::OutputField> Contact::output_fields(const Body& body) const {
  return contact_force_fields(body, a_, b_, force_);
}

}  // namespace rkpm::sim

namespace rkpm::terms::contact {

namespace {

// Refuses clouds with a surface hollow no particle of the potential pushes back from
// (holding.hpp), naming s0 and the body whose cloud is too coarse.
void check_holding(const scene::ParamSet& params, const sim::ContactSettings& s, const sim::Body& a,
                   const sim::Body& b) {
  const std::array<const sim::Body*, 2> bodies = {&a, &b};
  for (int k = 0; k < 2; ++k) {
    const sim::Body& body = *bodies[k];
    const sim::Body& other = *bodies[1 - k];
    const sim::SurfaceHollow hollow = sim::widest_facing_hollow(body, sim::reference_centroid(other));
    if (hollow.radius < s.s0) continue;
    throw sim::SetupError(params.error(
        "s0", fmt::format(
                  "an equilibrium distance that holds the clouds apart: the surface of body '{}' facing '{}' "
                  "has a hollow {:.4g} m = {:.3f} s0 from its nearest particles (around ({:.4g}, {:.4g}, {:.4g}) "
                  "m); its particles repel only within s0, so particles of '{}' would fall through its surface "
                  "layer. Use s0 > {:.4g} m, or a finer cloud for '{}' (its [body.cloud] resolution: surface "
                  "particles on a square grid less than sqrt(2) s0 = {:.4g} m apart)",
                  body.name, other.name, hollow.radius, hollow.radius / s.s0, hollow.centre.x(), hollow.centre.y(),
                  hollow.centre.z(), other.name, hollow.radius, body.name, std::sqrt(2.0) * s.s0)).what());
  }
}

}  // namespace

std::unique_ptr<sim::Term> build(const scene::ParamSet& params, sim::World& world) {
  const sim::ContactSettings s = settings_table().read(params);
  sim::Body& a = named_body(world, params, s.bodies[0]);
  sim::Body& b = named_body(world, params, s.bodies[1]);
  // The surface formulation meets a faceted surface, with no gaps between particles to
  // fall through: the hollow check is the pair sum's.
  if (s.formulation == sim::ContactFormulation::surface)
    return constructed(params, [&]() -> std::unique_ptr<sim::Term> {
      return std::make_unique<sim::SurfaceContact>(a, b, s, *world.comm);
    });
  check_holding(params, s, a, b);
  return constructed(params,
                     [&]() -> std::unique_ptr<sim::Term> { return std::make_unique<sim::Contact>(a, b, s, *world.comm); });
}

}  // namespace rkpm::terms::contact
