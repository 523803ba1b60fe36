"""Tests of the traction measure of an adhered body (scripts/lib/contact_traction.py):
forces sampled from a known pressure on a square lattice of spacing h, as a run's
particles carry them, give back the pressure's zero radius to a small fraction of h,
better as h falls; the cumulative force is the lattice sum; a force field that never
pulls is refused."""
import math
import os
import sys

import numpy as np
import pytest

sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "lib"))
import contact_theory as ct  # noqa: E402
import contact_traction as tr  # noqa: E402

# A Maugis-Dugdale contact like the adhered sphere's check: R = 5 um, E* = 37.6 kPa,
# the adhesion scene's law (lambda 0.37).
R, E_STAR = 5e-6, 3.7556e4
LAW = ct.contact_term_law(3.265e-15, 0.75e-6, [1e18, 1e18])
CONTACT = ct.maugis_dugdale(R, LAW.w, LAW.sigma0, E_STAR)
EDGE = ct.md_zero_pressure_radius(CONTACT, R, LAW.sigma0, E_STAR)


def lattice_forces(h, offset=(0.0, 0.0)):
    """Particles on a square lattice of spacing h in the plane z = 0 (shifted by
    `offset`), each with the force p(r) h^2 along +z of the Maugis-Dugdale pressure."""
    n = int(math.ceil(1.5 * CONTACT.c / h))
    g = (np.arange(-n, n + 1) * h)
    x, y = np.meshgrid(g + offset[0], g + offset[1])
    points = np.c_[x.ravel(), y.ravel(), np.zeros(x.size)]
    p = ct.md_pressure(np.hypot(points[:, 0], points[:, 1]), CONTACT, R, LAW.sigma0, E_STAR)
    forces = np.c_[np.zeros(x.size), np.zeros(x.size), p * h * h]
    return points, forces


def test_the_cumulative_force_is_the_lattice_sum():
    points, forces = lattice_forces(0.2e-6)
    r, F = tr.cumulative_normal_force(points, forces, centre=(0.0, 0.0, 0.0))
    assert np.all(np.diff(r) > 0)
    inside = np.hypot(points[:, 0], points[:, 1]) <= r[10] * (1 + 1e-12)
    assert F[10] == pytest.approx(forces[inside, 2].sum(), rel=1e-12)
    assert F[-1] == pytest.approx(forces[:, 2].sum(), rel=1e-12)


@pytest.mark.parametrize("offset", [(0.0, 0.0), (0.37, 0.11)])
def test_the_compressive_zone_radius_comes_back_from_lattice_forces(offset):
    errors = []
    for h in (0.3e-6, 0.15e-6, 0.075e-6):
        points, forces = lattice_forces(h, (offset[0] * h, offset[1] * h))
        radius, peak = tr.compressive_zone_radius(points, forces, centre=(0.0, 0.0, 0.0))
        assert peak > 0.0
        errors.append(abs(radius - EDGE))
        assert errors[-1] < 0.25 * h, (h, radius, EDGE)
    assert errors[-1] < errors[0]
    # Against the radius of the nearest ring alone: the parabola is the better estimate
    # at the finest lattice (the staircase's own error is up to half a ring gap).
    assert errors[-1] < 0.01 * EDGE


def test_smoothing_finds_the_edge_through_uneven_steps():
    # Each particle's force off by up to +-30 % (seeded), as a lattice cut by a curved
    # surface makes the steps of F uneven: the largest single F can sit off the edge,
    # the local quadratic fit over three spacings stays within a fifth of a spacing.
    h = 0.15e-6
    points, forces = lattice_forces(h, (0.37 * h, 0.11 * h))
    rng = np.random.default_rng(7)
    noisy = forces * (1.0 + 0.3 * rng.uniform(-1.0, 1.0, size=(len(forces), 1)))
    smoothed, peak = tr.compressive_zone_radius(points, noisy, centre=(0.0, 0.0, 0.0), smoothing=3 * h)
    assert peak > 0.0
    assert abs(smoothed - EDGE) < 0.2 * h, (smoothed, EDGE)
    clean, _ = tr.compressive_zone_radius(points, forces, centre=(0.0, 0.0, 0.0), smoothing=3 * h)
    assert abs(clean - EDGE) < 0.1 * h, (clean, EDGE)


def test_a_force_that_never_pulls_has_no_edge_inside():
    points, forces = lattice_forces(0.2e-6)
    with pytest.raises(ValueError):
        tr.compressive_zone_radius(points, np.abs(forces), centre=(0.0, 0.0, 0.0))
