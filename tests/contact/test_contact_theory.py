"""Tests of the adhesive-contact reference module (scripts/lib/contact_theory.py): the
adhesion of the contact term's law between two half-spaces against the closed form of
the untruncated 12-6 potential and against an independent 2-D quadrature of the pair
sum's continuum limit (written from the C++ force loop), the values
docs/theory/contact.md quotes, the Hertz, JKR and DMT closed forms, and the
Maugis-Dugdale solver against its JKR and DMT limits and an independent solution of
its equations parametrised by the contact radius. About 1 s on one core."""
import math
import os
import sys

import numpy as np
import pytest
from scipy import integrate, optimize

sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "lib"))
import contact_theory as ct  # noqa: E402

# The adhesion scene's contact term (examples/adhesion/adhesion.toml).
EPS, S0, BETA = 3.265e-15, 0.75e-6, (1e18, 1e18)


# --- independent references ------------------------------------------------------------

def lj_half_space_closed_form(D, c12, c6, rho1, rho2):
    """W(D) and sigma(D) = -dW/dD of two half-spaces under phi = c12 r^-12 - c6 r^-6
    without cutoff. A molecule at height z over a half-space of density rho:
    int_z^inf 2 pi r (r - z) r^-n dr = 2 pi rho z^(3-n) / ((n-2)(n-3)); integrated over
    the other half-space, int_D^inf z^(3-n) dz = D^(4-n) / (n-4). So
    W = 2 pi rho1 rho2 [c12 / (10 9 8 D^8) - c6 / (4 3 2 D^2)]."""
    W = 2.0 * math.pi * rho1 * rho2 * (c12 / (720.0 * D ** 8) - c6 / (24.0 * D ** 2))
    sigma = 2.0 * math.pi * rho1 * rho2 * (8.0 * c12 / (720.0 * D ** 9) - 2.0 * c6 / (24.0 * D ** 3))
    return W, sigma


def code_pair(eps, s0):
    """The pair law of src/terms/contact/contact.hpp (LennardJones::energy_and_slope),
    written again: phi(r) and phi'(r) / r from the squared distance."""
    def energy_and_slope(r2):
        inv_r2 = 1.0 / r2
        u2 = s0 * s0 * inv_r2
        u6 = u2 * u2 * u2
        return eps * (u6 * u6 - 2.0 * u6), eps * 12.0 * (u6 - u6 * u6) * inv_r2
    return energy_and_slope


def brute_force_half_spaces(eps, s0, beta1, beta2, rc):
    """W(D) and sigma(D) of two half-spaces under the contact term's pair sum in the
    continuum limit, by 2-D quadrature over the height difference zeta of two molecules
    and their lateral distance s (the pairs with z1 > D, z2 < 0 at height difference
    zeta have the measure (zeta - D) per unit area): W from the shifted energy
    phi(r) - phi(rc), sigma from the pair forces -phi'(r) zeta / r (the force loop), both
    over r < rc. Not the module's order (radius first), not its formula."""
    pair = code_pair(eps, s0)
    shift = pair(rc * rc)[0]

    def lateral(z):
        return math.sqrt(max(rc * rc - z * z, 0.0))

    def energy(D):
        v, _ = integrate.dblquad(lambda s, z: (z - D) * s * (pair(s * s + z * z)[0] - shift), D, rc, 0.0, lateral,
                                 epsabs=1e-11 * eps * s0 ** 4, epsrel=1e-10)
        return 2.0 * math.pi * beta1 * beta2 * v

    def traction(D):
        v, _ = integrate.dblquad(lambda s, z: (z - D) * z * s * -pair(s * s + z * z)[1], D, rc, 0.0, lateral,
                                 epsabs=1e-11 * eps * s0 ** 3, epsrel=1e-10)
        return 2.0 * math.pi * beta1 * beta2 * v
    return energy, traction


