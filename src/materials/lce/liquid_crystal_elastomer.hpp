// Active nematic liquid-crystal elastomer: the cell (microtubule cytoskeleton)
// model of the seed paper (Fan & Li 2014, section 2.1, Eq. 1-7).
//
// Passive energy per reference volume [Pa]. The seed's Eq. 2 deviatoric part is
// the Warner-Terentjev "trace formula"
//   mu/2 [ |F|^2 - (s-1)/s |F^T h|^2 + (s-1) |F h0|^2 - (s-1)^2/s (F^T h . h0)^2 - 3 ]
//     = mu/2 [ tr(l0 F^T l^-1 F) - 3 ],
//   l = I + (s-1) h h^T,  l^-1 = I - (s-1)/s h h^T,  l0 = I + (s-1) h0 h0^T.
// That alone gives P = mu l^-1 F l0, which is mu I (not zero) at F = I, h = h0;
// the seed closes it with an incompressibility pressure p. We use the
// compressible extension
//   W = mu/2 [ tr(l0 F^T l^-1 F) - 3 - 2 ln J ] + (K/2) (ln J)^2 + W_Frank,
// whose elastic first Piola-Kirchhoff stress is
//   P_el = mu (l^-1 F l0 - F^-T) + K ln J F^-T.
// Stress-free reference, exactly: at F = I, h = h0 (unit), l^-1 l0 = I and
// F^-T = I, so mu (l^-1 F l0 - F^-T) = 0; ln J = 0 kills the bulk term; and
// Grad h = 0 kills the Frank term. The energy is 0 there as well:
// tr(l0 l^-1) = 3 + (s-1) - (s-1)/s - (s-1)^2/s = 3.
// Small strain (h = h0): shear modulus mu (for shears not rotating h; the soft
// modes are softer), and K acts as Lame's first parameter: the small-strain
// bulk modulus is K + 2 mu / 3 and the P-wave modulus K + 2 mu.
// The energy is written as the polynomial above for any h; the stress formulas
// are exact derivatives of it even if |h| has drifted from 1.
//
// Frank (director-gradient) energy, one-constant form per current volume:
//   W_Frank = J kf |G|^2,  kf = kappa (s-1)^2 / (2 s),  G = grad_x h = (Grad_X h) F^-1,
// G_ij = d h_i / d x_j. At fixed h and Grad_X h, d|G|^2/dF = -2 G^T G F^-T, so
//   P_Frank = J kf ( |G|^2 I - 2 G^T G ) F^-T,   sigma_Frank = kf ( |G|^2 I - 2 G^T G ),
// the Ericksen stress of a one-constant nematic. The seed's Eq. 3-4 write this
// term as +kappa (s-1)^2/s G G^T (other sign, transposed indices, no |G|^2 I);
// we derive ours from the energy so that P = dW/dF holds exactly, which the
// energy-conserving force loop relies on.
//
// Active stress (seed Eq. 1), not derivable from W, kept separate:
//   sigma_a = -zeta h (x) h,   P_a = J sigma_a F^-T.
// SIGN CONVENTION: zeta > 0 makes the active stress compressive along h, so a
// free body elongates along h (extensile): in a free homogeneous body the
// passive stress must balance it, sigma_passive = +zeta h h, a tension along h.
// zeta < 0 contracts the body along h (contractile). (The seed's text calls the
// -zeta h h term "contractile"; with this sign that is zeta < 0.)
//
// Cauchy stress sigma = P F^T / J is not symmetric while the director is off
// its equilibrium: J skew(sigma) = (h g^T - g h^T) / 2 with g = dW/dh, the
// torque the director exerts on the network. It is symmetric at equilibrium.
//
// Director evolution (seed Eq. 5-7), Allen-Cahn with a scalar mobility L:
//   D~h/Dt = -L (I - h h^T) dF/dh,   dF/dh = dW/dh - Div_X( dW/d(Grad_X h) ),
//   D~h/Dt = dh/dt + (1/2) (l^T h - w h),   l = velocity gradient, w = (l - l^T)/2,
// so dh/dt = D~h/Dt - (1/2)(l^T h - w h). The projection (I - h h^T) makes the
// relaxational part tangent to the unit sphere, so it keeps |h| = 1 to first
// order in dt; the convective part of Eq. 7 has the component -(1/2) h.D h along
// h (D = (l + l^T)/2), so the integrator must renormalise h after each step.
#pragma once

