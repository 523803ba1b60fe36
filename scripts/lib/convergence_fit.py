"""Richardson extrapolation of a quantity computed at several resolutions, with Roache's
grid convergence index as its error bar (Roache, Verification and Validation in
Computational Science and Engineering (1998); ASME V&V 20).

A quantity q(h) at spacings h1 < h2 < h3 (finest first) that converges as
q(h) = q_inf + C h^p gives, from the three, the observed order p (the root of
(q2 - q1) / (q3 - q2) = (h2^p - h1^p) / (h3^p - h2^p), which needs no constant
refinement ratio), the limit q_inf, and the finest run's estimated error
GCI = Fs |q2 - q1| / (r^p - 1) with r = h2 / h1 and the safety factor Fs = 1.25 of a
three-resolution study."""
import math
from dataclasses import dataclass

from scipy import optimize

SAFETY_FACTOR = 1.25
ORDER_RANGE = (0.05, 12.0)


@dataclass(frozen=True)
class Richardson:
    """q_inf: the extrapolated limit; order: the observed p; gci: the finest value's
    estimated error (absolute, in q's unit); monotone: whether the three values
    approach the limit from one side (otherwise order and q_inf are not defined and
    are nan, and gci is the spread of the three)."""
    q_inf: float
    order: float
    gci: float
    monotone: bool


def richardson(h, q):
    """The Richardson estimate from the three finest of the pairs (h, q) (any order)."""
    if len(h) != len(q) or len(h) < 3:
        raise ValueError("need at least three resolutions, each with its value")
    (h1, q1), (h2, q2), (h3, q3) = sorted(zip(h, q))[:3]
    if not 0.0 < h1 < h2 < h3:
        raise ValueError(f"spacings must be positive and distinct, got {h1}, {h2}, {h3}")
    d21, d32 = q2 - q1, q3 - q2
    if d21 == 0.0 or d32 == 0.0 or (d21 > 0.0) != (d32 > 0.0):
        spread = max(q1, q2, q3) - min(q1, q2, q3)
        return Richardson(q_inf=math.nan, order=math.nan, gci=SAFETY_FACTOR * spread, monotone=False)
    ratio = d21 / d32

    def mismatch(p):
        return (h2 ** p - h1 ** p) / (h3 ** p - h2 ** p) - ratio

    lo, hi = ORDER_RANGE
    if mismatch(lo) * mismatch(hi) > 0.0:
        # The ratio is outside what any order in the range gives: no asymptotic convergence.
        spread = max(q1, q2, q3) - min(q1, q2, q3)
        return Richardson(q_inf=math.nan, order=math.nan, gci=SAFETY_FACTOR * spread, monotone=False)
    p = optimize.brentq(mismatch, lo, hi, xtol=1e-12)
    C = d21 / (h2 ** p - h1 ** p)
    q_inf = q1 - C * h1 ** p
    r = h2 / h1
    return Richardson(q_inf=q_inf, order=p, gci=SAFETY_FACTOR * abs(d21) / (r ** p - 1.0), monotone=True)