def md_load_of_A(A, lam):
    """Pbar at contact radius A of the Maugis-Dugdale equations (Maugis 1992, in
    Johnson & Greenwood's notation), solved the other way round from the module: m from
    Eq. (9) at given A by bracketing (its left side rises from 0 at m = 1), then
    Eq. (10). Returns Pbar and m."""
    def eq9(m):
        t = math.sqrt(m * m - 1.0)
        at = math.atan(t)
        return (lam * A * A / 2.0 * (t + (m * m - 2.0) * at) + 4.0 * lam * lam * A / 3.0 * (t * at - m + 1.0) - 1.0)
    hi = 2.0
    while eq9(hi) < 0.0:
        hi *= 2.0
    m = optimize.brentq(eq9, 1.0 + 1e-15, hi, xtol=1e-14, rtol=1e-14)
    t = math.sqrt(m * m - 1.0)
    return A ** 3 - lam * A * A * (t + m * m * math.atan(t)), m


# --- moduli ------------------------------------------------------------------------------

def test_the_combined_modulus():
    E, nu = 2e4, 0.3
    assert ct.combined_modulus(E, nu, E, nu) == pytest.approx(E / (2.0 * (1.0 - nu * nu)), rel=1e-14)
    assert ct.combined_modulus(E, nu, math.inf, 0.2) == pytest.approx(E / (1.0 - nu * nu), rel=1e-14)
    assert ct.combined_modulus(1e4, 0.45, 3e4, 0.49) == pytest.approx(ct.combined_modulus(3e4, 0.49, 1e4, 0.45),
                                                                      rel=1e-14)


def test_isotropic_moduli_from_shear_and_bulk():
    # nu = 0.25 is lambda = mu: K = 5 mu / 3, E = 2.5 mu.
    E, nu = ct.isotropic_moduli(1.0, 5.0 / 3.0)
    assert E == pytest.approx(2.5, rel=1e-14) and nu == pytest.approx(0.25, rel=1e-14)


# --- the contact law between two half-spaces ------------------------------------------------

@pytest.mark.parametrize("form", ["seed", "standard"])
def test_the_half_space_energy_has_the_closed_form_without_cutoff(form):
    # The seed's form (Eq. 13: c12 = eps s0^12, c6 = 2 eps s0^6) and the common
    # 4 eps [(s/r)^12 - (s/r)^6], in SI units of the adhesion scene.
    if form == "seed":
        phi, c12, c6 = ct.lennard_jones(EPS, S0), EPS * S0 ** 12, 2.0 * EPS * S0 ** 6
    else:
        phi = lambda r: 4.0 * EPS * ((S0 / r) ** 12 - (S0 / r) ** 6)  # noqa: E731
        c12, c6 = 4.0 * EPS * S0 ** 12, 4.0 * EPS * S0 ** 6
    for d in (0.55, 0.6367, 0.8, 1.0, 1.5, 3.0, 10.0):
        W, sigma = lj_half_space_closed_form(d * S0, c12, c6, *BETA)
        assert ct.half_space_energy(d * S0, phi, math.inf, *BETA) == pytest.approx(W, rel=1e-8)
        assert ct.half_space_traction(d * S0, phi, math.inf, *BETA) == pytest.approx(sigma, rel=1e-8)


def test_the_untruncated_law_has_the_values_the_docs_quote():
    # sigma = 0 where c12 / (45 D^9) = c6 / (6 D^3): D0^6 = 2 c12 / (15 c6) = s0^6 / 15;
    # the peak where 9 c12 / (45 D^10) = 3 c6 / (6 D^4): D^6 = s0^6 / 5.
    law = ct.contact_term_law(EPS, S0, BETA, cutoff=math.inf)
    unit = BETA[0] * BETA[1] * EPS
    assert law.z0 == pytest.approx(15.0 ** (-1.0 / 6.0) * S0, rel=1e-12)
    assert law.peak_gap == pytest.approx(5.0 ** (-1.0 / 6.0) * S0, rel=1e-10)
    W0, _ = lj_half_space_closed_form(law.z0, EPS * S0 ** 12, 2.0 * EPS * S0 ** 6, *BETA)
    _, peak = lj_half_space_closed_form(5.0 ** (-1.0 / 6.0) * S0, EPS * S0 ** 12, 2.0 * EPS * S0 ** 6, *BETA)
    assert law.w == pytest.approx(-W0, rel=1e-10)
    assert law.sigma0 == pytest.approx(-peak, rel=1e-10)
    # docs/theory/contact.md: |W(d0)| = 0.96848 and p_min = -1.56107 beta1 beta2 eps s0^n;
    # the scene's comment: 1e-3 J/m^2.
    assert law.w / (unit * S0 ** 4) == pytest.approx(0.96848, abs=1e-5)
    assert law.sigma0 / (unit * S0 ** 3) == pytest.approx(1.56107, abs=1e-5)
    assert law.w == pytest.approx(1e-3, rel=1e-3)