#include "rkpm/common/types.hpp"
#include "materials/kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace rkpm::materials {

// Director state at one material point.
struct DirectorPoint {
  Vec3 h = Vec3::UnitX();       // current director (unit vector, nematic: h ~ -h)
  Vec3 h0 = Vec3::UnitX();      // reference director, the network's memory (unit)
  Mat3 grad_h = Mat3::Zero();   // Grad_X h, (i, J) = d h_i / d X_J [1/m], from the RK smoothed gradients
};

struct LiquidCrystalElastomer {
  double mu = 0.0;        // [Pa]  shear modulus of the network (Eq. 2)
  double K = 0.0;         // [Pa]  volumetric coefficient (our compressible extension; Lame-like, see above)
  double s = 1.0;         // [-]   step-length anisotropy l_par / l_perp of the chains (Eq. 2); s > 1 prolate
  double kappa = 0.0;     // [N]   Frank modulus (Eq. 2); Frank length sqrt(kappa / mu)
  double zeta = 0.0;      // [Pa]  activity (Eq. 1); > 0 extensile, < 0 contractile (see above)
  double mobility = 0.0;  // [1/(Pa s)] Allen-Cahn mobility L of the director (Eq. 5), scalar

  // Throws std::invalid_argument (naming the parameter and value) unless
  // mu > 0, K >= 0, s > 0, kappa >= 0, mobility >= 0 and all are finite.
  void validate() const;

  // kf = kappa (s-1)^2 / (2 s): W_Frank = J kf |G|^2.
  double frank_coefficient() const { return kappa * (s - 1.0) * (s - 1.0) / (2.0 * s); }

  // l^-1 = I - (s-1)/s h h^T (current step-length tensor, inverted).
  Mat3 inverse_step_length(const Vec3& h) const {
    return Mat3::Identity() - ((s - 1.0) / s) * (h * h.transpose());
  }
  // l0 = I + (s-1) h0 h0^T (reference step-length tensor).
  Mat3 reference_step_length(const Vec3& h0) const {
    return Mat3::Identity() + (s - 1.0) * (h0 * h0.transpose());
  }

  // Passive free energy per reference volume [Pa] (elastic + Frank).
  double energy(const Mat3& F, const DirectorPoint& d) const {
    const Kinematics k(F);
    const double trace_term = (reference_step_length(d.h0) * F.transpose() * inverse_step_length(d.h) * F).trace();
    const Mat3 G = d.grad_h * k.F_inv;
    return 0.5 * mu * (trace_term - 3.0 - 2.0 * k.log_J) + 0.5 * K * k.log_J * k.log_J +
           k.J * frank_coefficient() * G.squaredNorm();
  }

  // The part of W that depends on h at fixed F, h0 and Grad_X h [Pa]: the h of
  // tr(l0 F^T l^-1 F) = tr(l0 F^T F) - (s-1)/s (F^T h) . l0 (F^T h), so
  //   W_h = -mu/2 (s-1)/s [ |F^T h|^2 + (s-1) (h0 . F^T h)^2 ].
  // Everything else in W (the Frank term included: it has no explicit h) is the same
  // for every h, so a director update at fixed F and Grad_X h changes W by the change
  // of W_h alone. The director's energy ledger books that change (sim/director.cpp)
  // from two passes of this instead of two of energy(): no inverse, no logarithm.
  double director_energy(const Mat3& F, const Vec3& h, const Vec3& h0) const {
    const Vec3 v = F.transpose() * h;
    const double along = h0.dot(v);
    return -0.5 * mu * ((s - 1.0) / s) * (v.squaredNorm() + (s - 1.0) * along * along);
  }

