"""Closed forms of the adhesive elastic contact of a sphere on a flat, and the adhesion
of the project's contact law, against which a simulated adhered sphere at rest is
compared (docs/theory/contact.md).

Contact law. The contact term (src/terms/contact/, seed Eq. 12-14) sums the 12-6
Lennard-Jones potential of seed Eq. (13),

    phi(r) = eps (s0/r)^12 - 2 eps (s0/r)^6,                                     (1)

truncated at the cutoff rc and shifted by phi(rc) (its forces are -phi'(r) inside rc,
none beyond), over the pairs of particles of two bodies, each particle carrying
n_I = beta V_I molecules: a nodal quadrature of seed Eq. (14), the double volume
integral of beta1 beta2 phi. In the continuum limit two half-spaces at gap D, molecule
densities rho1 = beta1 and rho2 = beta2, have the energy per unit area

    U(z) = 2 pi rho2 int_z^rc phi_s(r) r (r - z) dr,    W(D) = rho1 int_D^rc U(z) dz
         = pi rho1 rho2 int_D^rc phi_s(r) r (r - D)^2 dr,                        (2)

phi_s = phi - phi(rc) (U is the energy of one molecule at height z over a half-space:
the part of the sphere of radius r inside it has the area 2 pi r (r - z)). The
traction (> 0: repulsion) is

    sigma(D) = -dW/dD = 2 pi rho1 rho2 int_D^rc phi_s(r) r (r - D) dr,            (3)

the equilibrium gap z0 its zero (the minimum of W), the work of adhesion w = -W(z0),
the theoretical strength sigma0 = -min sigma (at dsigma/dD = 0, i.e.
int_D^rc phi_s r dr = 0) and the range of the equivalent Dugdale law h = w / sigma0
(Maugis 1992). For phi = C12 r^-12 - C6 r^-6 without cutoff, since
int_D^inf r^(1-n) (r - D)^2 dr = 2 D^(4-n) / ((n-2)(n-3)(n-4)),

    W(D) = pi rho1 rho2 [C12 / (360 D^8) - C6 / (12 D^2)];                        (4)

for Eq. (1) (C12 = eps s0^12, C6 = 2 eps s0^6) z0 = 15^(-1/6) s0, the peak tension at
5^(-1/6) s0, w = (pi 15^(1/3) / 8) rho1 rho2 eps s0^4 = 0.96848 rho1 rho2 eps s0^4 and
sigma0 = (2 sqrt(5) pi / 9) rho1 rho2 eps s0^3 = 1.56107 rho1 rho2 eps s0^3, the values
docs/theory/contact.md quotes. The default cutoff 3 s0 lowers w and sigma0
(`contact_term_law`).

Sphere on a flat. R the sphere's radius (for two spheres R1 R2 / (R1 + R2)), E* the
combined modulus, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, K = 4 E*/3, P the load
(> 0 compressive), a the contact radius, delta the approach (> 0 = interpenetration of
the undeformed profiles):

    Hertz:  a^3 = P R / K,  delta = a^2 / R;                                      (5)
    JKR (Johnson, Kendall & Roberts, Proc. R. Soc. A 324, 301 (1971)):
            a^3 = (R/K) [P + 3 pi w R + sqrt(6 pi w R P + (3 pi w R)^2)],
            delta = a^2 / R - sqrt(2 pi w a / E*),  pull-off P = -(3/2) pi w R;      (6)
    DMT (Derjaguin, Muller & Toporov, J. Colloid Interface Sci. 53, 314 (1975)):
            a^3 = (R/K) (P + 2 pi w R),  delta = a^2 / R,  pull-off P = -2 pi w R.    (7)

Maugis-Dugdale (Maugis, J. Colloid Interface Sci. 150, 243 (1992)): the tractions
outside the contact are the Dugdale law, sigma0 up to the gap h = w / sigma0, over
a < r < c. With

    A = a (K / (pi w R^2))^(1/3),  Pbar = P / (pi w R),
    Delta = delta (K^2 / (pi^2 w^2 R))^(1/3),  m = c / a,  t = sqrt(m^2 - 1),
    lambda = 2 sigma0 (R / (pi w K^2))^(1/3)                                      (8)

(Maugis' parameter), the contact is

    (lambda A^2 / 2) [t + (m^2 - 2) arctan t] + (4 lambda^2 A / 3) [t arctan t - m + 1] = 1,  (9)
    Pbar = A^3 - lambda A^2 [t + m^2 arctan t],                                   (10)
    Delta = A^2 - (4/3) A lambda t.                                               (11)

(Maugis' Eq. 6.17 and his load and approach, in the notation of Johnson & Greenwood,
J. Colloid Interface Sci. 192, 326 (1997); the same equations as the reference solution
PyCo/ReferenceSolutions/MaugisDugdale.py of ContactEngineering.) lambda -> infinity
gives JKR (A^3 = 6 at Pbar = 0, pull-off Pbar = -3/2), lambda -> 0 DMT (A^3 = 2,
pull-off -2). Eq. (9) is quadratic in A at given t, so the curve is explicit in t: A
decreases from infinity (t -> 0) to 0 (t -> infinity) and Pbar falls from +infinity
to a single minimum, the pull-off force under load control, then rises again. At a
load above it the contact on the stable branch (the largest A) is the root of Eq. (10)
between t -> 0 and the minimum (bracketed, `scipy.optimize.brentq`). Tabor's parameter (Tabor, J. Colloid
Interface Sci. 58, 2 (1977)) is mu = (R w^2 / (E*^2 z0^3))^(1/3); for the 9-3 law of
the untruncated Eq. (1) sigma0 = 16 w / (9 sqrt(3) z0), so lambda = 1.157 mu.

`adhered_sphere` gathers the three theories at one load; `contact_term_law` gives
w, sigma0, z0 and h of a [[term]] type = "contact" from its parameters. Run as a script
it prints the table (--help). Units SI throughout.
"""
import argparse
import math
import warnings
from dataclasses import dataclass

