// Coarse-grained adhesive contact between two bodies (CGCM, seed Eq. 12-14).
//
// Continuum energy (Eq. 14): Pi_AC = int_1 int_2 beta1 beta2 phi(|x1 - x2|) dv2 dv1 with
// the 12-6 Lennard-Jones potential of Eq. 13, phi(r) = eps (s0/r)^12 - 2 eps (s0/r)^6.
// beta are molecules per CURRENT volume, so beta dv = beta0 dV is conserved: particle I
// carries the fixed number of molecules n_I = beta0 V_I (V_I its reference volume).
// Nodal quadrature of both integrals gives the pair sum
//     Pi_AC = sum_{I in A} sum_{J in B, r_IJ < cutoff} n_I n_J w_J [phi(r_IJ) - phi(cutoff)],
//     r_IJ = |p_I - p_J|,  p_J = X_J + sum_K Psi_K(X_J) d_K (the physical positions, body.hpp),
// with w_J = 1, or the substrate's local stiffness ratio under the `linear` stiffness
// law (the seed: "eps ... is dependent on substrate elasticity"):
//     eps_J = eps w_J,  w_J = mu(X_J) / mu_ref,
// mu the small-strain shear modulus of the substrate at particle J and mu_ref given or
// the volume-weighted mean. The forces on the physical points,
//     f_I = -sum_J n_I n_J w_J phi'(r) (p_I - p_J)/r,   f_J = -(same pair term),
// are equal and opposite per pair, and act on the generalized coordinates as
// sum_J Psi_K(X_J) f_J: the exact gradient of the sum with respect to d (the RK
// functions reproduce constants, so the total force and momentum balance are kept),
// and the term is conservative (its energy is reported to the ledger).
// Why physical positions: a force on the generalized positions X + d of boundary
// particles also drives d away from the field it interpolates, a mode only the
// stabilization (proportional to mu) resists; under adhesion the generalized
// positions then stay apart while the physical surfaces interpenetrate.
// Bodies without RK operators (tests) use p = X + d.
// The potential is truncated and shifted: subtracting phi(cutoff) leaves every force
// unchanged and makes the energy continuous when a pair crosses the cutoff, so the
// stored energy stays consistent with the work of the forces (an unshifted energy
// jumps by n n w phi(cutoff) at every crossing). The forces are those of the
// truncated potential; docs/theory/contact.md gives the resulting half-space traction law
// and its deviation from the untruncated one.
// Pairs come from a Verlet list with a skin (contact_pairs.hpp).
//
// Distributed: a rank evaluates the pairs of the particles of A it owns, against the
// particles of B it owns and the B ghosts near them. Those ghosts are chosen at each
// rebuild of the list, which every rank makes together as soon as any particle moved
// more than skin/2: each rank states the box of its A points grown by cutoff + skin,
// and the owners of B send it their particles inside. Between rebuilds nothing moves
// more than skin/2, so every pair within the cutoff has its B particle among them.
// Every step the ghosts' physical points are pulled from their owners and the pair
// forces on them pushed back, summed in rank order.
#pragma once

#include "terms/contact/contact_pairs.hpp"
#include "terms/contact/contact_report.hpp"
#include "terms/contact/settings.hpp"
#include "rkpm/par/ghost_exchange.hpp"
#include "rkpm/sim/world.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace rkpm::sim {

// phi(r) = eps [(s0/r)^12 - 2 (s0/r)^6] (Eq. 13), minimum -eps at r = s0.
struct LennardJones {
  double eps = 0.0, s0 = 0.0;
  double energy(double r) const;
  double derivative(double r) const;         // phi'(r)
  double second_derivative(double r) const;  // phi''(r)
  // Largest eigenvalue magnitude of the pair Hessian d^2 phi / dx dx:
  // max(|phi''(r)|, |phi'(r)| / r) (along and across the bond).
  double stiffness(double r) const;
  // Both at once from the squared distance, without roots or pow (the force loop):
  // returns phi(r) and sets derivative_over_r = phi'(r) / r.
  double energy_and_slope(double r2, double& derivative_over_r) const {
    const double inv_r2 = 1.0 / r2;
    const double u2 = s0 * s0 * inv_r2, u6 = u2 * u2 * u2;
    derivative_over_r = eps * 12.0 * (u6 - u6 * u6) * inv_r2;
    return eps * (u6 * u6 - 2.0 * u6);
  }
};