  // Passive first Piola-Kirchhoff stress dW/dF at fixed h, h0, Grad_X h [Pa].
  Mat3 first_piola_passive(const Mat3& F, const DirectorPoint& d) const {
    return passive_piola(F, d, Kinematics(F));
  }
  // Active first Piola-Kirchhoff stress J sigma_a F^-T (Eq. 1) [Pa].
  Mat3 first_piola_active(const Mat3& F, const Vec3& h) const {
    const Kinematics k(F);
    return k.J * cauchy_active(h) * k.F_inv_T;
  }
  // Total P (passive + active): what the force loop needs.
  Mat3 first_piola(const Mat3& F, const DirectorPoint& d) const {
    const Kinematics k(F);
    return passive_piola(F, d, k) + k.J * cauchy_active(d.h) * k.F_inv_T;
  }
  // What the force loop needs, from one set of kinematics: P with the active part
  // scaled by `activity` (the local value of the activity field, 1 = zeta), and the
  // Frank flux dW/d(Grad_X h) when `frank_flux` is given.
  Mat3 first_piola(const Mat3& F, const DirectorPoint& d, double activity, Mat3* frank_flux) const {
    const Kinematics k(F);
    if (frank_flux) *frank_flux = frank_flux_at(d, k);
    return passive_piola(F, d, k) + (activity * k.J) * cauchy_active(d.h) * k.F_inv_T;
  }

  // Passive Cauchy stress P_passive F^T / J [Pa] (non-symmetric off director equilibrium).
  Mat3 cauchy_passive(const Mat3& F, const DirectorPoint& d) const {
    const Kinematics k(F);
    const Mat3 network = inverse_step_length(d.h) * F * reference_step_length(d.h0) * F.transpose();
    const Mat3 G = d.grad_h * k.F_inv;
    return (1.0 / k.J) * (mu * (network - Mat3::Identity()) + K * k.log_J * Mat3::Identity()) +
           frank_coefficient() * (G.squaredNorm() * Mat3::Identity() - 2.0 * G.transpose() * G);
  }
  // Active Cauchy stress -zeta h (x) h (Eq. 1) [Pa].
  Mat3 cauchy_active(const Vec3& h) const { return -zeta * (h * h.transpose()); }
  // Total Cauchy stress [Pa].
  Mat3 cauchy(const Mat3& F, const DirectorPoint& d) const { return cauchy_passive(F, d) + cauchy_active(d.h); }

  // dW/dh at fixed F, h0 and Grad_X h (the Frank term has no explicit h):
  //   -mu (s-1)/s [ F F^T h + (s-1) (h . F h0) F h0 ]  [Pa]
  // (minus the bracket of the seed's Eq. 6, which is -dW/dh up to L).
  Vec3 director_driving_force(const Mat3& F, const DirectorPoint& d) const {
    const Vec3 Fh0 = F * d.h0;
    return -mu * ((s - 1.0) / s) * (F * (F.transpose() * d.h) + (s - 1.0) * d.h.dot(Fh0) * Fh0);
  }

  // dW/d(Grad_X h) = 2 kf J G F^-T = kappa (s-1)^2/s J G F^-T  [N/m^2 * m = Pa m].
  // Its reference divergence, (Div_X)_i = sum_J d(flux_iJ)/dX_J, enters the
  // functional derivative dF/dh = dW/dh - Div_X(flux); the simulator assembles
  // it with the RK smoothed gradients and passes it to director_rate.
  // (The seed's Eq. 6 writes this term as Div[F^-1 J F^-T G]: other index order.)
  Mat3 frank_flux(const Mat3& F, const DirectorPoint& d) const { return frank_flux_at(d, Kinematics(F)); }
  Mat3 frank_flux_at(const DirectorPoint& d, const Kinematics& k) const {
    return (2.0 * frank_coefficient() * k.J) * (d.grad_h * k.F_inv * k.F_inv_T);
  }

  // The part of dF/dh across h, (I - h h^T) dF/dh [Pa], with
  // frank_divergence = Div_X(frank_flux): what Eq. 5 drives the director by, zero at the
  // director's own equilibrium.
  Vec3 transverse_molecular_field(const Mat3& F, const DirectorPoint& d,
                                  const Vec3& frank_divergence = Vec3::Zero()) const {
    const Vec3& h = d.h;
    const Vec3 dF_dh = director_driving_force(F, d) - frank_divergence;
    return dF_dh - h * h.dot(dF_dh);
  }

  // dh/dt [1/s] from Eq. 5 and 7 (see the header comment), given the velocity
  // gradient l = dF/dt F^-1 and frank_divergence = Div_X(frank_flux) [Pa].
  Vec3 director_rate(const Mat3& F, const DirectorPoint& d, const Mat3& velocity_gradient,
                     const Vec3& frank_divergence = Vec3::Zero()) const {
    const Vec3& h = d.h;
    const Vec3 corotational_rate = -mobility * transverse_molecular_field(F, d, frank_divergence);
    const Mat3 spin = 0.5 * (velocity_gradient - velocity_gradient.transpose());
    return corotational_rate - 0.5 * (velocity_gradient.transpose() * h - spin * h);
  }

