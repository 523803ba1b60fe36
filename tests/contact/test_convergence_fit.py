"""Tests of the Richardson estimate the contact studies report (scripts/lib/
convergence_fit.py): a quantity built as q_inf + C h^p at uneven spacings gives back
q_inf and p; the grid convergence index bounds the finest value's true error and is
Roache's formula; values that oscillate or do not converge are flagged, not fitted."""
import math
import os
import sys

import pytest

sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "lib"))
from convergence_fit import SAFETY_FACTOR, richardson  # noqa: E402

# The adhesion study's sphere spacings (10 um / cells for 32, 22, 16, 12 cells).
H = [10e-6 / n for n in (32, 22, 16, 12)]


@pytest.mark.parametrize("p", [0.7, 1.0, 2.0, 3.5])
@pytest.mark.parametrize("c", [0.05, -0.02])
def test_recovers_limit_and_order(p, c):
    q_inf = 1.43e-6
    q = [q_inf * (1.0 + c * (h / H[0]) ** p) for h in H]
    est = richardson(H, q)
    assert est.monotone
    assert est.order == pytest.approx(p, rel=1e-7)
    assert est.q_inf == pytest.approx(q_inf, rel=1e-10)


def test_uses_the_three_finest_in_any_order():
    q = {h: 2.0 + 0.3 * h / H[0] for h in H}
    q[H[3]] = 99.0  # the coarsest value, far off, must not enter
    shuffled = [H[2], H[3], H[0], H[1]]
    est = richardson(shuffled, [q[h] for h in shuffled])
    assert est.order == pytest.approx(1.0, rel=1e-8)
    assert est.q_inf == pytest.approx(2.0, rel=1e-12)


def test_gci_is_roache_and_bounds_the_error():
    q = [5.0 + 7.0 * h / H[0] * (1 + 0.1 * h / H[0]) for h in H]  # first order with a second-order part
    est = richardson(H, q)
    r = H[1] / H[0]
    assert est.gci == pytest.approx(SAFETY_FACTOR * abs(q[1] - q[0]) / (r ** est.order - 1.0), rel=1e-12)
    true_error = abs(q[0] - 5.0)
    assert est.gci > true_error
    assert est.gci < 3.0 * true_error


def test_oscillating_values_are_flagged():
    est = richardson(H[:3], [1.0, 1.2, 0.9])
    assert not est.monotone
    assert math.isnan(est.q_inf) and math.isnan(est.order)
    assert est.gci == pytest.approx(SAFETY_FACTOR * 0.3)


def test_refuses_too_few_or_repeated_spacings():
    with pytest.raises(ValueError, match="three"):
        richardson(H[:2], [1.0, 2.0])
    with pytest.raises(ValueError, match="distinct"):
        richardson([1.0, 1.0, 2.0], [1.0, 2.0, 3.0])