def test_the_untruncated_law_relates_maugis_and_tabor_parameters():
    # 9-3 law: sigma0 z0 / w = 16 / (9 sqrt 3), so lambda / mu = 2 (16 / (9 sqrt 3))
    # (9 / (16 pi))^(1/3) = 1.157 (K = 4 E* / 3).
    law = ct.contact_term_law(EPS, S0, BETA, cutoff=math.inf)
    assert law.sigma0 * law.z0 / law.w == pytest.approx(16.0 / (9.0 * math.sqrt(3.0)), rel=1e-10)
    R, E_star = 5e-6, 1.2e4
    ratio = ct.maugis_parameter(R, law.w, law.sigma0, E_star) / ct.tabor_parameter(R, law.w, E_star, law.z0)
    assert ratio == pytest.approx(32.0 / (9.0 * math.sqrt(3.0)) * (9.0 / (16.0 * math.pi)) ** (1.0 / 3.0), rel=1e-10)
    assert ratio == pytest.approx(1.157, abs=1e-3)


@pytest.mark.parametrize("cutoff", [3.0, 5.0])
def test_the_truncated_law_matches_a_brute_force_quadrature_of_the_pair_sum(cutoff):
    # w = -min W and sigma0 = -min sigma of the 2-D quadrature (pair energies and pair
    # forces of the C++ law), minimised independently, against the module in SI units.
    energy, traction = brute_force_half_spaces(1.0, 1.0, 1.0, 1.0, cutoff)
    e = optimize.minimize_scalar(energy, bounds=(0.55, 0.75), method="bounded", options={"xatol": 1e-7})
    s = optimize.minimize_scalar(traction, bounds=(0.68, 0.88), method="bounded", options={"xatol": 1e-7})
    law = ct.contact_term_law(EPS, S0, BETA, cutoff=cutoff * S0)
    unit = BETA[0] * BETA[1] * EPS
    assert law.w / (unit * S0 ** 4) == pytest.approx(-e.fun, rel=1e-6)
    assert law.sigma0 / (unit * S0 ** 3) == pytest.approx(-s.fun, rel=1e-6)
    assert law.z0 / S0 == pytest.approx(e.x, abs=1e-4)       # the minima's positions, to their tolerance
    assert law.peak_gap / S0 == pytest.approx(s.x, abs=1e-4)
    assert abs(traction(law.z0 / S0)) < 1e-8 * law.sigma0 / (unit * S0 ** 3)
    assert law.h == pytest.approx(law.w / law.sigma0, rel=1e-15)


def test_the_truncated_law_has_the_values_the_docs_table_quotes():
    # docs/theory/contact.md, "Truncation": zero-traction gap, peak position and
    # p_min / (beta1 beta2 eps s0^3) for rc = 3, 5, 10 s0, to the digits given.
    unit = BETA[0] * BETA[1] * EPS
    for rc, z0, peak, pmin in ((3.0, 0.6434, 0.7663, 1.339), (5.0, 0.6383, 0.7649, 1.506),
                               (10.0, 0.6370, 0.7647, 1.553)):
        law = ct.contact_term_law(EPS, S0, BETA, cutoff=rc * S0)
        assert law.z0 / S0 == pytest.approx(z0, abs=5e-5)
        assert law.peak_gap / S0 == pytest.approx(peak, abs=5e-5)
        assert law.sigma0 / (unit * S0 ** 3) == pytest.approx(pmin, abs=5e-4)
    # The default cutoff is 3 s0; it keeps 64 % of the untruncated adhesion energy (the
    # shift phi(rc) inside the cutoff costs a further part of the lost r^-6 tail).
    default = ct.contact_term_law(EPS, S0, BETA)
    assert default == ct.contact_term_law(EPS, S0, BETA, cutoff=3.0 * S0)
    full = ct.contact_term_law(EPS, S0, BETA, cutoff=math.inf)
    assert default.w / full.w == pytest.approx(0.640, abs=1e-3)


