"""Tests of the layered bodies' adhesion energy (scripts/lib/layered_contact.py): the
plane's closed form against quadrature, the continuum's adhesion energy against the
contact term's documented law, the layers' limit, and a case summed by hand. Under a
second on one core."""
import math
import os
import sys

import numpy as np
import pytest

sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "lib"))
import contact_theory as ct  # noqa: E402
import layered_contact as lc  # noqa: E402

# The crawling scene's contact term (examples/crawling/crawling.toml), cutoff 3 s0.
EPS, S0, BETA = 3.265e-15, 0.75e-6, 1e18
RC = 3.0 * S0


@pytest.mark.parametrize("D", [0.3e-6, 0.48e-6, 1e-6, 2e-6])
def test_plane_energy_closed_form_matches_quadrature(D):
    phi = ct.lennard_jones(EPS, S0)
    shift = phi(RC)
    by_quadrature = 2.0 * math.pi * ct._quad(lambda r: (phi(r) - shift) * r, D, RC)
    assert lc.plane_energy(D, EPS, S0, RC) == pytest.approx(by_quadrature, rel=1e-10)


def test_plane_energy_vanishes_beyond_the_cutoff():
    assert lc.plane_energy(np.array([RC, 1.5 * RC]), EPS, S0, RC) == pytest.approx([0.0, 0.0], abs=1e-40)


def test_continuum_is_the_contact_terms_law():
    """docs/theory/contact.md: with the 3 s0 cutoff the zero-traction gap is 0.6434 s0 and
    the adhesion energy 0.6199 beta^2 eps s0^4."""
    gap, w = lc.continuum_adhesion_energy(EPS, S0, BETA, RC)
    assert gap / S0 == pytest.approx(0.6434, abs=1e-4)
    assert w / (BETA * BETA * EPS * S0 ** 4) == pytest.approx(0.6199, abs=1e-4)


def test_thin_layers_reach_the_continuum():
    """Halving the layers' spacing from 0.05 to 0.025 um cuts the adhesion energy's error
    by more than three, to within 2 %."""
    coarse = abs(lc.adhesion_ratio(0.05e-6, 0.05e-6, EPS, S0, BETA, RC) - 1.0)
    fine = abs(lc.adhesion_ratio(0.025e-6, 0.025e-6, EPS, S0, BETA, RC) - 1.0)
    assert fine < 0.02
    assert coarse > 3.0 * fine


def test_layers_deeper_than_the_cutoff_leave_the_surface_layers_alone():
    """With layers 3 um apart only the two surface layers, each carrying half a layer's
    molecules, lie within the 2.25 um cutoff."""
    c1, c2, gap = 3e-6, 4e-6, 0.6e-6
    alone = (BETA * c1 / 2) * (BETA * c2 / 2) * lc.plane_energy(gap, EPS, S0, RC)
    assert lc.layered_energy(gap, c1, c2, EPS, S0, BETA, RC) == pytest.approx(alone, rel=1e-12)


def test_two_layers_summed_by_hand():
    """Layers 1.5 um apart, gap 0.5 um: the surface pair and the two pairs with one second
    layer (2.0 um) are within the cutoff, the second layers' pair (3.5 um) is not."""
    c, gap = 1.5e-6, 0.5e-6
    half, full = BETA * c / 2, BETA * c
    by_hand = half * half * lc.plane_energy(gap, EPS, S0, RC) + 2 * half * full * lc.plane_energy(gap + c, EPS, S0, RC)
    assert lc.layered_energy(gap, c, c, EPS, S0, BETA, RC) == pytest.approx(by_hand, rel=1e-12)


def test_layered_traction_is_minus_the_energys_derivative():
    """sigma = -dW/dD and its slope against central differences, on the crawling
    ladder's coarsest layers (cell 10/17 um, block 1.125 um)."""
    law = lc.LayeredTraction(10e-6 / 17, 1.125e-6, EPS, S0, BETA, RC)
    h = 1e-11
    for D in (0.45e-6, 0.6e-6, 1.0e-6, 1.9e-6):
        dW = (lc.layered_energy(D + h, 10e-6 / 17, 1.125e-6, EPS, S0, BETA, RC)
              - lc.layered_energy(D - h, 10e-6 / 17, 1.125e-6, EPS, S0, BETA, RC)) / (2 * h)
        assert float(law(np.array([D]))[0]) == pytest.approx(-dW, rel=1e-6)
        ds = (law(np.array([D + h]))[0] - law(np.array([D - h]))[0]) / (2 * h)
        assert float(law.slope(np.array([D]))[0]) == pytest.approx(ds, rel=1e-5)


def test_thin_layers_traction_is_the_half_spaces():
    """Halving the layers' spacing from 0.05 to 0.025 um cuts the traction's largest
    departure from the continuum's (contact_theory) by more than three, to within 2.5 %
    of its peak tension; the zero lies within 1 % of the continuum's 0.6434 s0."""
    phi = ct.lennard_jones(EPS, S0)
    gaps = np.linspace(0.55e-6, 2.0e-6, 12)
    continuum = np.array([ct.half_space_traction(D, phi, RC, BETA, BETA) for D in gaps])

    def departure(spacing):
        law = lc.LayeredTraction(spacing, spacing, EPS, S0, BETA, RC)
        return np.max(np.abs(law(gaps) - continuum)) / abs(continuum.min()), law.z0

    coarse, _ = departure(0.05e-6)
    fine, z0 = departure(0.025e-6)
    assert fine < 0.025
    assert coarse > 3.0 * fine
    assert z0 / (0.6434 * S0) == pytest.approx(1.0, abs=0.01)


def test_energy_at_a_fixed_gap_converges_at_second_order():
    """At the continuum's rest gap the layers' energy per area approaches the half-spaces'
    as the square of the spacing (a trapezoid rule over depth: the surface layer's half
    weight; a full weight there would make it first order): halving 0.05 um cuts the
    error by more than three, to within 1.5 %."""
    phi = ct.lennard_jones(EPS, S0)
    D = 0.6434 * S0
    continuum = ct.half_space_energy(D, phi, RC, BETA, BETA)
    errors = [abs(lc.layered_energy(D, c, c, EPS, S0, BETA, RC) / continuum - 1.0) for c in (0.05e-6, 0.025e-6)]
    assert errors[1] < 0.015
    assert errors[0] > 3.0 * errors[1]


def test_a_gap_below_the_laws_range_is_refused():
    law = lc.LayeredTraction(0.2e-6, 0.2e-6, EPS, S0, BETA, RC)
    with pytest.raises(FloatingPointError):
        law(np.array([0.5 * law.low, S0]))
