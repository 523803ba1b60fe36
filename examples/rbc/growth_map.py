#!/usr/bin/env python3
"""In-plane growth that maps the seed's oblate shell onto the Evans-Fung disc.

Both surfaces are axisymmetric. An isotropic in-plane growth g (what an active stress
along a wall-normal director produces, seed Eq. 1) maps one surface onto the other
without stretching exactly when the map is conformal, i.e. when it preserves the
isothermal coordinate u = integral ds / r along the meridian (s arc length, r distance
from the axis), measured from the equator. The growth is then g = r_target(u) / r_start(u).
Printed: g against the relative distance rho = r / R of the starting shell, for the
Evans-Fung disc scaled to the same area as the start (and to the same diameter).
Usage: python3 examples/rbc/growth_map.py   (standard library only)
"""
import math

N = 20000


def oblate(a, c):
    """Meridian of the spheroid with semi-axes a, a, c from the equator to the pole."""
    return [(a * math.cos(t), c * math.sin(t)) for t in (0.5 * math.pi * k / N for k in range(N + 1))]


def evans_fung(radius):
    """Upper outer surface z = T(r)/2 of the Evans-Fung profile scaled to `radius`."""
    scale = radius / 3.91
    pts = []
    for k in range(N + 1):
        x = math.cos(0.5 * math.pi * k / N)  # r / R0 from 1 (equator) to 0 (pole)
        pts.append((radius * x, 0.5 * scale * math.sqrt(max(0.0, 1 - x * x)) * (0.81 + 7.83 * x * x - 4.39 * x ** 4)))
    return pts


def isothermal(pts):
    u, out = 0.0, [0.0]
    for (r0, z0), (r1, z1) in zip(pts, pts[1:]):
        u += math.hypot(r1 - r0, z1 - z0) / max(0.5 * (r0 + r1), 1e-30)
        out.append(u)
    return out


def area(pts):
    return 2 * sum(2 * math.pi * 0.5 * (r0 + r1) * math.hypot(r1 - r0, z1 - z0)
                   for (r0, z0), (r1, z1) in zip(pts, pts[1:]))


def growth(start, target):
    us, ut = isothermal(start), isothermal(target)
    rows, j = [], 0
    for rho in (1.0, 0.98, 0.95, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4, 0.3, 0.2, 0.1):
        i = min(range(len(start)), key=lambda k: abs(start[k][0] / start[0][0] - rho))
        while j < len(ut) - 1 and ut[j] < us[i]:
            j += 1
        rows.append((rho, target[j][0] / start[i][0]))
    return rows


start = oblate(5.0, 1.5)
a0 = area(start)
for label, radius in (("same area", 3.91 * math.sqrt(a0 / area(evans_fung(3.91)))), ("same diameter", 5.0)):
    print(f"Evans-Fung at {label} (D = {2 * radius:.2f} um):")
    print("  rho = r/R   g")
    for rho, g in growth(start, evans_fung(radius)):
        print(f"  {rho:8.2f}  {g:6.3f}")