def test_the_contact_law_refuses_what_the_term_refuses():
    with pytest.raises(ValueError):
        ct.contact_term_law(EPS, S0, BETA, cutoff=S0)
    with pytest.raises(ValueError):
        ct.contact_term_law(EPS, S0, (0.0, 1e18))


# --- Hertz, JKR, DMT ---------------------------------------------------------------------

R, E_STAR, W = 5e-6, 1.2e4, 6e-4


def test_jkr_closed_form_identities():
    a0 = ct.jkr_zero_load_radius(R, W, E_STAR)
    assert ct.jkr_radius(0.0, R, W, E_STAR) == pytest.approx(a0, rel=1e-14)
    assert a0 ** 3 == pytest.approx(9.0 * math.pi * W * R * R / (2.0 * E_STAR), rel=1e-13)
    # At pull-off the radius is a0 / 4^(1/3); below it there is no contact.
    P_c = ct.jkr_pull_off(R, W)
    assert P_c == pytest.approx(-1.5 * math.pi * W * R, rel=1e-15)
    assert ct.jkr_radius(P_c, R, W, E_STAR) == pytest.approx(a0 / 4.0 ** (1.0 / 3.0), rel=1e-12)
    with pytest.raises(ValueError):
        ct.jkr_radius(1.001 * P_c, R, W, E_STAR)
    # The approach at zero load: a0^2 / R - (2/3) a0^2 / R = a0^2 / (3 R).
    assert ct.jkr_approach(a0, R, W, E_STAR) == pytest.approx(a0 * a0 / (3.0 * R), rel=1e-12)
    # The load as a function of a, P = K a^3 / R - sqrt(6 pi w K a^3), inverts jkr_radius,
    # and its minimum is the pull-off force.
    K = 4.0 * E_STAR / 3.0
    load = lambda a: K * a ** 3 / R - math.sqrt(6.0 * math.pi * W * K * a ** 3)  # noqa: E731
    for P in (-0.5 * abs(P_c), 0.0, 3.0 * abs(P_c)):
        assert load(ct.jkr_radius(P, R, W, E_STAR)) == pytest.approx(P, abs=1e-10 * abs(P_c))
    res = optimize.minimize_scalar(load, bounds=(0.1 * a0, a0), method="bounded", options={"xatol": 1e-15})
    assert res.fun == pytest.approx(P_c, rel=1e-9)


def test_dmt_closed_form_identities():
    K = 4.0 * E_STAR / 3.0
    P_c = ct.dmt_pull_off(R, W)
    assert P_c == pytest.approx(-2.0 * math.pi * W * R, rel=1e-15)
    assert ct.dmt_radius(P_c, R, W, E_STAR) == 0.0
    a = ct.dmt_radius(0.0, R, W, E_STAR)
    assert a ** 3 == pytest.approx(2.0 * math.pi * W * R * R / K, rel=1e-13)
    assert ct.dmt_approach(a, R) == pytest.approx(a * a / R, rel=1e-15)
    with pytest.raises(ValueError):
        ct.dmt_radius(1.001 * P_c, R, W, E_STAR)


def test_without_adhesion_every_theory_is_hertz():
    # w -> 0 at a fixed load: a^3 = 3 P R / (4 E*). MD with the stress fixed (lambda
    # large) and with the range fixed (lambda small).
    P, w = 1e-8, 1e-12
    hertz = (3.0 * P * R / (4.0 * E_STAR)) ** (1.0 / 3.0)
    assert ct.hertz_radius(P, R, E_STAR) == pytest.approx(hertz, rel=1e-14)
    assert ct.jkr_radius(P, R, w, E_STAR) == pytest.approx(hertz, rel=1e-4)
    assert ct.dmt_radius(P, R, w, E_STAR) == pytest.approx(hertz, rel=1e-8)
    for sigma0 in (1e2, 1e-3):
        md = ct.maugis_dugdale(R, w, sigma0, E_STAR, load=P)
        assert md.a == pytest.approx(hertz, rel=1e-4)
        assert md.delta == pytest.approx(hertz ** 2 / R, rel=1e-3)


