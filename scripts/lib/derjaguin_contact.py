"""An adhered sphere on a flat with the contact law's own traction: the self-consistent
solution of the two elastic half-spaces and the law between them (Greenwood, Proc. R.
Soc. A 453, 1277 (1997); Feng, J. Colloid Interface Sci. 225, 382 (2000)), the reference
that Maugis-Dugdale approximates.

Maugis-Dugdale replaces the traction-gap law of the two surfaces by Dugdale's: the
strength sigma0 up to the gap h = w / sigma0, nothing beyond, with the same work of
adhesion. Across the transition (Tabor parameter near 1) the shape of the law matters:
where the surfaces press and where they pull is decided by the law's own curve. This
module keeps the two theories' other assumptions (half-spaces, small strain, the
surfaces interacting pointwise across their local gap: Derjaguin's approximation) and
uses the real law sigma(D) of the contact term between two half-spaces
(`contact_theory.half_space_traction`, Eq. 3 there):

    gap(r) = h0 + g(r) + u(r),   u(r) = int p(s) G(r, s) ds,   p(s) = sigma(gap(s)),   (1)

g the undeformed profile (r^2 / (2R), or the sphere's R - sqrt(R^2 - r^2)), h0 the gap of
the undeformed profiles on the axis, u the two surfaces' elastic separation under the
pressure p (> 0 compressive), with the half-space's surface displacement of a uniform
pressure p on a disk of radius b (Johnson, Contact Mechanics (1985), Eq. 3.39-3.40,
both bodies through 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2):

    u(r) = 4 p b E(r/b) / (pi E*)                               r < b,
    u(r) = 4 p r [E(b/r) - (1 - b^2/r^2) K(b/r)] / (pi E*)       r > b,               (2)

E and K the complete elliptic integrals. The pressure is constant on each of n rings
(a ring is the difference of two disks) and Eq. (1) holds at the rings' mid-radii: n
equations in the n gaps, solved by Newton's method at a prescribed h0 (displacement
control, continued from a far h0 inward); the load is P = sum of the rings' p times
their area, and the adhered state at rest the h0 where P = 0 (bracketed, then brentq).
Displacement control follows the equilibrium branch without jumps for Tabor parameters
below about 1 (Greenwood 1997); the solver raises if Newton's method does not
converge.

What it returns for a sphere at rest: the radius inside which the surfaces press (the
gap below the law's zero z0: the edge of the compressive zone, what a simulation
measures, `adhesion_at_rest.py`), the approach delta = z0 - h0 (from where the rigid
sphere would rest at the gap z0), and the pressure profile. Units SI throughout.

    /usr/bin/python3 scripts/lib/derjaguin_contact.py --R 5e-6 --E-star 3.76e4 \\
        --epsilon 3.265e-15 --s0 0.75e-6 --beta 1e18 1e18
"""
import argparse
import math
from dataclasses import dataclass

import numpy as np
from scipy import interpolate, optimize, special

import contact_theory as T


def disk_displacement(r, b, E_star):
    """The two surfaces' separation [m per Pa] at radii r [m] under a unit pressure on a
    disk of radius b [m] (Eq. 2); r = b gives 4 b / (pi E*)."""
    r = np.asarray(r, float)
    if b == 0.0:
        return np.zeros_like(r)
    inside = r <= b
    k_in = np.where(inside, r / b, 0.0)
    k_out = np.where(inside, 0.0, b / np.maximum(r, b))
    u_in = 4.0 * b * special.ellipe(k_in * k_in) / (math.pi * E_star)
    # (1 - k^2) K(k) -> 0 as k -> 1, where ellipk diverges: only evaluated for k < 1.
    u_out = 4.0 * r * (special.ellipe(k_out * k_out) - (1.0 - k_out * k_out) * special.ellipk(k_out * k_out)) \
        / (math.pi * E_star)
    return np.where(inside, u_in, u_out)


def influence_matrix(edges, E_star):
    """C[i, j]: the separation at ring i's mid-radius under a unit pressure on ring j
    (Eq. 2: the disk to ring j's outer edge less the disk to its inner edge)."""
    mid = 0.5 * (edges[:-1] + edges[1:])
    disks = np.stack([disk_displacement(mid, b, E_star) for b in edges], axis=1)
    return disks[:, 1:] - disks[:, :-1]


