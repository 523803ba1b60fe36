// Finite-strain viscoelastic solid: a generalized Maxwell model (Prony series) on top
// of the compressible neo-Hookean solid (neo_hookean.hpp). Not part of the seed paper:
// cytoplasm and the gels around cells relax their shear stress in time, which a purely
// elastic model cannot show.
//
// Model. An equilibrium branch (the neo-Hookean solid, mu and lambda) in parallel with
// n <= 4 Maxwell branches, each a neo-Hookean spring of shear modulus beta_i mu in series
// with a dashpot of relaxation time tau_i. Branch i's internal variable is its viscous
// right Cauchy-Green tensor Cv_i = Fv_i^T Fv_i (Sidoroff's split F = Fe_i Fv_i, as in
// Reese & Govindjee 1998, Int. J. Solids Struct. 35:3455): symmetric, det Cv_i = 1,
// Cv_i = I in the reference state. With C = F^T F, J = det F, Cbar = J^(-2/3) C,
//
//   W(F, Cv) = W_NH(F) + sum_i psi_i,   W_NH = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,
//   psi_i    = beta_i mu / 2 (tr(Cbar Cv_i^-1) - 3)                                     (1)
//
// psi_i is the isochoric neo-Hookean energy of the branch's elastic part Fe_i = F Fv_i^-1
// (tr(Fe^T Fe) = tr(C Cv^-1)): the branches carry shear only, so the bulk modulus
// lambda + 2 mu / 3 is the same at every rate (bulk relaxation of a gel is poroelastic,
// not this model's). psi_i >= 0, and psi_i = 0 exactly when Cv_i = Cbar: the eigenvalues
// of Cbar Cv_i^-1 are positive with product 1, so their sum is >= 3 (AM-GM).
//
// Stress at fixed internal variables (exact derivative of (1); d J^(-2/3) / dF =
// -2/3 J^(-2/3) F^-T, d tr(F G F^T) / dF = 2 F G for symmetric G):
//
//   P = mu F + (lambda ln J - mu) F^-T + mu J^(-2/3) [ F Gsum - tr(C Gsum)/3 F^-T ],
//   Gsum = sum_i beta_i Cv_i^-1.                                                        (2)
//
// Small strain (Cbar = I + 2 e, Cv = I + 2 v, both deviatoric to first order):
// psi_i = beta_i mu |e - v_i|^2, so the branch's shear stress is 2 beta_i mu (e - v_i).
//
// Evolution: geodesic relaxation. At fixed F each branch's elastic left Cauchy-Green
// tensor Be_i = Fbar Cv_i^-1 Fbar^T (Fbar = J^(-1/3) F, det Be_i = 1) relaxes along
//
//   d/dt ln Be_i = -ln Be_i / tau_i   (Be_i's principal directions fixed),             (3)
//
// the linear Maxwell law written in the branch's elastic Hencky strain: the elastic
// stretches decay as lambda_e(t) = lambda_e(0)^exp(-t/tau). In Cv_i it is
// dCv_i/dt = Log_{Cv_i}(Cbar) / tau_i, the Riemannian logarithm of the affine-invariant
// metric on SPD matrices (Bhatia 2007, Positive Definite Matrices, ch. 6): the geodesic
// counterpart of the "linear" law dCv/dt = (Cbar - Cv)/tau, which it equals to first
// order in the strain. Its exact solution at fixed F is the update relax() applies:
//
//   Cv_i^-1(t + dt) = Fbar^-1 Be_i^s Fbar^-T,   s = exp(-dt / tau_i),                  (4)
//
// i.e. Cv_i^-1(t + dt) = Cbar^-1 #_s Cv_i^-1(t), the weighted matrix geometric mean: the
// state slides along the geodesic to its equilibrium Cbar^-1 by the fraction 1 - s.
// Why this update rather than the exponential of the linear law followed by a
// projection to det = 1:
//  - exact: it is the flow of (3) itself, so relax(dt1) then relax(dt2) equals
//    relax(dt1 + dt2) and a step at fixed F has no time-discretisation error at all;
//  - unconditionally stable and dissipative for every dt: with e_k = ln of Be_i's
//    eigenvalues (sum e_k = 0), psi_i = beta_i mu/2 (sum_k exp(e_k) - 3) and e_k -> s e_k,
//    so psi_i(s) is convex in s with its minimum 0 at s = 0, hence nondecreasing on
//    [0, 1]: an update never raises psi_i. The rate form is the dissipation
//      D_i = -dpsi_i/dt = beta_i mu / (2 tau_i) sum_k e_k (exp(e_k) - 1) >= 0,          (5)
//    zero only at equilibrium (e (exp(e) - 1) > 0 for e != 0);
//  - det Cv_i = 1 and Cv_i SPD by construction (the eigenvalue logarithms are centred,
//    which also removes round-off drift of det over many steps); objective (it depends
//    on F only through C: F -> QF leaves Fbar^-1 Be^s Fbar^-T unchanged);
//  - linear limit: (3) becomes d(e - v_i)/dt = -(e - v_i)/tau_i at fixed e, the linear
//    Maxwell element, and in general dv_i/dt = (e - v_i)/tau_i. A step strain gamma
//    held fixed gives the relaxation modulus G(t) = mu (1 + sum_i beta_i exp(-t/tau_i)).
// (3) is coaxial with the branch's driving stress dev(Be_i) but not proportional to it
// (that is, it is not the gradient flow of the neo-Hookean psi_i, whose solution has no
// closed form); (5) is what thermodynamic consistency requires.
//
// Storage: the state holds Cv_i^-1 (not Cv_i): the stress (2) and the energy (1) need
// only the inverse, so the force loop inverts nothing. Per branch a packed symmetric
// 6-vector of doubles; the state is fixed-size for kMaxPronyBranches = 4 branches,
// 4 x 6 x 8 = 192 bytes per integration point whatever branch_count is (branches past
// branch_count stay I and are never read). Doubles: det Cv = 1 to 1e-12 would not survive
// float storage.
//
// Cost: energy and stress add two 3x3 products (C and F Gsum) and a 9-term dot product
// per branch to the neo-Hookean kernel; relax() does one symmetric 3x3 eigendecomposition per
// branch (Eigen's iterative solver: backward stable also near the reference state, where
// Be's eigenvalues nearly coincide and the closed-form solver loses accuracy).
//
// An inverted point (det F <= 0) gives NaN stress (Kinematics), as in the other models;
// the materials do not throw in the force loop.
#pragma once

