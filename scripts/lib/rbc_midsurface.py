"""The mid-surface of the red-blood-cell shell (examples/rbc/rbc.toml) in a run's last
frame, as an axisymmetric meridian, for the comparison with Helfrich's model and
Evans-Fung (scripts/studies/rbc-helfrich.sh, docs/verification/rbc.md).

Why from the frame and not from shape_profile.csv: rkpm's shape report
(src/sim/run/shape_report.cpp) measures the shell's *outer* surface, the cell's contour.
A membrane model such as Helfrich's describes a surface without thickness, whose
counterpart in a thick wall is its mid-surface; with the default 0.5 um wall in a cell
about 9 um across, the outer surface's reduced volume and dimple are not the
mid-surface's.

Which mid-surface. The shell generator ("shell", particles/src/make_shell.cpp) places
`layers` particle layers on nested spheroids and joins them by hexahedra whose bottom
face (nodes 0-3) lies on one layer and top face (nodes 4-7) on the next one out, node
a + 4 above node a. Following those edges from the inner surface outward gives the
*columns*: one particle per layer, at the same place of every layer's meridian. Two
surfaces are built from them:
  "mid"       the material mid-surface: the surface halfway through the reference wall,
              carried by the deformation (for an odd layer count the middle layer
              itself, for an even one the mean of the two middle layers' particles);
  "midpoint"  the point halfway between a column's inner and outer particles in the
              current state: the geometric middle of the deformed wall, which differs
              from the material one where the wall has thickened unevenly.
and "outer" and "inner" are the wall's surfaces.

The meridian. Every particle of a surface is a sample of the same generating curve
(as far as the shape is axisymmetric: the shape report's axial asymmetry measures it),
so the curve is taken as the mean current (r, z) of the particles in bins of their
column's reference parametric angle psi (r = a sin psi, z = c cos psi on the outer
reference spheroid, psi = 0 at the top pole), averaged over the azimuth.
The bins are centred on psi = k pi / (2 n) for k = 0..2n: one bin on each pole, one on
the equator. A pole bin's point is replaced by (0, z0) from the fit z = z0 + z2 r^2 to
its particles (z is even in r on a smooth surface), so the curve starts and ends on the
axis as `helfrich.profile_measures` needs. The frame's centre is the outer surface's
centroid, its axis the z axis, as in the shape report. Standard library and numpy
only; the frame format is rkpm's .vtu (appended raw data, zlib, UInt64 headers)."""
import re
import tomllib
import xml.etree.ElementTree as ElementTree
import zlib

import numpy as np

_VTK_TYPES = {"Float64": "<f8", "Float32": "<f4", "Int64": "<i8", "Int32": "<i4", "UInt8": "u1"}


def read_vtu(path, names):
    """The named data arrays of an rkpm frame (.vtu with appended raw, zlib-compressed
    data and UInt64 block headers), as numpy arrays of shape (n,) or (n, components)."""
    data = open(path, "rb").read()
    head = data[:data.index(b"<AppendedData")].decode()
    start = data.index(b"_", data.index(b"<AppendedData")) + 1
    out = {}
    for name in names:
        tag = re.search(r'<DataArray\b[^>]*\bName="' + re.escape(name) + r'"[^>]*>', head)
        if tag is None:
            raise ValueError(f"{path}: no data array named {name}")
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', tag.group(0)))
        pos = start + int(attrs["offset"])
        # Header: number of blocks, uncompressed block size, size of the last block,
        # then the compressed size of each block.
        blocks = int(np.frombuffer(data, "<u8", 1, pos)[0])
        sizes = np.frombuffer(data, "<u8", blocks, pos + 24)
        pos += 24 + 8 * blocks
        raw = bytearray()
        for size in sizes:
            raw += zlib.decompress(data[pos:pos + int(size)])
            pos += int(size)
        values = np.frombuffer(bytes(raw), _VTK_TYPES[attrs["type"]])
        components = int(attrs.get("NumberOfComponents", 1))
        out[name] = values.reshape(-1, components) if components > 1 else values
    return out


def last_frame(run_dir):
    """The path of a run's last frame, the last data set of its frames.pvd."""
    sets = ElementTree.parse(f"{run_dir}/frames.pvd").getroot().iter("DataSet")
    last = max(sets, key=lambda s: float(s.get("timestep")))
    return f"{run_dir}/{last.get('file')}"