import numpy as np
from scipy import integrate, optimize

# ---------------------------------------------------------------------------------------
# The contact law between two half-spaces, Eqs. (1)-(4)
# ---------------------------------------------------------------------------------------


def lennard_jones(epsilon, s0):
    """The pair potential of the contact term, seed Eq. (13) (Eq. 1 here):
    phi(r) = epsilon [(s0/r)^12 - 2 (s0/r)^6], minimum -epsilon at r = s0, as a
    function of r [m] returning J (`epsilon` [J] and `s0` [m] as in the scene)."""
    def phi(r):
        u6 = (s0 / r) ** 6
        return epsilon * (u6 * u6 - 2.0 * u6)
    return phi


def _shifted(phi, cutoff):
    """phi - phi(cutoff), the truncated and shifted potential of the contact term inside
    the cutoff (no shift for an infinite cutoff)."""
    if math.isinf(cutoff):
        return phi
    shift = phi(cutoff)
    return lambda r: phi(r) - shift


def _quad(f, lo, hi):
    """int_lo^hi f by adaptive quadrature to 1e-12 relative. Near the zero of sigma the
    positive and negative parts cancel and quad warns that the relative tolerance is out
    of reach; the absolute error stays at rounding of the parts (the tests check z0 to
    1e-12 against the closed form), so the warning is silenced."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", integrate.IntegrationWarning)
        value, _ = integrate.quad(f, lo, hi, epsabs=0.0, epsrel=1e-12, limit=400)
    return value


def half_space_energy(D, phi, cutoff, rho1, rho2):
    """W(D) [J/m^2], Eq. (2): the energy per unit area of two half-spaces with molecule
    densities rho1, rho2 [1/m^3] at gap D [m] under the pair potential phi(r) [J]
    truncated at `cutoff` [m] (may be inf) and shifted by phi(cutoff) as the contact
    term does (seed Eq. 14 in the continuum limit)."""
    if D >= cutoff:
        return 0.0
    phi_s = _shifted(phi, cutoff)
    # r = D x: scale-free limits for quad (its map of an infinite range assumes unit scale).
    return math.pi * rho1 * rho2 * D ** 4 * _quad(lambda x: phi_s(D * x) * x * (x - 1.0) ** 2, 1.0, cutoff / D)


def half_space_traction(D, phi, cutoff, rho1, rho2):
    """sigma(D) = -dW/dD [Pa], Eq. (3): the normal traction between the two half-spaces
    of `half_space_energy` (> 0: repulsion)."""
    if D >= cutoff:
        return 0.0
    phi_s = _shifted(phi, cutoff)
    return 2.0 * math.pi * rho1 * rho2 * D ** 3 * _quad(lambda x: phi_s(D * x) * x * (x - 1.0), 1.0, cutoff / D)


def _traction_slope_sign(D, phi, cutoff):
    """int_D^rc phi_s(r) r dr, proportional to -dsigma/dD (Eq. 3): zero at the peak
    tension."""
    phi_s = _shifted(phi, cutoff)
    return D * D * _quad(lambda x: phi_s(D * x) * x, 1.0, cutoff / D)


def _first_sign_change(f, grid, positive_first=True):
    """The first interval of `grid` over which f goes from > 0 to <= 0 (or the reverse)."""
    previous = None
    for x in grid:
        value = f(x) if positive_first else -f(x)
        if previous is not None and previous[1] > 0.0 >= value:
            return previous[0], x
        previous = (x, value)
    raise ValueError("no sign change found: is the potential repulsive at short range and attractive beyond?")


@dataclass(frozen=True)
class HalfSpaceLaw:
    """The adhesion of two half-spaces under a pair potential (Eqs. 2-3): work of
    adhesion w = -W(z0) [J/m^2], theoretical strength sigma0 = -min sigma [Pa],
    equilibrium gap z0 [m] (sigma = 0), the gap of the peak tension [m], and the range
    h = w / sigma0 [m] of the Dugdale law of the same w and sigma0 (Maugis 1992)."""
    w: float
    sigma0: float
    z0: float
    peak_gap: float

    @property
    def h(self):
        return self.w / self.sigma0


def half_space_law(phi, cutoff, rho1, rho2, length):
    """w, sigma0, z0 of two half-spaces (`HalfSpaceLaw`) for a pair potential phi(r) [J]
    with a repulsive core, truncated at `cutoff` [m] (may be inf) and shifted as the
    contact term does, molecule densities rho1, rho2 [1/m^3]. `length` [m] is the
    potential's scale (e.g. its minimum): z0 and the peak are bracketed on a geometric
    grid from length / 100 to min(cutoff, 100 length) and found by brentq, z0 as the
    zero of sigma (Eq. 3), the peak where int_D^rc phi_s r dr = 0."""
    hi = min(cutoff, 100.0 * length)
    grid = np.geomspace(0.01 * length, hi, 401)[:-1]
    sigma = lambda D: half_space_traction(D, phi, cutoff, rho1, rho2)  # noqa: E731
    lo, up = _first_sign_change(sigma, grid)
    z0 = optimize.brentq(sigma, lo, up, xtol=1e-15 * length, rtol=1e-15, maxiter=200)
    slope = lambda D: _traction_slope_sign(D, phi, cutoff)  # noqa: E731
    lo, up = _first_sign_change(slope, [z0] + [D for D in grid if D > z0])
    peak = optimize.brentq(slope, lo, up, xtol=1e-15 * length, rtol=1e-15, maxiter=200)
    w = -half_space_energy(z0, phi, cutoff, rho1, rho2)
    sigma0 = -sigma(peak)
    return HalfSpaceLaw(w=w, sigma0=sigma0, z0=z0, peak_gap=peak)


def cutoff_or_default(cutoff, s0):
    """The contact term's cutoff [m]: the scene's, or its default 3 s0 (docs/theory/contact.md)."""
    return 3.0 * s0 if cutoff is None else cutoff


def contact_term_law(epsilon, s0, beta, cutoff=None):
    """`HalfSpaceLaw` of a [[term]] type = "contact" (src/terms/contact/params.cpp) with
    its parameters: `epsilon` [J], `s0` [m], `beta` = [beta1, beta2] [1/m^3] (molecules
    per reference volume; the term's beta = 0, one molecule per particle, must be given
    here as the body's particle number density N / V), `cutoff` [m] (absent: 3 s0, the
    term's default). Uniform eps (stiffness_law = "none")."""
    beta1, beta2 = beta
    if beta1 <= 0.0 or beta2 <= 0.0:
        raise ValueError("beta must be positive: for the term's beta = 0 give the particle number density N / V")
    rc = cutoff_or_default(cutoff, s0)
    if rc <= s0:
        raise ValueError(f"cutoff {rc} must exceed s0 = {s0} (as the contact term requires)")
    return half_space_law(lennard_jones(epsilon, s0), rc, beta1, beta2, s0)


# ---------------------------------------------------------------------------------------
# Elastic moduli and the adhesion parameters
# ---------------------------------------------------------------------------------------


def combined_modulus(E1, nu1, E2, nu2):
    """E* [Pa] of two elastic bodies: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2; E2 = inf is
    a rigid flat (Hertz; Johnson, Contact Mechanics (1985), ch. 4)."""
    compliance = (1.0 - nu1 * nu1) / E1
    if not math.isinf(E2):
        compliance += (1.0 - nu2 * nu2) / E2
    return 1.0 / compliance


def isotropic_moduli(shear, bulk):
    """Young's modulus [Pa] and Poisson's ratio of an isotropic solid of small-strain
    shear modulus `shear` and bulk modulus `bulk` [Pa]:
    E = 9 K mu / (3 K + mu), nu = (3 K - 2 mu) / (2 (3 K + mu))."""
    return 9.0 * bulk * shear / (3.0 * bulk + shear), (3.0 * bulk - 2.0 * shear) / (2.0 * (3.0 * bulk + shear))


def _K(E_star):
    return 4.0 * E_star / 3.0


def tabor_parameter(R, w, E_star, z0):
    """Tabor's parameter mu = (R w^2 / (E*^2 z0^3))^(1/3) (Tabor 1977), z0 the equilibrium
    gap of the surfaces: the elastic neck height over the range of the forces."""
    return (R * w * w / (E_star * E_star * z0 ** 3)) ** (1.0 / 3.0)


def maugis_parameter(R, w, sigma0, E_star):
    """Maugis' lambda = 2 sigma0 (R / (pi w K^2))^(1/3), K = 4 E*/3 (Maugis 1992; Eq. 8)."""
    return 2.0 * sigma0 * (R / (math.pi * w * _K(E_star) ** 2)) ** (1.0 / 3.0)


# ---------------------------------------------------------------------------------------
# Hertz, JKR, DMT, Eqs. (5)-(7)
# ---------------------------------------------------------------------------------------


def hertz_radius(P, R, E_star):
    """Hertz contact radius a = (3 P R / (4 E*))^(1/3) (Eq. 5)."""
    return (P * R / _K(E_star)) ** (1.0 / 3.0)


def jkr_radius(P, R, w, E_star):
    """JKR contact radius at load P on the stable branch (Johnson, Kendall & Roberts
    1971; Eq. 6); ValueError below the pull-off force -3/2 pi w R."""
    s = 3.0 * math.pi * w * R
    disc = 2.0 * s * P + s * s
    if disc < 0.0:
        raise ValueError(f"load {P} N below the JKR pull-off force {-0.5 * s} N")
    return (R / _K(E_star) * (P + s + math.sqrt(disc))) ** (1.0 / 3.0)


def jkr_zero_load_radius(R, w, E_star):
    """a0 = (9 pi w R^2 / (2 E*))^(1/3), the JKR radius at P = 0 (Eq. 6)."""
    return (9.0 * math.pi * w * R * R / (2.0 * E_star)) ** (1.0 / 3.0)


def jkr_approach(a, R, w, E_star):
    """JKR approach delta = a^2 / R - sqrt(2 pi w a / E*) at contact radius a (Eq. 6)."""
    return a * a / R - math.sqrt(2.0 * math.pi * w * a / E_star)


def jkr_pull_off(R, w):
    """JKR pull-off force -3/2 pi w R (load control; Eq. 6), reached at a0 / 4^(1/3)."""
    return -1.5 * math.pi * w * R


def dmt_radius(P, R, w, E_star):
    """DMT contact radius a^3 = (R/K)(P + 2 pi w R) (Derjaguin, Muller & Toporov 1975;
    Eq. 7); ValueError below the pull-off force -2 pi w R."""
    total = P + 2.0 * math.pi * w * R
    if total < 0.0:
        raise ValueError(f"load {P} N below the DMT pull-off force {-2.0 * math.pi * w * R} N")
    return (R / _K(E_star) * total) ** (1.0 / 3.0)


def dmt_approach(a, R):
    """DMT approach delta = a^2 / R, Hertz's (Eq. 7)."""
    return a * a / R


def dmt_pull_off(R, w):
    """DMT (Bradley) pull-off force -2 pi w R (Eq. 7)."""
    return -2.0 * math.pi * w * R


# ---------------------------------------------------------------------------------------
# Maugis-Dugdale, Eqs. (8)-(11), in Maugis' dimensionless variables
# ---------------------------------------------------------------------------------------

_T_SERIES = 0.05   # below, t + (t^2 - 1) arctan t by its series (the two terms cancel)


def _f1(t):
    """t + (t^2 - 1) arctan t = t + (m^2 - 2) arctan t (Eq. 9), by its Taylor series
    sum_k (-1)^(k-1) 4k / (4k^2 - 1) t^(2k+1) for small t."""
    if t < _T_SERIES:
        return sum((-1) ** (k - 1) * 4.0 * k / (4.0 * k * k - 1.0) * t ** (2 * k + 1) for k in range(1, 9))
    return t + (t * t - 1.0) * math.atan(t)


def _f2(t):
    """t arctan t - m + 1 (Eq. 9), with m - 1 = t^2 / (m + 1) (no cancellation at m -> 1)."""
    return t * math.atan(t) - t * t / (math.sqrt(1.0 + t * t) + 1.0)


def md_radius_of_t(t, lam):
    """A on the Maugis-Dugdale curve at t = sqrt(m^2 - 1): the positive root of Eq. (9),
    a quadratic in A."""
    alpha = 0.5 * lam * _f1(t)
    beta = 4.0 * lam * lam / 3.0 * _f2(t)
    return 2.0 / (beta + math.sqrt(beta * beta + 4.0 * alpha))


def md_load_of_t(t, lam):
    """Pbar on the Maugis-Dugdale curve at t (Eqs. 9-10)."""
    A = md_radius_of_t(t, lam)
    return A ** 3 - lam * A * A * (t + (1.0 + t * t) * math.atan(t))


def md_approach(A, t, lam):
    """Delta = A^2 - (4/3) A lambda t (Eq. 11)."""
    return A * A - 4.0 / 3.0 * A * lam * t


@dataclass(frozen=True)
class MDPoint:
    """A point of the Maugis-Dugdale curve at Maugis' lambda (Eq. 8): A, m = c/a, Pbar,
    Delta (all dimensionless)."""
    lam: float
    A: float
    m: float
    Pbar: float
    Delta: float


def _md_point(t, lam):
    A = md_radius_of_t(t, lam)
    return MDPoint(lam, A, math.sqrt(1.0 + t * t), md_load_of_t(t, lam), md_approach(A, t, lam))


def _check_lambda(lam):
    if not 1e-4 <= lam <= 1e4:
        raise ValueError(f"Maugis' lambda = {lam} outside [1e-4, 1e4]: use DMT or JKR")


def _md_minimum_t(lam):
    """t of the least load on the Maugis-Dugdale curve: a grid in log t brackets the
    single minimum of Pbar(t), refined by bounded Brent minimisation."""
    logs = np.linspace(math.log(1e-6), math.log(1e8), 281)
    loads = [md_load_of_t(math.exp(x), lam) for x in logs]
    i = int(np.argmin(loads))
    if i == len(logs) - 1:
        return math.exp(logs[-1])
    res = optimize.minimize_scalar(lambda x: md_load_of_t(math.exp(x), lam), method="bounded",
                                   bounds=(logs[max(i - 1, 0)], logs[i + 1]), options={"xatol": 1e-12})
    return math.exp(res.x)


def md_pull_off(lam):
    """The pull-off (least) load of the Maugis-Dugdale curve under load control, as an
    `MDPoint` (Pbar from -2 at lambda -> 0 to -3/2 at lambda -> infinity)."""
    _check_lambda(lam)
    return _md_point(_md_minimum_t(lam), lam)


def md_contact(lam, Pbar=0.0):
    """The Maugis-Dugdale contact at Maugis' lambda and load Pbar (Eqs. 8-11) on the
    stable branch (the largest A), as an `MDPoint`: Pbar(t) falls monotonically from
    +infinity at t -> 0 to its minimum (`md_pull_off`), so the root is bracketed in
    (t_low, t_min) and found by brentq. ValueError below the pull-off load (a load within
    rounding, 1e-12, of it gives the pull-off point)."""
    _check_lambda(lam)
    t_min = _md_minimum_t(lam)
    p_min = md_load_of_t(t_min, lam)
    if Pbar < p_min - 1e-12 * abs(p_min):
        raise ValueError(f"load Pbar = {Pbar} below the Maugis-Dugdale pull-off {p_min} at lambda = {lam}")
    if Pbar <= p_min:
        return _md_point(t_min, lam)
    t_low = t_min
    while md_load_of_t(t_low, lam) < Pbar:
        t_low *= 0.1
        if t_low < 1e-30:
            raise ValueError(f"load Pbar = {Pbar} too large to bracket at lambda = {lam}")
    t = optimize.brentq(lambda x: md_load_of_t(x, lam) - Pbar, t_low, t_min, xtol=1e-300, rtol=1e-14,
                        maxiter=500)
    return _md_point(t, lam)


@dataclass(frozen=True)
class MaugisDugdale:
    """A Maugis-Dugdale contact in SI units: contact radius a and outer radius c of the
    cohesive zone [m], approach delta [m], load P [N], and the dimensionless `point`."""
    a: float
    c: float
    delta: float
    P: float
    point: MDPoint


def _md_scales(R, w, E_star):
    """The length scales of A and Delta and the force scale of Pbar (Eq. 8)."""
    K = _K(E_star)
    return ((math.pi * w * R * R / K) ** (1.0 / 3.0), (math.pi ** 2 * w * w * R / K ** 2) ** (1.0 / 3.0),
            math.pi * w * R)


def maugis_dugdale(R, w, sigma0, E_star, load=0.0):
    """The Maugis-Dugdale contact (Maugis 1992, Eqs. 8-11) of a sphere of radius R [m] on
    a flat, work of adhesion w [J/m^2], Dugdale stress sigma0 [Pa] (range h = w / sigma0),
    combined modulus E* [Pa], at load `load` [N] (> 0 compressive) on the stable branch."""
    length, depth, force = _md_scales(R, w, E_star)
    p = md_contact(maugis_parameter(R, w, sigma0, E_star), load / force)
    return MaugisDugdale(a=p.A * length, c=p.m * p.A * length, delta=p.Delta * depth, P=load, point=p)


def md_pressure(r, contact, R, sigma0, E_star):
    """The normal pressure [Pa] (> 0 compressive) at the radii r [m] of a Maugis-Dugdale
    contact (`maugis_dugdale`): the Hertz pressure of its contact radius a less the
    Dugdale adhesion's share inside a, the tension sigma0 over a < r < c, none beyond
    (Maugis 1992):

        p(r) = (2 E* / (pi R)) sqrt(a^2 - r^2)
               - (2 sigma0 / pi) arctan sqrt((c^2 - a^2) / (a^2 - r^2))    r < a,
        p(r) = -sigma0                                                    a < r < c.

    Its integral over the plane is the load: 4 E* a^3 / (3 R) from the first term and
    -2 sigma0 a^2 (sqrt(m^2 - 1) + m^2 arctan sqrt(m^2 - 1)) from the rest, Eq. (10)."""
    r = np.asarray(r, float)
    a, c = contact.a, contact.c
    inside = r < a
    q = np.where(inside, a * a - r * r, 1.0)
    hertz = 2.0 * E_star / (math.pi * R) * np.sqrt(q)
    adhesive = 2.0 * sigma0 / math.pi * np.arctan(np.sqrt((c * c - a * a) / q))
    return np.where(inside, hertz - adhesive, np.where(r < c, -sigma0, 0.0))


def md_zero_pressure_radius(contact, R, sigma0, E_star):
    """The radius [m] inside which a Maugis-Dugdale contact presses (`md_pressure` > 0):
    the edge of the compressive zone, which a simulation with a continuous law measures
    as the zero of its traction. In the DMT limit it is a (the Hertz pressure inside,
    the tension outside); towards JKR the adhesion pulls inside the edge too, and at
    zero load it falls to sqrt(2/3) a (JKR's pressure p0 sqrt(1 - x^2) - q / sqrt(1 - x^2)
    with q / p0 = 1/3)."""
    p = lambda r: float(md_pressure(r, contact, R, sigma0, E_star))
    if p(0.0) <= 0.0:
        return 0.0
    return optimize.brentq(p, 0.0, contact.a * (1.0 - 1e-12), xtol=1e-15 * contact.a)


def maugis_dugdale_pull_off(R, w, sigma0, E_star):
    """The Maugis-Dugdale pull-off force [N] under load control (`md_pull_off`)."""
    return md_pull_off(maugis_parameter(R, w, sigma0, E_star)).Pbar * math.pi * w * R


# ---------------------------------------------------------------------------------------
# One adhered sphere: the three theories side by side
# ---------------------------------------------------------------------------------------

JKR_ABOVE = 5.0
DMT_BELOW = 0.1


def regime(lam):
    """The theory that applies at Maugis' lambda: "JKR" for lambda > 5, "DMT" for
    lambda < 0.1, "MD" between: the bounds commonly quoted from the adhesion map of
    Johnson & Greenwood (J. Colloid Interface Sci. 192, 326 (1997)), beyond which the
    simpler theory's pull-off force is within a few percent of Maugis-Dugdale's. With this
    module: at lambda = 5 the MD pull-off is 0.4 % and the zero-load radius 0.9 % from
    JKR's; at lambda = 0.1, 2.5 % and 6 % from DMT's (the radius converges slowest)."""
    if lam > JKR_ABOVE:
        return "JKR"
    if lam < DMT_BELOW:
        return "DMT"
    return "MD"


@dataclass(frozen=True)
class AdheredSphere:
    """A sphere adhered to a flat at one load by the three theories: Maugis' lambda
    `lam`, Tabor's mu `tabor` (nan without z0), contact radii a_* [m], approaches
    delta_* [m], the MD cohesive zone's outer radius c_md [m], the pull-off forces [N]
    and the `regime` that applies (`regime`)."""
    lam: float
    tabor: float
    a_jkr: float
    a_dmt: float
    a_md: float
    c_md: float
    delta_jkr: float
    delta_dmt: float
    delta_md: float
    pull_off_jkr: float
    pull_off_dmt: float
    pull_off_md: float
    regime: str


def adhered_sphere(R, w, E_star, load=0.0, *, sigma0=None, h=None, z0=None):
    """JKR, DMT and Maugis-Dugdale contact of a sphere of radius R [m] on a flat at
    `load` [N] (default 0: adhered at rest), work of adhesion w [J/m^2], combined
    modulus E* [Pa], and the range of the forces given by exactly one of `sigma0` [Pa]
    (the theoretical strength) or `h` [m] (the Dugdale range, sigma0 = w / h). `z0` [m],
    the equilibrium gap, gives Tabor's parameter. Returns an `AdheredSphere`."""
    if (sigma0 is None) == (h is None):
        raise ValueError("give exactly one of sigma0 and h")
    if sigma0 is None:
        sigma0 = w / h
    md = maugis_dugdale(R, w, sigma0, E_star, load)
    a_jkr = jkr_radius(load, R, w, E_star)
    a_dmt = dmt_radius(load, R, w, E_star)
    return AdheredSphere(
        lam=md.point.lam, tabor=tabor_parameter(R, w, E_star, z0) if z0 is not None else float("nan"),
        a_jkr=a_jkr, a_dmt=a_dmt, a_md=md.a, c_md=md.c,
        delta_jkr=jkr_approach(a_jkr, R, w, E_star), delta_dmt=dmt_approach(a_dmt, R), delta_md=md.delta,
        pull_off_jkr=jkr_pull_off(R, w), pull_off_dmt=dmt_pull_off(R, w),
        pull_off_md=maugis_dugdale_pull_off(R, w, sigma0, E_star), regime=regime(md.point.lam))


# ---------------------------------------------------------------------------------------
# Command line
# ---------------------------------------------------------------------------------------


def main(argv=None):
    parser = argparse.ArgumentParser(
        description="JKR, DMT and Maugis-Dugdale contact of an adhered sphere on a flat (SI units). The "
                    "adhesion is given by --w with --h or --sigma0 (and optionally --z0), or by the contact "
                    "term's parameters --epsilon --s0 --beta [--cutoff].")
    parser.add_argument("--R", type=float, required=True, help="sphere radius [m]")
    parser.add_argument("--E-star", type=float, required=True, help="combined modulus E* [Pa]")
    parser.add_argument("--load", type=float, default=0.0, help="load [N], > 0 compressive (default 0)")
    parser.add_argument("--w", type=float, help="work of adhesion [J/m^2]")
    parser.add_argument("--h", type=float, help="Dugdale range w / sigma0 [m]")
    parser.add_argument("--sigma0", type=float, help="theoretical strength [Pa]")
    parser.add_argument("--z0", type=float, help="equilibrium gap [m] (Tabor's parameter)")
    parser.add_argument("--epsilon", type=float, help="contact term: epsilon [J]")
    parser.add_argument("--s0", type=float, help="contact term: s0 [m]")
    parser.add_argument("--beta", type=float, nargs=2, help="contact term: beta1 beta2 [1/m^3]")
    parser.add_argument("--cutoff", type=float, help="contact term: cutoff [m] (default 3 s0)")
    args = parser.parse_args(argv)
    w, sigma0, h, z0 = args.w, args.sigma0, args.h, args.z0
    if args.epsilon is not None:
        if args.s0 is None or args.beta is None:
            parser.error("--epsilon needs --s0 and --beta")
        law = contact_term_law(args.epsilon, args.s0, args.beta, args.cutoff)
        w, sigma0, h, z0 = law.w, law.sigma0, None, law.z0
        print(f"contact law: w = {law.w:.6g} J/m^2, sigma0 = {law.sigma0:.6g} Pa, z0 = {law.z0:.6g} m, "
              f"h = w/sigma0 = {law.h:.6g} m, peak tension at {law.peak_gap:.6g} m")
    elif w is None or (sigma0 is None) == (h is None):
        parser.error("give --w with one of --h, --sigma0, or the contact term's --epsilon --s0 --beta")
    s = adhered_sphere(args.R, w, args.E_star, args.load, sigma0=sigma0, h=h, z0=z0)
    print(f"Maugis lambda = {s.lam:.4g}, Tabor mu = {s.tabor:.4g}: {s.regime} applies")
    print(f"{'theory':8s} {'a [m]':>12s} {'delta [m]':>12s} {'pull-off [N]':>13s}")
    for name, a, d, p in (("JKR", s.a_jkr, s.delta_jkr, s.pull_off_jkr), ("DMT", s.a_dmt, s.delta_dmt, s.pull_off_dmt),
                          ("MD", s.a_md, s.delta_md, s.pull_off_md)):
        print(f"{name:8s} {a:12.5g} {d:12.5g} {p:13.5g}")
    print(f"MD cohesive zone to c = {s.c_md:.5g} m")


if __name__ == "__main__":
    main()