#include "materials/kinematics.hpp"
#include "materials/neo_hookean/neo_hookean.hpp"
#include "rkpm/common/types.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

namespace rkpm::materials {

inline constexpr int kMaxPronyBranches = 4;

// A symmetric 3x3 tensor as (xx, yy, zz, yz, xz, xy), Voigt's order.
using PackedSymmetric = std::array<double, 6>;

inline constexpr PackedSymmetric kPackedIdentity{1.0, 1.0, 1.0, 0.0, 0.0, 0.0};

inline Mat3 unpack_symmetric(const PackedSymmetric& a) {
  Mat3 m;
  m << a[0], a[5], a[4],  //
      a[5], a[1], a[3],   //
      a[4], a[3], a[2];
  return m;
}

// Packs the symmetric part of m (the products that build the state are symmetric only
// to round-off).
inline PackedSymmetric pack_symmetric(const Mat3& m) {
  return {m(0, 0), m(1, 1), m(2, 2), 0.5 * (m(1, 2) + m(2, 1)), 0.5 * (m(0, 2) + m(2, 0)), 0.5 * (m(0, 1) + m(1, 0))};
}

// One Maxwell branch: a neo-Hookean spring of shear modulus beta mu in series with a
// dashpot; its shear stress relaxes as exp(-t / tau) in the small-strain limit.
struct PronyBranch {
  double beta = 0.0;  // [-] branch shear modulus relative to the equilibrium mu, >= 0
  double tau = 0.0;   // [s] relaxation time, > 0
};

// The internal variables of one integration point: Cv_i^-1 per branch (see the header
// comment for why the inverse). Default-constructed = the reference state.
struct ViscousState {
  std::array<PackedSymmetric, kMaxPronyBranches> inverse_viscous_cauchy_green{
      kPackedIdentity, kPackedIdentity, kPackedIdentity, kPackedIdentity};

