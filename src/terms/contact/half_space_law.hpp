// The contact law of two flat half-spaces under the contact term's pair potential
// (seed Eq. 13, truncated at the cutoff and shifted to zero there): seed Eq. 14's double
// volume integral done in closed form over the depth of both bodies, per unit area and
// per unit product of their molecule densities rho1 rho2 (docs/theory/contact.md,
// "The surface formulation"):
//
//   W(D)     =   pi   int_D^rc phi_s(r) r (r - D)^2 dr   energy per area, gap D
//   sigma(D) = 2 pi   int_D^rc phi_s(r) r (r - D)   dr = -dW/dD   (> 0: repulsion)
//   sigma'(D) = -2 pi int_D^rc phi_s(r) r dr
//
// with phi_s(r) = eps [(s0/r)^12 - 2 (s0/r)^6] - phi(rc). Each integrand is a sum of
// powers of r, so each integral is its antiderivative's difference between rc and D;
// scripts/lib/contact_theory.py evaluates the same law by quadrature.
#pragma once

namespace rkpm::sim {

class HalfSpaceLaw {
 public:
  HalfSpaceLaw(double epsilon, double s0, double cutoff);
  // All three vanish at D >= cutoff; D must be positive.
  double energy(double D) const;          // W(D) / (rho1 rho2) [J m^4]
  double traction(double D) const;        // sigma(D) / (rho1 rho2) [J m^3]
  double traction_slope(double D) const;  // sigma'(D) / (rho1 rho2) [J m^2]
  double cutoff() const { return rc_; }

 private:
  double c12_, c6_, shift_, rc_;
};

}  // namespace rkpm::sim
