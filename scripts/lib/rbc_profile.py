"""The distance between two red-blood-cell thickness profiles, the measure the RBC
studies (scripts/study rbc, scripts/study relaxation) and their convergence criteria
use: the RMS of h(r) / D over 41 points of r / R in 0.05-0.95, each profile in units of
its own diameter D (docs/verification/rbc.md). The study scripts import it (PYTHONPATH=scripts/lib)."""
import csv
import math

# r / R of the compared points.
POINTS = [0.05 + 0.9 * k / 40 for k in range(41)]


def read(run_dir, diameter):
    """A run's profile: its diameter [m] and its (r, h) points [m] from shape_profile.csv."""
    with open(f"{run_dir}/shape_profile.csv") as f:
        return diameter, [(float(p["r"]), float(p["thickness"])) for p in csv.DictReader(f)]


def thickness_over_D(profile, x):
    """h(r) / D at r = x D / 2, linear between the profile's points."""
    D, points = profile
    pts = [(2 * r / D, h / D) for r, h in points]
    for (x0, h0), (x1, h1) in zip(pts, pts[1:]):
        if x0 <= x <= x1:
            return h0 + (h1 - h0) * (x - x0) / (x1 - x0)
    return pts[0][1] if x < pts[0][0] else pts[-1][1]


def rms_distance(a, b):
    """RMS of h / D between two profiles over POINTS [fraction of D]."""
    return math.sqrt(sum((thickness_over_D(a, x) - thickness_over_D(b, x)) ** 2 for x in POINTS) / len(POINTS))