  // Cv_i = I for every branch: the unstretched dashpots of an undeformed body.
  static ViscousState reference() { return ViscousState{}; }

  Mat3 inverse_viscous(int branch) const { return unpack_symmetric(inverse_viscous_cauchy_green[branch]); }
  void set_inverse_viscous(int branch, const Mat3& Cv_inv) {
    inverse_viscous_cauchy_green[branch] = pack_symmetric(Cv_inv);
  }
  // Cv_i itself, for output (not on the hot path).
  Mat3 viscous_cauchy_green(int branch) const { return inverse_viscous(branch).inverse(); }
};

static_assert(std::is_trivially_copyable_v<ViscousState>, "the state is copied and checkpointed as bytes");
static_assert(sizeof(ViscousState) == kMaxPronyBranches * 6 * sizeof(double), "192 bytes per point");

struct PronyNeoHookean {
  static constexpr int kMaxBranches = kMaxPronyBranches;

  NeoHookean equilibrium;                            // the long-term (fully relaxed) solid
  std::array<PronyBranch, kMaxBranches> branches{};  // the first branch_count are used
  int branch_count = 0;

  // Long-term small-strain shear modulus mu: G(t -> infinity).
  double shear_modulus() const { return equilibrium.mu; }
  // Instantaneous small-strain shear modulus mu (1 + sum_i beta_i): G(0+).
  double instantaneous_shear_modulus() const { return equilibrium.mu * (1.0 + beta_sum()); }
  // The branches are isochoric: the bulk modulus is the neo-Hookean one at every rate.
  double bulk_modulus() const { return equilibrium.bulk_modulus(); }

  // Throws std::invalid_argument naming the parameter and value ("viscoelastic material:
  // beta[1] = -0.5 must be >= 0"; branches counted from 0) unless mu > 0, lambda > 0,
  // 0 <= branch_count <= 4 and, for each used branch, beta >= 0 and tau > 0, all finite.
  void validate() const;

  // psi_i of (1): branch i's stored energy per reference volume [Pa].
  double branch_energy(const Mat3& F, const ViscousState& state, int branch) const {
    return isochoric_branch_energy(isochoric_cauchy_green(F), state.inverse_viscous(branch), branches[branch].beta);
  }

  // sum_i psi_i [Pa]: the part of W that relaxation dissipates.
  double viscous_energy(const Mat3& F, const ViscousState& state) const {
    if (branch_count <= 0) return 0.0;
    const Mat3 C_bar = isochoric_cauchy_green(F);
    double sum = 0.0;
    for (int i = 0; i < branch_count; ++i)
      sum += isochoric_branch_energy(C_bar, state.inverse_viscous(i), branches[i].beta);
    return sum;
  }

  // W of (1): stored energy per reference volume at the given internal variables [Pa].
  double energy(const Mat3& F, const ViscousState& state) const {
    return equilibrium.energy(F) + viscous_energy(F, state);
  }

  // First Piola-Kirchhoff stress (2), P = dW/dF at fixed internal variables [Pa]. The
  // neo-Hookean part is the same expression as NeoHookean::first_piola, so with beta = 0
  // the two agree to the bit.
  Mat3 first_piola(const Mat3& F, const ViscousState& state) const {
    const Kinematics k(F);
    const double mu = equilibrium.mu;
    Mat3 P = mu * F + (equilibrium.lambda * k.log_J - mu) * k.F_inv_T;
    if (branch_count <= 0) return P;
    // Gsum and tr(C Gsum)/3 = sum_i beta_i tr(C Cv_i^-1)/3, the latter summed branch by
    // branch: at F = I, Cv_i = I each tr/3 is exactly 1 and the bracket of (2) exactly 0
    // (3 x beta_sum / 3 is not always beta_sum in floating point).
    const Mat3 C = F.transpose() * F;
    Mat3 weighted = Mat3::Zero();
    double third_of_trace = 0.0;
    for (int i = 0; i < branch_count; ++i) {
      const Mat3 Cv_inv = state.inverse_viscous(i);
      weighted += branches[i].beta * Cv_inv;
      third_of_trace += branches[i].beta * (C.cwiseProduct(Cv_inv).sum() / 3.0);
    }
    P += (mu * inverse_cbrt_squared(k.J)) * (F * weighted - third_of_trace * k.F_inv_T);
    return P;
  }