# --- Maugis-Dugdale ------------------------------------------------------------------------

@pytest.mark.parametrize("t", [1e-4, 1e-3, 0.01, 0.049, 0.051, 0.2, 3.0])
def test_the_bracket_of_eq_9_is_accurate_at_small_t(t):
    # t + (t^2 - 1) arctan t cancels as t -> 0 (the module switches to its series below
    # t = 0.05); against the quadrature of its derivative 2 x arctan x + 2 x^2 / (1 + x^2),
    # which has no cancellation.
    ref, _ = integrate.quad(lambda x: 2.0 * x * math.atan(x) + 2.0 * x * x / (1.0 + x * x), 0.0, t,
                            epsabs=0.0, epsrel=1e-13)
    assert ct._f1(t) == pytest.approx(ref, rel=1e-12)


def test_maugis_dugdale_tends_to_jkr_for_large_lambda():
    # JKR in Maugis' variables: A^3 = 6 at Pbar = 0, Delta = A^2 - (2/3) sqrt(6 A),
    # pull-off Pbar = -3/2 at A = (3/2)^(1/3).
    p = ct.md_contact(50.0)
    assert p.A == pytest.approx(6.0 ** (1.0 / 3.0), rel=1e-3)
    assert p.Delta == pytest.approx(p.A ** 2 - 2.0 / 3.0 * math.sqrt(6.0 * p.A), rel=1e-3)
    c = ct.md_pull_off(50.0)
    assert c.Pbar == pytest.approx(-1.5, rel=5e-4)
    assert c.A == pytest.approx(1.5 ** (1.0 / 3.0), rel=1e-2)
    # ... and not yet at lambda = 1: the limit is not reached trivially.
    assert abs(ct.md_contact(1.0).A / 6.0 ** (1.0 / 3.0) - 1.0) > 0.05


def test_maugis_dugdale_tends_to_dmt_for_small_lambda():
    # DMT: A^3 = 2 at Pbar = 0, pull-off -2. The approach converges more slowly: at small
    # lambda Eq. (9) gives m^2 = 4 / (pi lambda A^2), so Eq. (11) departs from A^2 by
    # (4/3) A lambda t = (8/3) sqrt(lambda / pi) (the cohesive zone's own deflection).
    p = ct.md_contact(0.01)
    assert p.A == pytest.approx(2.0 ** (1.0 / 3.0), rel=1e-2)
    assert ct.md_pull_off(0.01).Pbar == pytest.approx(-2.0, rel=2e-3)
    q = ct.md_contact(1e-4)
    assert q.A == pytest.approx(2.0 ** (1.0 / 3.0), rel=1e-3)
    assert q.A ** 2 - q.Delta == pytest.approx(8.0 / 3.0 * math.sqrt(1e-4 / math.pi), rel=1e-3)
    assert abs(ct.md_contact(1.0).A / 2.0 ** (1.0 / 3.0) - 1.0) > 0.05


@pytest.mark.parametrize("lam", [0.01, 0.1, 0.5, 1.0, 3.0, 10.0])
def test_maugis_dugdale_solution_against_the_equations_solved_by_radius(lam):
    # Independent solution: Pbar(A) with m from Eq. (9) at each A. Its least value is the
    # pull-off; at a load between the pull-off and Pbar(A -> 0) two radii carry it, and
    # the module returns the larger (stable under load control).
    A_grid = np.geomspace(1e-3, 4.0, 400)
    loads = np.array([md_load_of_A(A, lam)[0] for A in A_grid])
    i = int(np.argmin(loads))
    res = optimize.minimize_scalar(lambda A: md_load_of_A(A, lam)[0], bounds=(A_grid[max(i - 1, 0)], A_grid[i + 1]),
                                   method="bounded", options={"xatol": 1e-10})
    pull = ct.md_pull_off(lam)
    assert pull.Pbar == pytest.approx(res.fun, rel=1e-9)
    assert pull.A == pytest.approx(res.x, rel=1e-3)    # flat minimum: the position to sqrt(tolerance)
    for Pbar in (0.0, 0.5 * (pull.Pbar + loads[0]), 2.0):
        p = ct.md_contact(lam, Pbar)
        check, m = md_load_of_A(p.A, lam)
        assert check == pytest.approx(Pbar, abs=1e-10)
        assert p.m == pytest.approx(m, rel=1e-9)
        assert p.Delta == pytest.approx(p.A ** 2 - 4.0 / 3.0 * p.A * lam * math.sqrt(m * m - 1.0), rel=1e-9)
        roots = [A_grid[k] for k in range(len(A_grid) - 1) if (loads[k] - Pbar) * (loads[k + 1] - Pbar) <= 0.0]
        assert p.A >= max(roots) * (1.0 - 1e-2)
    with pytest.raises(ValueError):
        ct.md_contact(lam, pull.Pbar - 1e-3)


