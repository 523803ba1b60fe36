#!/usr/bin/env python3
"""In-plane growth that maps the seed's oblate shell onto the Evans-Fung disc.

Both surfaces are axisymmetric. An isotropic in-plane growth g (what an active stress
along a wall-normal director produces, seed Eq. 1) maps one surface onto the other
without stretching exactly when the map is conformal, i.e. when it preserves the
isothermal coordinate u = integral ds / r along the meridian (s arc length, r distance
from the axis), measured from the equator. The growth is then g = r_target(u) / r_start(u).
Printed: g against the relative distance rho = r / R of the starting shell, for the
Evans-Fung disc scaled to the same area as the start (and to the same diameter).
With wall thicknesses T [um] as arguments it also prints the map between the mid-surfaces
of a wall of thickness T: the spheroid with semi-axes reduced by T / 2, and Evans-Fung
offset inward along its normal by T / 2, scaled so the two mid-surfaces have the same
area (docs/verification/rbc.md, "What the 0.75 um wall lacks").
Usage: python3 examples/rbc/growth_map.py [T_um ...]   (standard library only)
"""
import math
import sys

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


def offset_inward(pts, d):
    """The meridian moved by d along its inward normal (the curve runs from the equator
    to the pole, so the outward normal of the closed surface is (dz, -dr) / |ds|)."""
    out = []
    for k, (r, z) in enumerate(pts):
        (r0, z0), (r1, z1) = pts[max(k - 1, 0)], pts[min(k + 1, len(pts) - 1)]
        length = math.hypot(r1 - r0, z1 - z0)
        out.append((r - d * (z1 - z0) / length, z + d * (r1 - r0) / length))
    return out


def equal_area_radius(make, target_area):
    """Bisection for the radius at which make(radius) has the given area."""
    lo, hi = 1.0, 10.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if area(make(mid)) < target_area else (lo, mid)
    return 0.5 * (lo + hi)


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

for thickness in (float(t) for t in sys.argv[1:]):
    start = oblate(5.0 - thickness / 2, 1.5 - thickness / 2)
    make = lambda radius: offset_inward(evans_fung(radius), thickness / 2)
    radius = equal_area_radius(make, area(start))
    print(f"Mid-surfaces of a {thickness} um wall (Evans-Fung outer D = {2 * radius:.2f} um):")
    print("  rho = r/R   g")
    for rho, g in growth(start, make(radius)):
        print(f"  {rho:8.2f}  {g:6.3f}")