  // Cauchy stress sigma = P F^T / J [Pa] (symmetric: W depends on F through C only).
  Mat3 cauchy(const Mat3& F, const ViscousState& state) const {
    return first_piola(F, state) * F.transpose() / F.determinant();
  }

  // The internal variables after dt [s] at fixed F: the exact solution (4) of the
  // evolution law (3). Any dt >= 0, including infinity (then Cv_i = Cbar, psi_i = 0).
  // energy(F, relax(F, s, dt)) - energy(F, s) <= 0 is minus the energy the step
  // dissipates (the ledger's StateUpdate::energy_change, state_hooks.hpp).
  ViscousState relax(const Mat3& F, const ViscousState& state, double dt) const {
    ViscousState next = state;
    if (branch_count <= 0) return next;
    const double J_third = std::cbrt(F.determinant());
    const Mat3 F_bar = F / J_third;
    const Mat3 F_bar_inv = J_third * F.inverse();
    for (int i = 0; i < branch_count; ++i) {
      const double remaining = std::exp(-dt / branches[i].tau);  // s in (4)
      const Mat3 Be = F_bar * state.inverse_viscous(i) * F_bar.transpose();
      next.set_inverse_viscous(i, F_bar_inv * unimodular_power(Be, remaining) * F_bar_inv.transpose());
    }
    return next;
  }

  // Longitudinal wave speed [m/s] for the stable time step, reference configuration,
  // rho0 = reference density [kg/m^3]: an upper bound on sqrt(max eigenvalue of the
  // acoustic tensor / rho0) at this F AND state. The neo-Hookean bound with mu replaced
  // by the instantaneous mu (1 + sum beta_i) is not one: the isochoric branch is stiffer
  // than mu/2 (I1 - 3) under a finite stretch even in the reference state, and a branch
  // relaxed at a large stretch and then unloaded is stiffer still, by the eigenvalues of
  // Cv^-1, which no state-free bound can know (InstantaneousNeoHookeanBoundIsNotABound:
  // 11 % below the numerical speed in both cases).
  //
  // Derivation: the neo-Hookean part's exact maximum (NeoHookean::wave_speed) plus a
  // bound per branch (the maximum of a sum is at most the sum of the maxima). Branch i,
  // a = beta_i mu, G = Cv_i^-1: differentiating psi_i twice along m (x) N, with
  // det(F + e m N^T) = J (1 + e b.m) exactly,
  //   Q_i(N) = a J^(-2/3) [ q I + (5/9) phi b b^T - (2/3)(b c^T + c b^T) ],
  //   q = N.G N,  phi = tr(C G),  b = F^-T N,  c = F G N  (b.c = q).
  // The rank-2 part's largest eigenvalue is that of the 2x2 product S K, S = [[5/9 phi,
  // -2/3], [-2/3, 0]], K the Gram matrix of b and c; with p = |b|^2, r = |c|^2,
  //   lambda_max(Q_i(N)) = a J^(-2/3) [ q/3 + x + sqrt((x - 2q/3)^2 + (4/9)(p r - q^2)) ],
  //   x = (5/18) phi p.
  // It increases with x and with p r, which are at most X = (5/18) phi / C_min and
  // PR = lambda_max(G C G) / C_min (p = N.C^-1 N, r = N.G C G N); there the q^2 terms
  // cancel, leaving the concave
  //   h(q) = q/3 + X + sqrt(X^2 + (4/9) PR - (4/3) X q),
  // maximised over the q a unit N can have, [g_min, min(g_max, sqrt(PR))] (g = eigenvalues
  // of G; q^2 <= p r <= PR): at q* = (PR/3 - 9 X^2/4) / X clamped to that interval. So
  //   rho0 c^2 <= [neo-Hookean exact maximum] + sum_i beta_i mu J^(-2/3) h_i(q_i*).
  // At F = I and the reference state it is exact, h = 4/3: lambda + 2 mu + (4/3) mu
  // sum beta_i, the instantaneous P-wave modulus K + (4/3) mu (1 + sum beta_i). The
  // tests measure the speed 2-19 % above the numerical acoustic tensor's maximum at
  // random large strains and states.
  double wave_speed(const Mat3& F, const ViscousState& state, double rho0) const {
    const double c_equilibrium = equilibrium.wave_speed(F, 1.0);  // sqrt of its modulus
    double modulus = c_equilibrium * c_equilibrium;
    if (branch_count > 0) {
      const Mat3 C = F.transpose() * F;
      const double C_min = symmetric_eigenvalues(C)[0];
      const double isochoric_scale = equilibrium.mu * inverse_cbrt_squared(F.determinant());  // mu J^(-2/3)
      for (int i = 0; i < branch_count; ++i)
        modulus += branches[i].beta * isochoric_scale * branch_acoustic_bound(C, C_min, state.inverse_viscous(i));
    }
    return std::sqrt(modulus / rho0);
  }

