"""Tests of the self-consistent adhered sphere with the contact law's own traction
(scripts/lib/derjaguin_contact.py): its elastic kernel against Hertz's closed-form
displacement, its solution with Dugdale's law against Maugis-Dugdale (the theory it
generalises; contact_theory.py is tested on its own), its discretisation, and the
contact law's solution at rest. About 15 s on one core."""
import math
import os
import sys

import numpy as np
import pytest

sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "lib"))
import contact_theory as ct  # noqa: E402
import derjaguin_contact as dc  # noqa: E402

# The adhesion scene's contact term (examples/adhesion/adhesion.toml) and the sphere of
# examples/adhesion/sphere_at_rest.toml.
EPS, S0, BETA = 3.265e-15, 0.75e-6, (1e18, 1e18)
R = 5e-6


def test_ring_kernel_gives_hertz_displacement():
    """Hertz's pressure p0 sqrt(1 - r^2/a^2) separates the surfaces by
    pi p0 (2 a^2 - r^2) / (4 a E*) inside a (Johnson 1985, Eq. 3.41): the rings' kernel
    to 2e-4 of the central value on 600 rings."""
    E_star, a, p0 = 1e4, 1e-6, 100.0
    edges = np.linspace(0.0, 3e-6, 601)
    r = 0.5 * (edges[1:] + edges[:-1])
    u = dc.influence_matrix(edges, E_star) @ (p0 * np.sqrt(np.clip(1.0 - r * r / (a * a), 0.0, None)))
    exact = math.pi * p0 * (2.0 * a * a - r * r) / (4.0 * a * E_star)
    inside = r < a
    assert np.max(np.abs(u[inside] - exact[inside])) < 2e-4 * exact[0]


def test_disk_displacement_continuous_at_its_edge():
    """Eq. (2)'s two branches meet at r = b (4 b / (pi E*)) and decay as b^2 / (2 r) far away."""
    b, E_star = 1e-6, 1e4
    u = dc.disk_displacement(np.array([b * (1 - 1e-9), b, b * (1 + 1e-9), 1e3 * b]), b, E_star)
    assert u[0] == pytest.approx(4.0 * b / (math.pi * E_star), rel=1e-6)
    assert u[2] == pytest.approx(u[0], rel=1e-6)
    assert u[3] == pytest.approx(4.0 / (math.pi * E_star) * b * b * math.pi / (4.0 * 1e3 * b), rel=1e-3)


class SmoothedDugdale:
    """Dugdale's law of strength sigma0 and range h above the gap z0, with a stiff linear
    repulsion below z0, its end smoothed over 5 % of h (the same work of adhesion w =
    sigma0 h): Maugis-Dugdale's law, so the solver must give Maugis-Dugdale."""

    def __init__(self, z0, sigma0, h):
        self.z0, self.sigma0, self.cutoff = z0, sigma0, z0 + h
        self.stiffness = sigma0 / (1e-3 * z0)
        self.width = 0.05 * h

    def _parts(self, g):
        g = np.asarray(g, float)
        linear = self.stiffness * (self.z0 - g)
        t = np.tanh((g - self.cutoff) / self.width)
        return np.maximum(linear, -self.sigma0), np.where(linear > -self.sigma0, -self.stiffness, 0.0), t

    def __call__(self, g):
        law, _, t = self._parts(g)
        return law * 0.5 * (1.0 - t)

    def slope(self, g):
        law, slope, t = self._parts(g)
        return slope * 0.5 * (1.0 - t) - law * 0.5 * (1.0 - t * t) / self.width


@pytest.mark.parametrize("E_star, tolerance", [(37.6e3, 0.005), (112.8e3, 0.025)])
def test_dugdale_law_gives_maugis_dugdale(E_star, tolerance):
    """With Dugdale's law the solution is Maugis-Dugdale's: the compressive zone and the
    approach within 0.5 % at lambda 0.37 and within 2.5 % at lambda 0.18, where the
    smoothing of the law's end weighs more (measured: +0.24 % and +1.7 %)."""
    w, sigma0, z0 = 6.4e-4, 1.84e3, 0.483e-6
    solver = dc.AdheredSphereSolver(R, E_star, SmoothedDugdale(z0, sigma0, w / sigma0), z0)
    state = solver.at_load(0.0)
    md = ct.maugis_dugdale(R, w, sigma0, E_star)
    assert abs(state.P) < 1e-9 * math.pi * w * R
    assert state.compressive_radius == pytest.approx(ct.md_zero_pressure_radius(md, R, sigma0, E_star), rel=tolerance)
    assert state.delta == pytest.approx(md.delta, rel=tolerance)


@pytest.fixture(scope="module")
def law_state():
    return dc.adhered_sphere(R, 37.6e3, EPS, S0, BETA)


def test_rings_converged(law_state):
    """Twice the rings move the compressive zone's edge by less than 1e-3."""
    finer = dc.adhered_sphere(R, 37.6e3, EPS, S0, BETA, rings=800)
    assert finer.compressive_radius == pytest.approx(law_state.compressive_radius, rel=1e-3)


def test_contact_law_at_rest(law_state):
    """At zero load the pressure integrates to zero, presses inside the edge and pulls
    outside it, the gap is the law's zero at the edge, and the edge lies above
    Maugis-Dugdale's (measured +8 % at lambda 0.37: the law spreads its tension over gaps
    up to its cutoff, Dugdale's law puts it all within h = w / sigma0 of z0) and below
    JKR's contact radius."""
    law = ct.contact_term_law(EPS, S0, BETA)
    areas = math.pi * np.diff(np.linspace(0.0, law_state.r[-1] + 0.5 * (law_state.r[1] - law_state.r[0]),
                                          len(law_state.r) + 1) ** 2)
    assert abs(areas @ law_state.pressure) < 1e-6 * np.max(law_state.pressure) * areas.sum()
    edge = law_state.compressive_radius
    assert np.all(law_state.pressure[law_state.r < 0.95 * edge] > 0.0)
    assert law_state.pressure[np.searchsorted(law_state.r, 1.05 * edge)] < 0.0
    assert np.interp(edge, law_state.r, law_state.gap) == pytest.approx(law.z0, rel=1e-3)
    md = ct.maugis_dugdale(R, law.w, law.sigma0, 37.6e3)
    assert ct.md_zero_pressure_radius(md, R, law.sigma0, 37.6e3) < edge < ct.jkr_zero_load_radius(R, law.w, 37.6e3)


def test_sphere_profile_narrows_the_zone(law_state):
    """The sphere's own profile opens the gap faster than the paraboloid (by r^4 / (8 R^3)),
    so the zone is smaller: by a few per cent at a / R = 0.3."""
    sphere = dc.adhered_sphere(R, 37.6e3, EPS, S0, BETA, profile="sphere")
    assert 0.9 * law_state.compressive_radius < sphere.compressive_radius < 0.99 * law_state.compressive_radius