class Contact final : public Term {
 public:
  Contact(Body& a, Body& b, const ContactSettings& settings, const par::Comm& comm = par::Comm::self());
  std::string name() const override { return "contact"; }
  bool distributed() const override { return true; }
  void add_forces(World& world) override;
  double stored_energy(const World&) const override { return energy_; }
  // Critical step of the pair springs at the current configuration: with k_IJ the
  // pair-Hessian bound above times n_I n_J w_J, Gershgorin's bound on the largest
  // eigenvalue of M^-1/2 K M^-1/2 is omega^2 <= max_P sum_Q k_PQ (1/m_P + 1/sqrt(m_P m_Q)),
  // and dt = 2 / omega. The integrator multiplies by dt_safety and re-estimates every
  // stable_step_interval steps (10 by default).
  double stable_dt(const World&) const override;
  void report(const World&, io::Json& summary) const override;
  // With a report surface: the first body's centroid, smallest gap and contact patch.
  // At each rebuild of the pair list (no particle has moved more than skin/2 since the
  // last look): a boundary particle of either body more than s0/2 inside the other's
  // closed surface (nearest face's side, confirmed by the winding number) means the law
  // did not hold the clouds apart. The diagnosis names the particle and its depth.
  std::string diagnose(const World&) override;
  std::vector<std::string> history_columns() const override { return log_.history_columns(); }
  std::string history_values(const World&) const override { return log_.history_values(); }
  // Frames show each particle's contact force (force_on) as "contact_force_<other
  // body>": summed over a patch of the surface and divided by its area, the traction.
  std::vector<materials::OutputField> output_fields(const Body& body) const override;

  // At the last force evaluation (over every rank): the energy, the number of pairs
  // inside the cutoff.
  double energy() const { return energy_; }
  std::size_t active_pairs() const { return active_pairs_; }
  const ContactPairs& pairs() const { return pairs_; }
  // Molecules of each particle, n_I w_I (index 0 = body A, 1 = body B).
  const std::vector<double>& molecules(int body) const { return molecules_[body]; }
  // Forces on the physical points of each body (with RK operators, the generalized
  // forces are sum_J Psi_I(X_J) of these); distributed, valid at the owned particles.
  const std::vector<Vec3>& force_on(int body) const { return force_[body]; }

  // The declared report (report_surface): measures the present state and keeps the
  // first sample and the smallest gap over all samples for the summary. Null report:
  // has_report() is false and sample() must not be called.
  bool has_report() const { return log_.declared(); }
  ContactSample sample() const { return log_.sample(); }
  // Wall time spent in add_forces since construction [s] (the cost of the term).
  double seconds() const { return seconds_; }

 private:
  // Distributed: chooses the B ghosts near this rank's A points (collective).
  void choose_partner_ghosts();

  Body& a_;
  Body& b_;
  const par::Comm& comm_;
  LennardJones lj_;
  double cutoff_;
  double energy_shift_;  // phi(cutoff)
  ContactPairs pairs_;
  std::array<std::vector<double>, 2> molecules_;
  std::array<std::vector<Vec3>, 2> force_;   // on the physical points
  std::array<std::vector<Vec3>, 2> points_;  // physical positions at the last evaluation
  std::vector<Vec3> pair_force_;    // on A's particle of each listed pair
  std::vector<double> row_energy_;  // per particle of A
  std::vector<Index> columns_;      // the particles of B this rank's rows may pair with, increasing
  par::GhostExchange partner_ghosts_;  // distributed: the B ghosts among them
  // The pairs' sums at B's particles (channel 0: the force; 1: the stiffness rows of the
  // stable step), over A's rows in the one-process order; planned at each rebuild.
  mutable rk::RowScatter b_sums_;
  double energy_ = 0.0, mu_reference_ = 0.0;
  std::size_t active_pairs_ = 0;
  StiffnessLaw law_;
  int substrate_;
  ContactReportLog log_;
  // Each body's boundary particles against the other's whole surface (diagnose); absent
  // for bodies without faces (clouds made in tests).
  std::array<std::optional<ContactReport>, 2> overlap_;
  double s0_;
  std::size_t diagnosed_builds_ = 0;
  std::size_t evaluations_ = 0;
  double seconds_ = 0.0;
};

}  // namespace rkpm::sim