 private:
  double beta_sum() const {
    double sum = 0.0;
    for (int i = 0; i < branch_count; ++i) sum += branches[i].beta;
    return sum;
  }

  // J^(-2/3), exactly 1 at J = 1.
  static double inverse_cbrt_squared(double J) { return 1.0 / std::cbrt(J * J); }

  static Mat3 isochoric_cauchy_green(const Mat3& F) {
    return inverse_cbrt_squared(F.determinant()) * (F.transpose() * F);
  }

  // psi = beta mu / 2 (tr(Cbar Cv^-1) - 3); tr(A B) of symmetric A, B = A : B.
  double isochoric_branch_energy(const Mat3& C_bar, const Mat3& Cv_inv, double beta) const {
    return 0.5 * beta * equilibrium.mu * (C_bar.cwiseProduct(Cv_inv).sum() - 3.0);
  }

  // A^s for a symmetric positive definite A projected to det A = 1: A = V diag(a) V^T,
  // A^s = V diag(exp(s (ln a - mean ln a))) V^T. s = 0 is the identity exactly (dt = inf).
  static Mat3 unimodular_power(const Mat3& A, double s) {
    if (s == 0.0) return Mat3::Identity();
    const Eigen::SelfAdjointEigenSolver<Mat3> spectral(0.5 * (A + A.transpose()));
    Vec3 log_a = spectral.eigenvalues().array().log().matrix();
    log_a.array() -= log_a.mean();
    const Vec3 powered = (s * log_a).array().exp().matrix();
    return spectral.eigenvectors() * powered.asDiagonal() * spectral.eigenvectors().transpose();
  }

  // max over unit N of h(q) in wave_speed's derivation: the branch's largest acoustic
  // eigenvalue divided by beta mu J^(-2/3).
  static double branch_acoustic_bound(const Mat3& C, double C_min, const Mat3& Cv_inv) {
    const double X = (5.0 / 18.0) * C.cwiseProduct(Cv_inv).sum() / C_min;
    const double PR = symmetric_eigenvalues(Cv_inv * C * Cv_inv)[2] / C_min;
    const Vec3 g = symmetric_eigenvalues(Cv_inv);
    const double q_high = std::min(g[2], std::sqrt(PR));
    const double q_low = std::min(g[0], q_high);
    const double q = std::clamp((PR / 3.0 - 2.25 * X * X) / X, q_low, q_high);
    return q / 3.0 + X + std::sqrt(std::max(0.0, X * X + (4.0 / 9.0) * PR - (4.0 / 3.0) * X * q));
  }
};

}  // namespace rkpm::materials