  // Upper bound [Pa] on the stiffness of the director relaxation at fixed F, so that the
  // explicit update h += dt L (...) is stable for dt < 2 / (L bound). Local part: the
  // relaxation is dh/dt = L (I - h h^T) M h with M = mu (s-1)/s (F F^T + (s-1) F h0 (F h0)^T)
  // (director_driving_force is -M h), whose linearisation in the tangent plane at the
  // equilibrium has the rates L (lambda_i - lambda_1): at most the spread
  // lambda_max - lambda_min of M (mu (s-1)^2 / s at rest). Frank part: a diffusion of h in
  // X with coefficient D = 2 kf J C^-1 (frank_flux); the discrete Laplacian on particles
  // `spacing` apart has eigenvalues up to 4 / spacing^2 per direction, 4 tr(D) / spacing^2
  // in all.
  double director_stiffness(const Mat3& F, const Vec3& h0, double spacing) const {
    const Kinematics k(F);
    const Vec3 Fh0 = F * h0;
    const Mat3 M = (mu * (s - 1.0) / s) * (F * F.transpose() + (s - 1.0) * Fh0 * Fh0.transpose());
    const Vec3 eigenvalues = symmetric_eigenvalues(M);  // ascending
    const double local = eigenvalues[2] - eigenvalues[0];
    const double frank = 2.0 * frank_coefficient() * k.J * k.F_inv.squaredNorm() * 4.0 / (spacing * spacing);
    return local + frank;
  }

  // Director minimising the elastic energy at fixed F (unit; sign chosen with
  // h . F h0 >= 0). W depends on h only through -mu (s-1)/(2s) h.(F l0 F^T) h,
  // so for s > 1 it is the leading eigenvector of F l0 F^T, for s < 1 the
  // trailing one; for s = 1 W does not depend on h and F h0 / |F h0| is returned.
  Vec3 equilibrium_director(const Mat3& F, const Vec3& h0) const;

  // Conservative longitudinal wave speed [m/s] in the reference configuration
  // (rho0 = reference density [kg/m^3]); see docs/theory/materials.md. With a = N.l0 N,
  // b = F^-T N, the acoustic tensor satisfies, for unit m and N,
  //   m.Q(N) m = mu (N.l0 N)(m.l^-1 m) + (mu + K - K ln J)(b.m)^2 + 2 kf J |G m|^2 |b|^2
  //            <= N.[ mu lmax(l^-1) l0 + (max(0, mu + K - K ln J) + 2 kf J |G|^2) C^-1 ] N,
  // so c^2 rho0 = lambda_max of that symmetric matrix. At F = I, h = h0, Grad h = 0
  // it is K + mu + s mu for s >= 1, i.e. the P-wave speed sqrt((K + 2 mu)/rho0)
  // to within (s-1) mu / (2 (K + 2 mu)) relative (0.5 % for s = 2, K = 100 mu);
  // the exact maximum lies in between (oblique directions couple through s).
  double wave_speed(const Mat3& F, const DirectorPoint& d, double rho0) const {
    const Kinematics k(F);
    const double beta = (s - 1.0) / s;
    const double largest_inverse_step = std::max(1.0, 1.0 - beta * d.h.squaredNorm());
    const double volumetric = std::max(0.0, mu + K - K * k.log_J);
    const double frank = 2.0 * frank_coefficient() * k.J * (d.grad_h * k.F_inv).squaredNorm();
    const Mat3 bound = (mu * largest_inverse_step) * reference_step_length(d.h0) +
                       (volumetric + frank) * (k.F_inv * k.F_inv_T);
    return std::sqrt(std::max(symmetric_eigenvalues(bound)[2], 0.0) / rho0);
  }

 private:
  Mat3 passive_piola(const Mat3& F, const DirectorPoint& d, const Kinematics& k) const {
    const Mat3 G = d.grad_h * k.F_inv;
    const Mat3 frank_stress = frank_coefficient() * (G.squaredNorm() * Mat3::Identity() - 2.0 * G.transpose() * G);
    return mu * (inverse_step_length(d.h) * F * reference_step_length(d.h0)) +
           (K * k.log_J - mu) * k.F_inv_T + k.J * frank_stress * k.F_inv_T;
  }
};

}  // namespace rkpm::materials