class TractionLaw:
    """sigma(D) and dsigma/dD of two half-spaces under the contact term's law
    (`contact_theory.half_space_traction`), tabulated from 0.3 z0 to the cutoff and
    interpolated by a cubic spline (zero beyond the cutoff)."""

    def __init__(self, phi, cutoff, rho1, rho2, z0, points=600):
        self.cutoff = cutoff
        self.low = 0.3 * z0
        gaps = self.low + (cutoff - self.low) * (1.0 - np.cos(np.linspace(0.0, math.pi, points))) / 2.0
        values = [T.half_space_traction(D, phi, cutoff, rho1, rho2) for D in gaps]
        self._spline = interpolate.CubicSpline(gaps, values)
        self._slope = self._spline.derivative()

    def __call__(self, D):
        self._check(D)
        return np.where(D < self.cutoff, self._spline(np.minimum(D, self.cutoff)), 0.0)

    def slope(self, D):
        self._check(D)
        return np.where(D < self.cutoff, self._slope(np.minimum(D, self.cutoff)), 0.0)

    def _check(self, D):
        if np.min(D) < self.low:
            raise FloatingPointError(f"a gap of {np.min(D):.4g} m, below the law's table (from {self.low:.4g} m)")


@dataclass(frozen=True)
class DerjaguinContact:
    """The adhered sphere at one load: the gap h0 of the undeformed profiles on the axis,
    the approach delta = z0 - h0, the load P [N], the radius inside which the surfaces
    press (compressive_radius [m], 0 if nowhere), and per ring its mid-radius r, gap and
    pressure (> 0 compressive)."""
    h0: float
    delta: float
    P: float
    compressive_radius: float
    r: np.ndarray
    gap: np.ndarray
    pressure: np.ndarray


class AdheredSphereSolver:
    """Eq. (1) on `rings` rings out to where the undeformed gap exceeds the law's cutoff
    by half a cutoff, for a sphere of radius R [m] (profile "paraboloid", as the
    theories assume, or "sphere"), combined modulus E* [Pa] and a `TractionLaw`."""

    def __init__(self, R, E_star, law, z0, rings=400, profile="paraboloid"):
        self.R, self.z0, self.law = R, z0, law
        reach = 1.5 * law.cutoff
        if profile == "paraboloid":
            r_max = math.sqrt(2.0 * R * reach)
            shape = lambda r: r * r / (2.0 * R)  # noqa: E731
        elif profile == "sphere":
            if reach >= R:
                raise ValueError(f"sphere radius {R} m not larger than 1.5 cutoffs ({reach} m)")
            r_max = math.sqrt(R * R - (R - reach) ** 2)
            shape = lambda r: R - np.sqrt(R * R - r * r)  # noqa: E731
        else:
            raise ValueError(f"profile {profile!r}: expected 'paraboloid' or 'sphere'")
        self.edges = np.linspace(0.0, r_max, rings + 1)
        self.r = 0.5 * (self.edges[:-1] + self.edges[1:])
        self.area = math.pi * (self.edges[1:] ** 2 - self.edges[:-1] ** 2)
        self.profile = shape(self.r)
        self.C = influence_matrix(self.edges, E_star)
        self.gap = self.profile + 1.2 * law.cutoff  # far apart: no traction

    def solve_at(self, h0, iterations=60, tol=1e-12):
        """The gaps at the rigid gap h0 by Newton's method from the last solution, with
        the step halved until the residual falls; returns the load P [N]."""
        gap = self.gap.copy()
        eye = np.eye(len(gap))
        for _ in range(iterations):
            residual = gap - h0 - self.profile - self.C @ self.law(gap)
            norm = np.max(np.abs(residual))
            if norm <= tol * self.z0:
                self.gap = gap
                return float(self.area @ self.law(gap))
            step = np.linalg.solve(eye - self.C * self.law.slope(gap)[None, :], -residual)
            scale = 1.0
            while True:
                trial = gap + scale * step
                try:
                    if np.max(np.abs(trial - h0 - self.profile - self.C @ self.law(trial))) < norm:
                        break
                except FloatingPointError:
                    pass
                scale *= 0.5
                if scale < 1e-6:
                    raise ArithmeticError(f"Newton's method stalled at h0 = {h0:.6g} m (residual {norm:.3g} m)")
            gap = trial
        raise ArithmeticError(f"Newton's method did not converge at h0 = {h0:.6g} m in {iterations} iterations")

    def state(self, h0):
        P = self.solve_at(h0)
        pressure = self.law(self.gap)
        return DerjaguinContact(h0=h0, delta=self.z0 - h0, P=P, compressive_radius=self._compressive_radius(pressure),
                                r=self.r.copy(), gap=self.gap.copy(), pressure=pressure)

    def _compressive_radius(self, pressure):
        """Where the pressure first turns from > 0 to <= 0 going out, linearly between
        the two rings' mid-radii."""
        if pressure[0] <= 0.0:
            return 0.0
        if not np.any(pressure <= 0.0):
            raise ArithmeticError(f"the surfaces press out to the last ring ({self.r[-1]:.4g} m): no edge within it")
        i = int(np.argmax(pressure <= 0.0))
        return float(self.r[i - 1] + (self.r[i] - self.r[i - 1]) * pressure[i - 1] / (pressure[i - 1] - pressure[i]))

    def at_load(self, load=0.0, step=None):
        """The state at `load` [N] on the branch followed inward from far apart: h0 goes
        down in steps of `step` (default z0 / 20) until the load exceeds `load` after the
        attraction's minimum, then brentq between the last two h0."""
        step = self.z0 / 20.0 if step is None else step
        h0 = 1.2 * self.law.cutoff
        previous = (h0, self.solve_at(h0), self.gap.copy())
        least = previous[1]
        while True:
            h0 -= step
            P = self.solve_at(h0)
            least = min(least, P)
            if P > load and least < load:
                break
            previous = (h0, P, self.gap.copy())
            if h0 < -10.0 * self.law.cutoff:
                raise ArithmeticError(f"no equilibrium at load {load} N found down to h0 = {h0:.4g} m")
        far_gap = previous[2]

        def excess(x):
            self.gap = far_gap.copy()
            return self.solve_at(x) - load
        h0 = optimize.brentq(excess, h0, previous[0], xtol=1e-9 * self.z0, rtol=1e-12)
        self.gap = far_gap.copy()
        return self.state(h0)