def test_the_maugis_dugdale_pull_off_moves_monotonically_from_dmt_to_jkr():
    # Pbar_c from -2 (lambda -> 0) to -3/2 (lambda -> infinity). (Note: at lambda = 1 this
    # gives -1.601; no published table was at hand to check that value against.)
    lams = [0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0]
    pulls = [ct.md_pull_off(lam).Pbar for lam in lams]
    assert all(-2.0 < p < -1.5 for p in pulls)
    assert all(b > a for a, b in zip(pulls, pulls[1:]))


def test_the_dimensional_maugis_dugdale_contact_scales_as_maugis():
    sigma0 = 2e3
    K = 4.0 * E_STAR / 3.0
    lam = ct.maugis_parameter(R, W, sigma0, E_STAR)
    assert lam == pytest.approx(2.0 * sigma0 * (R / (math.pi * W * K * K)) ** (1.0 / 3.0), rel=1e-14)
    for load in (0.0, 1e-8):
        md = ct.maugis_dugdale(R, W, sigma0, E_STAR, load)
        p = ct.md_contact(lam, load / (math.pi * W * R))
        assert md.a == pytest.approx(p.A * (math.pi * W * R * R / K) ** (1.0 / 3.0), rel=1e-12)
        assert md.c == pytest.approx(p.m * md.a, rel=1e-12)
        assert md.delta == pytest.approx(p.Delta * (math.pi ** 2 * W * W * R / K ** 2) ** (1.0 / 3.0), rel=1e-12)
    P_c = ct.maugis_dugdale_pull_off(R, W, sigma0, E_STAR)
    assert P_c == pytest.approx(ct.md_pull_off(lam).Pbar * math.pi * W * R, rel=1e-12)
    assert ct.maugis_dugdale(R, W, sigma0, E_STAR, P_c).a > 0.0


# --- one adhered sphere ----------------------------------------------------------------------

def test_adhered_sphere_gathers_the_theories():
    law = ct.contact_term_law(EPS, S0, BETA)
    s = ct.adhered_sphere(R, law.w, E_STAR, sigma0=law.sigma0, z0=law.z0)
    assert s == ct.adhered_sphere(R, law.w, E_STAR, h=law.h, z0=law.z0)
    assert s.a_jkr == pytest.approx(ct.jkr_zero_load_radius(R, law.w, E_STAR), rel=1e-14)
    assert s.a_dmt == pytest.approx(ct.dmt_radius(0.0, R, law.w, E_STAR), rel=1e-14)
    assert s.a_dmt < s.a_md < s.a_jkr
    assert s.pull_off_jkr > s.pull_off_md > s.pull_off_dmt
    assert s.tabor == pytest.approx(ct.tabor_parameter(R, law.w, E_STAR, law.z0), rel=1e-14)
    assert s.regime == "MD"
    assert math.isnan(ct.adhered_sphere(R, law.w, E_STAR, h=law.h).tabor)
    with pytest.raises(ValueError):
        ct.adhered_sphere(R, law.w, E_STAR)
    with pytest.raises(ValueError):
        ct.adhered_sphere(R, law.w, E_STAR, sigma0=law.sigma0, h=law.h)