def shell_spec(scene_path):
    """centre, semi_axes, thickness, layers, face_cells of the scene's (single) shell body,
    with the generator's defaults; the semi-axes must make a spheroid (a = b), the only
    case whose meridians are all one curve."""
    with open(scene_path, "rb") as f:
        scene = tomllib.load(f)
    bodies = [b for b in scene.get("body", []) if b.get("cloud", {}).get("generator") == "shell"]
    if len(bodies) != 1:
        raise ValueError(f"{scene_path}: expected one body with generator = \"shell\"")
    cloud = bodies[0]["cloud"]
    spec = {"centre": np.array(cloud.get("center", [0.0, 0.0, 0.0]), float),
            "semi_axes": np.array(cloud.get("semi_axes", [5e-6, 5e-6, 1.5e-6]), float),
            "thickness": float(cloud.get("thickness", 0.5e-6)),
            "layers": int(cloud.get("layers", 5)), "face_cells": int(cloud.get("face_cells", 32))}
    if spec["semi_axes"][0] != spec["semi_axes"][1]:
        raise ValueError(f"{scene_path}: the shell is not a spheroid (semi-axes {spec['semi_axes']})")
    return spec


class Shell:
    """A shell run's last frame: current positions x, reference positions X (x minus the
    displacement), and `columns` (layers x particles per layer; row 0 the inner surface,
    the last row the outer one) from the hexahedra, with each column's reference angle
    `psi` on the outer spheroid."""

    def __init__(self, run_dir, scene_path):
        self.spec = spec = shell_spec(scene_path)
        self.frame = last_frame(run_dir)
        d = read_vtu(self.frame, ["Points", "displacement", "connectivity", "offsets"])
        self.x = d["Points"]
        self.X = self.x - d["displacement"]
        if not np.all(np.diff(d["offsets"]) == 8):
            raise ValueError(f"{self.frame}: not a shell of hexahedra")
        hexes = d["connectivity"].reshape(-1, 8)
        up = np.full(len(self.x), -1)
        for a in range(4):
            up[hexes[:, a]] = hexes[:, a + 4]
        bottom_only = np.setdiff1d(hexes[:, :4], hexes[:, 4:])  # the inner surface
        columns = [bottom_only]
        while np.all(up[columns[-1]] >= 0):
            columns.append(up[columns[-1]])
        self.columns = np.array(columns)
        if len(self.columns) != spec["layers"] or self.columns.size != len(self.x):
            raise ValueError(f"{self.frame}: {len(self.columns)} layers of {self.columns.shape[1]} particles, "
                             f"not the scene's {spec['layers']} layers covering {len(self.x)} particles")
        a, _, c = spec["semi_axes"]
        Xo = self.X[self.columns[-1]] - spec["centre"]
        self.psi = np.arctan2(np.hypot(Xo[:, 0], Xo[:, 1]) / a, Xo[:, 2] / c)
        # The shape report's frame: the outer surface's centroid, the z axis.
        self.centre = self.x[self.columns[-1]].mean(axis=0)

    def surface(self, name, reference=False):
        """Positions, one per column, of the surface `name` ("outer", "inner", "mid",
        "midpoint"; see the module's docstring), current or reference."""
        p = self.X if reference else self.x
        cols = self.columns
        if name == "outer":
            return p[cols[-1]]
        if name == "inner":
            return p[cols[0]]
        if name == "mid":
            n = len(cols)
            return 0.5 * (p[cols[(n - 1) // 2]] + p[cols[n // 2]])
        if name == "midpoint":
            return 0.5 * (p[cols[0]] + p[cols[-1]])
        raise ValueError(f"unknown surface {name}")

    def reference_mid_axes(self):
        """Semi-axes (a, c) of the reference mid-surface: the spheroid halfway through the
        wall (every layer's semi-axes are the outer ones minus a share of the thickness).
        With an odd layer count the middle layer lies on it; with an even one the mean of
        the two middle layers' particles lies only near it."""
        a, _, c = self.spec["semi_axes"]
        half = 0.5 * self.spec["thickness"]
        return a - half, c - half

    def distance(self, a, b, psi, halfwidth):
        """Mean current distance between a column's points on the surfaces a and b (for
        "inner" and "outer" the wall's thickness along the column), over the columns
        whose reference angle is within halfwidth of psi."""
        s = np.abs(self.psi - psi) <= halfwidth
        return float(np.mean(np.linalg.norm(self.surface(a)[s] - self.surface(b)[s], axis=1)))

    def rz(self, name, reference=False):
        """Distance from the axis and height of each column's point of a surface,
        about the centre (the reference's: the scene's centre)."""
        p = self.surface(name, reference) - (self.spec["centre"] if reference else self.centre)
        return np.hypot(p[:, 0], p[:, 1]), p[:, 2]


def meridian(r, z, psi, n):
    """The generating curve, pole (psi = 0) to pole, from samples (r, z) at reference
    angles psi: 2 n + 1 points, the mean of the samples in bins of width pi / (2 n)
    centred on k pi / (2 n); the pole bins give (0, z0) of a fit z = z0 + z2 r^2. Returns
    (r, z, samples per bin). Raises ValueError if a bin is empty (n too large)."""
    k = np.rint(psi / (0.5 * np.pi / n)).astype(int)
    counts = np.bincount(k, minlength=2 * n + 1)
    if counts.min() == 0:
        raise ValueError(f"an empty bin at {n} bins per quarter meridian")
    R = np.bincount(k, weights=r) / counts
    Z = np.bincount(k, weights=z) / counts
    for b in (0, 2 * n):
        s = k == b
        if counts[b] >= 3:
            Z[b] = np.linalg.lstsq(np.c_[np.ones(counts[b]), r[s] ** 2], z[s], rcond=None)[0][0]
        R[b] = 0.0
    return R, Z, counts


def three_point_curvature(r, z):
    """Curvature of the circle through each point of the curve and its two neighbours
    (points 1..n-2), positive where the curve is convex (a sphere's outline), for a
    curve from the top pole outward and down to the bottom pole."""
    p = np.c_[r, z]
    p0, p1, p2 = p[:-2], p[1:-1], p[2:]
    sides = np.linalg.norm(p1 - p0, axis=1) * np.linalg.norm(p2 - p1, axis=1) * np.linalg.norm(p2 - p0, axis=1)
    cross = (p1[:, 0] - p0[:, 0]) * (p2[:, 1] - p0[:, 1]) - (p1[:, 1] - p0[:, 1]) * (p2[:, 0] - p0[:, 0])
    return -2.0 * cross / sides


def equator_fit_curvature(r, z, psi, halfwidth):
    """Meridian curvature at the equator from the raw samples of the band
    |psi - pi/2| <= halfwidth: least squares r = R + c2 z^2 + c4 z^4 (r is even in z on a
    shape symmetric about its equator z = 0, and r' = 0 there), curvature -2 c2. Returns
    the curvature and the number of samples."""
    s = np.abs(psi - 0.5 * np.pi) <= halfwidth
    coef = np.linalg.lstsq(np.c_[np.ones(s.sum()), z[s] ** 2, z[s] ** 4], r[s], rcond=None)[0]
    return -2.0 * coef[1], int(s.sum())


def thickness_profile(r, z):
    """The thickness profile [(r, h)] of a meridian from pole to pole (`meridian`) with
    2 n + 1 points: h = z(top) - z(bottom) of the points at psi and pi - psi, at their
    mean r, pole to equator (the format rbc_profile.rms_distance compares), and the
    largest up-down asymmetry |z(top) + z(bottom)| over the largest thickness. Either
    pole may come first; the points at psi and pi - psi must be at about the same r
    (the shape symmetric about its equator z = 0, as the shell and the references are)."""
    r, z = np.asarray(r, float), np.asarray(z, float)
    if z[0] < z[-1]:
        r, z = r[::-1], z[::-1]
    n = (len(r) - 1) // 2
    top_r, top_z = r[:n], z[:n]
    bot_r, bot_z = r[::-1][:n], z[::-1][:n]
    h = top_z - bot_z
    points = [(0.5 * (a + b), t) for a, b, t in zip(top_r, bot_r, h)] + [(r[n], 0.0)]
    return points, float(np.max(np.abs(top_z + bot_z)) / np.max(h))


def rim_curvature(r, z):
    """The largest |curvature| over the rim of a meridian from pole to pole (binned, or a
    dense analytic curve), by `three_point_curvature` (convex positive, either pole
    first): over the points whose tangent is within 45 degrees of the axis direction
    (|dz| >= |dr| between the two neighbours: the surface faces sideways more than up or
    down). Returns that curvature (signed) and the point's z, and the curvature at the
    curve's middle point: the equator of a shape symmetric about it (the bin at
    psi = pi/2 of `meridian`; t = 1/2 of a Helfrich shape, alpha = 0 of Evans-Fung's)."""
    r, z = np.asarray(r, float), np.asarray(z, float)
    if z[0] < z[-1]:
        r, z = r[::-1], z[::-1]
    k = three_point_curvature(r, z)
    band = np.abs(z[2:] - z[:-2]) >= np.abs(r[2:] - r[:-2])
    j = int(np.argmax(np.where(band, np.abs(k), -1.0)))
    return k[j], z[j + 1], k[(len(r) - 1) // 2 - 1]