def adhered_sphere(R, E_star, epsilon, s0, beta, cutoff=None, load=0.0, rings=400, profile="paraboloid"):
    """The self-consistent `DerjaguinContact` at `load` [N] of a sphere of radius R [m],
    combined modulus E* [Pa], under the contact term's law (epsilon [J], s0 [m], beta
    [1/m^3] per body, cutoff [m], default 3 s0; `contact_theory.contact_term_law`)."""
    rc = T.cutoff_or_default(cutoff, s0)
    halves = T.contact_term_law(epsilon, s0, beta, rc)
    law = TractionLaw(T.lennard_jones(epsilon, s0), rc, beta[0], beta[1], halves.z0)
    return AdheredSphereSolver(R, E_star, law, halves.z0, rings=rings, profile=profile).at_load(load)


def main(argv=None):
    parser = argparse.ArgumentParser(description="A sphere adhered to a flat with the contact term's own traction "
                                     "law (Derjaguin's approximation, half-spaces): compressive zone and approach.")
    parser.add_argument("--R", type=float, required=True, help="sphere radius [m]")
    parser.add_argument("--E-star", type=float, required=True, help="combined modulus E* [Pa]")
    parser.add_argument("--epsilon", type=float, required=True, help="contact term: epsilon [J]")
    parser.add_argument("--s0", type=float, required=True, help="contact term: s0 [m]")
    parser.add_argument("--beta", type=float, nargs=2, required=True, help="contact term: beta1 beta2 [1/m^3]")
    parser.add_argument("--cutoff", type=float, help="contact term: cutoff [m] (default 3 s0)")
    parser.add_argument("--load", type=float, default=0.0, help="load [N], > 0 compressive (default 0)")
    parser.add_argument("--rings", type=int, default=400)
    parser.add_argument("--profile", choices=("paraboloid", "sphere"), default="paraboloid")
    args = parser.parse_args(argv)
    s = adhered_sphere(args.R, args.E_star, args.epsilon, args.s0, args.beta, args.cutoff, args.load, args.rings,
                       args.profile)
    law = T.contact_term_law(args.epsilon, args.s0, args.beta, args.cutoff)
    md = T.maugis_dugdale(args.R, law.w, law.sigma0, args.E_star, args.load)
    print(f"self-consistent ({args.profile}): compressive zone to {s.compressive_radius:.5g} m, approach "
          f"{s.delta:.5g} m, load {s.P:.3g} N")
    print(f"Maugis-Dugdale:  compressive zone to {T.md_zero_pressure_radius(md, args.R, law.sigma0, args.E_star):.5g} m, "
          f"approach {md.delta:.5g} m (from touching; the approach above is from rest at z0)")


if __name__ == "__main__":
    main()