def test_the_regimes_of_the_adhesion_map():
    assert [ct.regime(x) for x in (0.05, 0.1, 1.0, 5.0, 6.0)] == ["DMT", "MD", "MD", "MD", "JKR"]
    # The docstring's claims about the bounds: at lambda = 5, MD within 1 % of JKR; at
    # lambda = 0.1, within 2.5 % (pull-off) and 6.1 % (radius) of DMT.
    assert abs(ct.md_contact(5.0).A / 6.0 ** (1.0 / 3.0) - 1.0) < 0.01
    assert abs(ct.md_pull_off(5.0).Pbar / -1.5 - 1.0) < 0.005
    assert abs(ct.md_pull_off(0.1).Pbar / -2.0 - 1.0) < 0.025
    assert abs(ct.md_contact(0.1).A / 2.0 ** (1.0 / 3.0) - 1.0) < 0.061


def test_the_command_line_prints_the_table(capsys):
    ct.main(["--R", "5e-6", "--E-star", "1.2e4", "--epsilon", str(EPS), "--s0", str(S0), "--beta", "1e18", "1e18"])
    out = capsys.readouterr().out
    assert "contact law: w = " in out and "MD applies" in out
    assert all(name in out for name in ("JKR", "DMT", "MD"))


@pytest.mark.parametrize("lam,load_over_piwR", [(0.37, 0.0), (1.0, 0.0), (0.37, 2.0)])
def test_the_maugis_dugdale_pressure_integrates_to_the_load(lam, load_over_piwR):
    # sigma0 chosen for the wanted lambda at R, w, E*: lambda = 2 sigma0 (R / (pi w K^2))^(1/3).
    R, w, E_star = 5e-6, 6.4e-4, 3.7e4
    K = 4.0 * E_star / 3.0
    sigma0 = lam / (2.0 * (R / (math.pi * w * K * K)) ** (1.0 / 3.0))
    load = load_over_piwR * math.pi * w * R
    contact = ct.maugis_dugdale(R, w, sigma0, E_star, load)
    # Over r < a in u = sqrt(a^2 - r^2) (the square-root edge becomes smooth), then the
    # Dugdale ring a < r < c at -sigma0 exactly.
    a, c = contact.a, contact.c
    inside = integrate.quad(lambda u: 2.0 * math.pi * u * float(ct.md_pressure(math.sqrt(max(a * a - u * u, 0.0)),
                                                                             contact, R, sigma0, E_star)),
                            0.0, a, limit=200, epsabs=0.0, epsrel=1e-11)[0]
    ring = -sigma0 * math.pi * (c * c - a * a)
    scale = 4.0 * E_star * a ** 3 / (3.0 * R)  # the Hertz share, against which a zero load is small
    assert inside + ring == pytest.approx(load, abs=1e-8 * scale)


def test_the_compressive_zone_of_maugis_dugdale_runs_from_a_in_dmt_to_jkrs_closed_form():
    # JKR at zero load: p = p0 sqrt(1 - x^2) - q / sqrt(1 - x^2), x = r / a, with
    # q / p0 = 1/3 (a^3 = 9 pi w R^2 / (2 E*)), so it presses inside x = sqrt(2/3).
    # DMT: the Hertz pressure inside a, the tension outside: it presses inside a.
    R, w, E_star = 5e-6, 6.4e-4, 3.7e4
    K = 4.0 * E_star / 3.0
    ratios = []
    for lam in (0.01, 0.37, 1.0, 50.0):
        sigma0 = lam / (2.0 * (R / (math.pi * w * K * K)) ** (1.0 / 3.0))
        contact = ct.maugis_dugdale(R, w, sigma0, E_star)
        a0 = ct.md_zero_pressure_radius(contact, R, sigma0, E_star)
        assert float(ct.md_pressure(0.999 * a0, contact, R, sigma0, E_star)) > 0.0
        assert float(ct.md_pressure(1.001 * a0, contact, R, sigma0, E_star)) < 0.0
        ratios.append(a0 / contact.a)
    assert ratios[0] == pytest.approx(1.0, abs=0.01)
    assert ratios[-1] == pytest.approx(math.sqrt(2.0 / 3.0), rel=0.01)
    assert ratios == sorted(ratios, reverse=True)
