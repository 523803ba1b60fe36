"""The adhesion energy the contact term's pair sum gives two flat bodies made of particle
layers, against the continuum's (docs/verification/crawling.md, "What sets the velocity").

The contact term sums the pair law over particles that carry their dual cells' molecules
at their own positions (docs/theory/contact.md). Two flat bodies of layer spacings c1
and c2 are then stacks of planes: interior layers carry beta c molecules per area, the
surface layer beta c / 2 (its dual cell is half a cell deep), all at the surface. Each
layer is taken as a continuous plane: a molecule at distance D from a plane of unit
areal density has the energy 2 pi int_D^rc (phi(r) - phi(rc)) r dr. This is the depth
part of the discretisation alone. Along the surface a lattice's sum differs from the
plane's by terms that are exponentially small only where the lateral spacing is small
against the gap; at lateral spacings near s0 a molecule over a site and one over a
hollow see very different sums, and what is left of that after averaging over a curved
body's mismatched lattice is not modelled here. The pair sum across the surface is a
trapezoid rule of the continuum's integral over depth; with layers as deep as s0 it
misses the continuum's adhesion energy by tens of per cent, and not monotonically."""
import math

import numpy as np
from scipy import optimize

from contact_theory import half_space_energy, lennard_jones


def plane_energy(D, epsilon, s0, cutoff):
    """The energy [J m^2] of one molecule at distances D [m] (an array) from a plane of
    unit areal density: 2 pi int_D^rc (phi(r) - phi(rc)) r dr with the contact term's
    phi(r) = eps [(s0/r)^12 - 2 (s0/r)^6] truncated and shifted at rc = `cutoff`, in
    closed form (zero from rc on)."""
    D = np.minimum(np.asarray(D, dtype=float), cutoff)
    at_cutoff = lennard_jones(epsilon, s0)(cutoff)
    return (2.0 * math.pi * epsilon * (s0 ** 12 * (D ** -10 - cutoff ** -10) / 10.0
                                       - s0 ** 6 * (D ** -4 - cutoff ** -4) / 2.0)
            - math.pi * at_cutoff * (cutoff ** 2 - D ** 2))


def cloud_layer_spacings(sphere_cloud, block_cloud):
    """The layer spacings [m] the pair sum sees between a `sphere` cloud on a `block`
    cloud's top face: the sphere's 2 R / cells at its pole, the block's along z."""
    return (2.0 * sphere_cloud["radius"] / sphere_cloud["cells"], block_cloud["size"][2] / block_cloud["cells"][2])


def layers(spacing, beta, depth):
    """Depths [m] below the surface and areal densities [1/m^2] of a body's particle
    layers down to `depth`: the surface layer carries half a layer's molecules."""
    n = int(depth / spacing) + 2
    weights = np.full(n, beta * spacing)
    weights[0] *= 0.5
    return np.arange(n) * spacing, weights


def layered_energy(gap, spacing1, spacing2, epsilon, s0, beta, cutoff):
    """The pair sum's energy per area [J/m^2] of two layered bodies whose surface
    layers are `gap` [m] apart (both bodies' molecule density `beta`)."""
    z1, w1 = layers(spacing1, beta, cutoff)
    z2, w2 = layers(spacing2, beta, cutoff)
    return float(np.sum(np.outer(w1, w2) * plane_energy(gap + z1[:, None] + z2[None, :], epsilon, s0, cutoff)))


def _deepest(energy, lo, hi, n=91):
    """The minimum of energy(d) over [lo, hi]: a grid, then Brent's method around the
    grid's lowest point. Returns (d, energy(d))."""
    grid = np.linspace(lo, hi, n)
    values = [energy(d) for d in grid]
    k = min(max(int(np.argmin(values)), 1), n - 2)
    result = optimize.minimize_scalar(energy, bracket=(grid[k - 1], grid[k], grid[k + 1]))
    return float(result.x), float(result.fun)


def adhesion_energy(spacing1, spacing2, epsilon, s0, beta, cutoff):
    """(gap at rest [m], adhesion energy [J/m^2]) of two layered bodies: the depth of
    the energy per area's minimum over the surface layers' gap."""
    gap, energy = _deepest(lambda d: layered_energy(d, spacing1, spacing2, epsilon, s0, beta, cutoff),
                           0.3 * s0, 1.6 * s0)
    return gap, -energy


def continuum_adhesion_energy(epsilon, s0, beta, cutoff):
    """(gap at rest [m], adhesion energy [J/m^2]) of two continuous half-spaces under the
    same law (contact_theory.half_space_energy)."""
    phi = lennard_jones(epsilon, s0)
    gap, energy = _deepest(lambda d: half_space_energy(d, phi, cutoff, beta, beta), 0.3 * s0, 1.6 * s0)
    return gap, -energy


def adhesion_ratio(spacing1, spacing2, epsilon, s0, beta, cutoff):
    """The layered bodies' adhesion energy over the continuum's."""
    return (adhesion_energy(spacing1, spacing2, epsilon, s0, beta, cutoff)[1]
            / continuum_adhesion_energy(epsilon, s0, beta, cutoff)[1])


class LayeredTraction:
    """The traction sigma(D) [Pa] (> 0 repulsive) between two layered bodies whose
    surface layers are D apart, and its slope: minus the derivative of `layered_energy`,
    in closed form (d/dD of 2 pi int_D^rc (phi - phi(rc)) r dr is -2 pi (phi(D) - phi(rc)) D).
    The interface of derjaguin_contact.TractionLaw, so that the adhered sphere can be
    solved with the law the runs' particle layers carry; z0 is its zero."""

    def __init__(self, spacing1, spacing2, epsilon, s0, beta, cutoff):
        self.epsilon, self.s0, self.cutoff = epsilon, s0, cutoff
        z1, w1 = layers(spacing1, beta, cutoff)
        z2, w2 = layers(spacing2, beta, cutoff)
        self._depths = (z1[:, None] + z2[None, :]).ravel()
        self._weights = np.outer(w1, w2).ravel()
        self._phi = lennard_jones(epsilon, s0)
        self._at_cutoff = self._phi(cutoff)
        self.low = 0.0  # the range below is set from z0, which the bracket from 0.3 s0 finds
        self.z0 = optimize.brentq(lambda d: float(self(np.array([d]))[0]), 0.3 * s0, 1.2 * s0, xtol=1e-15)
        self.low = 0.3 * self.z0

    def _pairs(self, D):
        D = np.asarray(D, dtype=float)
        if np.min(D) < self.low:
            # As derjaguin_contact.TractionLaw: Newton's line search takes this as a step too far.
            raise FloatingPointError(f"a gap of {np.min(D):.4g} m, below the law's range (from {self.low:.4g} m)")
        r = D[..., None] + self._depths
        return r, r < self.cutoff

    def __call__(self, D):
        r, inside = self._pairs(D)
        return 2.0 * math.pi * np.sum(np.where(inside, self._weights * (self._phi(r) - self._at_cutoff) * r, 0.0),
                                      axis=-1)

    def slope(self, D):
        r, inside = self._pairs(D)
        u6 = (self.s0 / r) ** 6
        r_dphi = self.epsilon * (-12.0 * u6 * u6 + 12.0 * u6)  # r phi'(r)
        return 2.0 * math.pi * np.sum(np.where(inside, self._weights * (r_dphi + self._phi(r) - self._at_cutoff), 0.0),
                                      axis=-1)
