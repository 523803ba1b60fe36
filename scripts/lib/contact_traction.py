"""The contact traction of an adhered body from its particles' contact forces, and the
edge of its compressive zone, for comparing a run at rest with the closed forms of
scripts/lib/contact_theory.py (docs/theory/contact.md).

rkpm's frames show each particle's contact force as `contact_force_<other body>`
(docs/guide/outputs.md). The pair forces act through a layer about s0 deep, so no
single particle's stress is the traction; the force within a cylinder about the
contact's axis is: F(r) = sum over the particles at lateral distance r_i <= r of the
normal component of their contact force. It grows while the contact presses and falls
where it pulls, so the edge of the compressive zone, the zero of the traction
p(r) = F'(r) / (2 pi r), is where F peaks. A run's particles come in rings or in a
lattice, so F is a staircase; its peak is placed between the particles by a parabola
through F at the distinct radii around the largest value (least squares over a window
of `window` on each side)."""
import numpy as np


def cumulative_normal_force(positions, forces, centre, normal=(0.0, 0.0, 1.0)):
    """Distinct lateral distances r (ascending) from the axis through `centre` along
    `normal`, and the normal force F(r) [N] of the particles within each (> 0: pushing
    along the normal)."""
    n = np.asarray(normal, float)
    n = n / np.linalg.norm(n)
    d = np.asarray(positions, float) - np.asarray(centre, float)
    lateral = d - np.outer(d @ n, n)
    r = np.linalg.norm(lateral, axis=1)
    fn = np.asarray(forces, float) @ n
    order = np.argsort(r, kind="stable")
    r, fn = r[order], fn[order]
    # Particles at the same distance (a ring) enter together.
    digits = 12 - int(np.floor(np.log10(max(r.max(), 1e-300))))  # 12 significant digits of the largest
    _, first = np.unique(np.round(r, digits), return_index=True)
    totals = np.cumsum(fn)
    last = np.r_[first[1:], len(r)] - 1
    return r[last], totals[last]


def compressive_zone_radius(positions, forces, centre, normal=(0.0, 0.0, 1.0), window=None, smoothing=None):
    """The radius [m] where the contact traction changes from pushing to pulling: the
    peak of `cumulative_normal_force`, refined by a least-squares parabola over the radii
    within `window` of the largest value (default: the gap between the radii on either
    side of it, so that at least three take part). Returns (radius, F at the peak [N]).

    `smoothing` [m], for a run's particles: near its peak F is flat, and a lattice cut by
    a curved surface makes its steps uneven (a tenth of F from one radius to the next on
    the adhered sphere), so the largest single value can sit a spacing or more from the
    smooth curve's peak. With `smoothing`, the parabola is fitted over the radii within
    that half-width of its own vertex, moved until the vertex stays (a local quadratic
    fit; a few particle spacings is the intended scale)."""
    r, F = cumulative_normal_force(positions, forces, centre, normal)
    k = int(np.argmax(F))
    if k == 0 or k == len(r) - 1 or F[k + 1:].min() >= F[k] * (1.0 - 1e-9):
        raise ValueError("the normal force within r does not fall after its peak: no pulling zone, no edge inside")
    if smoothing is not None:
        return _local_quadratic_peak(r, F, r[k], smoothing)
    if window is None:
        window = max(r[k] - r[k - 1], r[k + 1] - r[k])
    near = np.abs(r - r[k]) <= window * (1.0 + 1e-9)
    c2, c1, c0 = np.polyfit(r[near] - r[k], F[near], 2)
    if c2 >= 0.0:
        return float(r[k]), float(F[k])
    shift = float(np.clip(-c1 / (2.0 * c2), -window, window))
    return float(r[k] + shift), float(c0 - c1 * c1 / (4.0 * c2))


def _local_quadratic_peak(r, F, start, half_width, max_moves=50):
    """The vertex of the least-squares parabola through (r, F) within `half_width` of the
    vertex itself, found by moving the window from `start`, and the parabola's value there."""
    centre = start
    for _ in range(max_moves):
        near = np.abs(r - centre) <= half_width
        if near.sum() < 3:
            raise ValueError(f"fewer than three radii within {half_width} m of {centre} m: widen the smoothing")
        c2, c1, c0 = np.polyfit(r[near] - centre, F[near], 2)
        if c2 >= 0.0:
            raise ValueError("the normal force within r has no peak at this smoothing")
        shift = float(np.clip(-c1 / (2.0 * c2), -half_width, half_width))
        centre += shift
        if abs(shift) <= 1e-9 * half_width:
            break
    return float(centre), float(c0 - c1 * c1 / (4.0 * c2))
