// Adhesive contact in the surface formulation: the contact term with
// `formulation = "surface"` (params.cpp).
//
// The pair sum of contact.hpp is a nodal quadrature of seed Eq. 14's double volume
// integral. Across each surface it weighs the particle layers with a trapezoid rule,
// which the potential's steep core makes coarse at the spacings a cell can afford: two
// flat bodies made of layers 0.2-0.6 um apart adhere with 0.77-1.19 of the continuum's
// work of adhesion for s0 = 0.75 um, and reach it only below 0.1 um
// (docs/verification/adhesion.md). Here both depth integrals are done in closed form
// for locally flat bodies, the surface-potential formulation of Sauer & De Lorenzis
// (Comput. Methods Appl. Mech. Engrg. 253, 369 (2013)): each boundary particle a of the
// first body, with its reference share A_a of the surface, carries the energy of two
// half-spaces at its gap g_a from the second body's surface,
//     Pi = sum_a c_a W(g_a),   c_a = A_a beta1 beta2 w_a          (half_space_law.hpp)
// with g_a the signed distance of a's physical point to the second body's boundary
// faces (> 0 on the side of the outward normal; a quadrilateral is four triangles about
// the mean of its corners, so that no diagonal biases the surface sideways when it
// bends) and w_a the stiffness law's factor: the
// substrate's mu / mu_ref at the nearest point (interpolated in the face) or at a,
// whichever body the substrate is. The force on a's point is c_a sigma(g_a) e_a, and
// the face's corners take the opposite force in the weights of the nearest point, so
// momentum balances. e_a is the corners' normals (area-weighted means of their faces')
// interpolated at the nearest point. On a flat face it is the unit gradient of the
// distance and the forces are exactly -dPi/dx (the corners' share is the distance's
// gradient with respect to them); where the faces meet at an angle it differs from
// that gradient by the angle, but it turns continuously across their edges, where the
// gradient jumps: a particle over the valley between two facets of a bent substrate
// then feels no force that flips with its side, which held relaxations at a residual
// of 2e-5 with the gradient's direction (docs/verification/adhesion.md). Under the
// stiffness law on the second body, w_a changes as the nearest point slides along the
// face: that adds -A_a beta1 beta2 W(g_a) grad w (w linear in each triangle, the
// gradient in its plane), the pull toward stronger adhesion that drives durotaxis
// (seed section 4.3); the corners take it back in the same weights. Below g_min = s0 / 4 the energy is continued
// linearly, with the traction of g_min: a particle pressed that far has failed, and
// `diagnose` stops the run once it is s0 / 2 inside.
//
// Assumptions, those of the adhesive contact theories it is checked against: the
// surfaces' radii of curvature are large against the cutoff (Derjaguin's
// approximation), and the strains at the surface small (reference areas and
// densities). One rank only (the term is refused on more).
#pragma once

#include "terms/contact/contact_report.hpp"
#include "terms/contact/half_space_law.hpp"
#include "terms/contact/settings.hpp"
#include "rkpm/rk/row_scatter.hpp"
#include "rkpm/sim/world.hpp"

#include <array>
#include <vector>

namespace rkpm::sim {

class SurfaceContact final : public Term {
 public:
  SurfaceContact(Body& a, Body& b, const ContactSettings& settings, const par::Comm& comm = par::Comm::self());
  std::string name() const override { return "contact"; }
  void add_forces(World& world) override;
  double stored_energy(const World&) const override { return energy_; }
  // Gershgorin's bound on omega^2 with each particle's spring k_a = c_a max(|sigma'|,
  // |sigma| / g) at its present gap, shared with the face's corners in their
  // weights (as Contact::stable_dt does for pairs): dt = 2 / omega.
  double stable_dt(const World&) const override;
  void report(const World&, io::Json& summary) const override;
  // A boundary particle of the first body more than s0/2 behind the second body's
  // surface (at the last force evaluation).
  std::string diagnose(const World&) override;
  std::vector<std::string> history_columns() const override { return log_.history_columns(); }
  std::string history_values(const World&) const override { return log_.history_values(); }
  // "contact_force_<other body>" on both bodies' physical points, as Contact's.
  std::vector<materials::OutputField> output_fields(const Body& body) const override;

  double energy() const { return energy_; }
  // Particles of the first body within the cutoff of the second at the last evaluation.
  std::size_t active_particles() const { return active_; }

 private:
  // Where boundary particle a of the first body meets the second body's surface.
  struct Foot {
    int face = -1;                      // -1: no face within the cutoff
    std::array<double, 4> weight{};     // the nearest point's weights on the face's corners
    double gap = 0.0;                   // signed distance [m]
    Vec3 direction = Vec3::Zero();      // the corners' normals interpolated at the nearest point
    double scale = 0.0;                 // c_a = A_a beta1 beta2 w_a [1/m^4]
    Vec3 scale_gradient = Vec3::Zero(); // A_a beta1 beta2 times the gradient of w along the face [1/m^5]
  };
  void find_feet();
  double factor_at(const Foot& foot, Index a_particle) const;
  // The gradient of the second body's stiffness factor along triangle (p0, p1, p2): face
  // corners k and k1 and the centre (a quadrilateral) or corner 2 (a triangle); zero
  // without the law on the second body.
  Vec3 factor_gradient(const Vec3& p0, const Vec3& p1, const Vec3& p2, const std::array<Index, 4>& face, int k,
                       int k1, int corners) const;
  double spring(const Foot& foot) const;  // k_a [N/m]

  Body& a_;
  Body& b_;
  HalfSpaceLaw law_;
  double s0_, gap_floor_;
  double density_product_;                       // beta1 beta2 [1/m^6]
  std::array<std::vector<double>, 2> stiffness_factor_;  // mu / mu_ref per particle (linear law), or empty
  std::vector<Index> surface_;                   // the first body's boundary particles, increasing
  std::vector<double> area_;                     // their reference areas [m^2]
  std::vector<std::array<Index, 4>> faces_;      // the second body's, outward order; -1: a triangle
  std::vector<Index> corners_;                   // their particles, increasing
  std::vector<Vec3> points_a_, points_b_;        // physical points (indexed by particle)
  std::vector<Vec3> centres_;                    // face centres at the last evaluation
  std::vector<Vec3> corner_normals_;             // unit normals at the faces' corners (by particle)
  std::vector<Foot> feet_;                       // per entry of surface_
  std::array<std::vector<Vec3>, 2> force_;       // on the physical points, by particle
  rk::RowScatter scatter_a_, scatter_b_;
  ContactReportLog log_;
  double energy_ = 0.0, mu_reference_ = 0.0;
  std::size_t active_ = 0, evaluations_ = 0;
  double seconds_ = 0.0;
};

}  // namespace rkpm::sim
