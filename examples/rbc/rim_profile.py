#!/usr/bin/env python3
"""Meridian profile of the red blood cell's outer surface near the rim, from one frame.

Reads a frame (.vtu as rkpm writes it: appended raw data, zlib-compressed, UInt64
headers) of the shell scene, takes the particles of the outer surface (reference
position on the spheroid with semi-axes a, a, c), bins them by the polar angle of their
reference position in the meridian plane (3 degrees per bin, averaged over the azimuth)
and prints, per bin, the mean current r (distance from the axis) and z, and the
curvature of the (r, z) curve through it and its two neighbours. A ridge at the
equator shows as a large curvature there flanked by negative curvature (concave bands).
With --reference the reference positions are used instead of the current ones.
Usage: python3 examples/rbc/rim_profile.py FRAME.vtu [--reference] [--a 5e-6 --c 1.5e-6]
(standard library only)
"""
import argparse
import math
import re
import struct
import zlib


def read_arrays(path, names):
    """The named point arrays (flat tuples of float64) of an appended-raw, zlib .vtu."""
    data = open(path, "rb").read()
    marker = b'<AppendedData encoding="raw">'
    start = data.index(b"_", data.index(marker) + len(marker)) + 1
    out = {}
    for name in names:
        m = re.search(rb'Name="' + name.encode() + rb'"[^>]*offset="(\d+)"', data)
        if not m:
            raise SystemExit(f"{path}: no array named {name}")
        offset = start + int(m.group(1))
        blocks = struct.unpack_from("<Q", data, offset)[0]
        sizes = struct.unpack_from("<" + "Q" * blocks, data, offset + 24)
        pos, raw = offset + 24 + 8 * blocks, b""
        for size in sizes:
            raw += zlib.decompress(data[pos:pos + size])
            pos += size
        out[name] = struct.unpack("<" + "d" * (len(raw) // 8), raw)
    return out


def curvature(p0, p1, p2):
    """Signed curvature of the circle through three points (1 / length)."""
    lengths = math.dist(p0, p1) * math.dist(p1, p2) * math.dist(p0, p2)
    twice_area = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0])
    return 2.0 * twice_area / lengths if lengths > 0 else 0.0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("frame")
    parser.add_argument("--reference", action="store_true")
    parser.add_argument("--a", type=float, default=5e-6)
    parser.add_argument("--c", type=float, default=1.5e-6)
    parser.add_argument("--max-angle", type=float, default=45.0)
    args = parser.parse_args()
    arrays = read_arrays(args.frame, ["Points", "displacement"])
    points, disp = arrays["Points"], arrays["displacement"]
    bins = {}
    for i in range(len(points) // 3):
        x = points[3 * i:3 * i + 3]
        X = [x[k] - disp[3 * i + k] for k in range(3)]
        if abs((X[0] ** 2 + X[1] ** 2) / args.a ** 2 + X[2] ** 2 / args.c ** 2 - 1.0) > 1e-6:
            continue  # not on the outer surface
        shown = X if args.reference else x
        angle = math.degrees(math.atan2(X[2], math.hypot(X[0], X[1])))
        bins.setdefault(round(angle / 3.0), []).append((math.hypot(shown[0], shown[1]), shown[2]))
    profile = [(3 * k, sum(p[0] for p in v) / len(v), sum(p[1] for p in v) / len(v), len(v))
               for k, v in sorted(bins.items())]
    print("angle_deg r_um z_um particles curvature_per_um")
    for j in range(1, len(profile) - 1):
        angle, r, z, count = profile[j]
        if abs(angle) <= args.max_angle:
            k = curvature(profile[j - 1][1:3], (r, z), profile[j + 1][1:3])
            print(f"{angle:9.0f} {r * 1e6:6.3f} {z * 1e6:6.3f} {count:9d} {k * 1e-6:16.3f}")


if __name__ == "__main__":
    main()
