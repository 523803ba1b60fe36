"""Tests of the red blood cell's mid-surface measures (scripts/lib/rbc_midsurface.py),
which scripts/study rbc-helfrich compares with Helfrich's minimum: the curve measures
against closed forms (a circle's and an ellipse's curvature, a spheroid's meridian and
thickness profile), and the reading of a real frame: rkpm writes the reference shell
(one step of a shell with no load), whose columns must run through the layers in order
and whose "mid" surface must lie on the spheroid halfway through the wall. RKPM_BIN
names the rkpm program (ctest passes the build's). About 2 s."""
import os
import subprocess
import sys
import tempfile

import numpy as np
import pytest

sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "lib"))
import rbc_midsurface as M  # noqa: E402


def ellipse(a, c, psi):
    """Points of the meridian r = a sin psi, z = c cos psi (psi = 0 at the top pole)."""
    return a * np.sin(psi), c * np.cos(psi)


def test_three_point_curvature_of_a_circle_is_its_inverse_radius_convex_positive():
    psi = np.linspace(0.0, np.pi, 41)
    r, z = ellipse(3.0, 3.0, psi)
    assert np.allclose(M.three_point_curvature(r, z), 1.0 / 3.0, rtol=1e-12)
    # The same curve from the bottom pole up: the sign stays (convex positive).
    k_up = M.three_point_curvature(r[::-1], z[::-1])
    assert np.all(k_up < 0) or np.all(k_up > 0)


def test_equator_fit_gives_an_ellipses_curvature_at_the_end_of_its_axis():
    # At the end of the semi-axis a, an ellipse's curvature is a / c^2.
    a, c = 4.0, 1.5
    psi = np.linspace(0.0, np.pi, 2001)
    r, z = ellipse(a, c, psi)
    k, n = M.equator_fit_curvature(r, z, psi, halfwidth=0.15)
    assert n > 50
    assert k == pytest.approx(a / c ** 2, rel=2e-3)


def test_rim_curvature_of_an_oblate_ellipse_is_at_its_equator():
    a, c = 4.0, 1.5
    psi = np.linspace(0.0, np.pi, 801)
    r, z = ellipse(a, c, psi)
    k_max, z_at, k_equator = M.rim_curvature(r, z)
    assert k_max == pytest.approx(a / c ** 2, rel=1e-3)
    assert abs(z_at) < 0.01 * c
    assert k_equator == pytest.approx(a / c ** 2, rel=1e-3)


def test_meridian_bins_a_spheroid_and_puts_its_poles_on_the_axis():
    a, c, n = 4.0, 1.5, 6
    rng = np.random.default_rng(3)
    psi = rng.uniform(0.0, np.pi, 20000)
    r, z = ellipse(a, c, psi)
    R, Z, counts = M.meridian(r, z, psi, n)
    assert len(R) == 2 * n + 1 and counts.min() > 0
    assert R[0] == 0.0 and R[-1] == 0.0
    # The pole fit's remainder is the r^4 term (3e-6 here); the bin's plain mean would be
    # low by about w^2 / 24 of c (3e-3).
    assert Z[0] == pytest.approx(c, rel=1e-4) and Z[-1] == pytest.approx(-c, rel=1e-4)
    # The equator bin's mean of a sin psi over its width pi / (2 n), sin(w/2) / (w/2) of a.
    w = 0.5 * np.pi / n
    assert R[n] == pytest.approx(a * np.sin(w / 2) / (w / 2), rel=5e-3)
    with pytest.raises(ValueError):
        M.meridian(r[:20], z[:20], psi[:20], 40)  # too many bins for the samples


def test_thickness_profile_of_a_spheroid_is_twice_its_height_and_symmetric():
    a, c = 4.0, 1.5
    psi = np.linspace(0.0, np.pi, 21)
    r, z = ellipse(a, c, psi)
    points, asymmetry = M.thickness_profile(r, z)
    assert asymmetry < 1e-12
    for rr, h in points:
        assert h == pytest.approx(2.0 * c * np.sqrt(max(0.0, 1.0 - (rr / a) ** 2)), abs=1e-12)


SCENE = """
[scene]
name = "shell_at_rest"
[integrator]
mode = "dynamic"
t_end = 1.0
[output]
every = 1.0
[[body]]
name = "cell"
density = 1000.0
[body.cloud]
generator = "shell"
center = [0.0, 0.0, 0.0]
semi_axes = [4e-6, 4e-6, 2e-6]
thickness = {thickness}
face_cells = 8
layers = {layers}
[body.material]
model = "neo_hookean"
mu = 1e4
lambda = 1e5
"""


@pytest.mark.parametrize("layers", [3, 4])
def test_a_frame_of_the_reference_shell_gives_its_layers_and_mid_surface(layers):
    program = os.environ.get("RKPM_BIN")
    if not program:
        pytest.skip("RKPM_BIN is not set (ctest sets it to the build's rkpm)")
    thickness = 0.5e-6
    with tempfile.TemporaryDirectory() as tmp:
        scene = os.path.join(tmp, "shell.toml")
        with open(scene, "w") as f:
            f.write(SCENE.format(thickness=thickness, layers=layers))
        out = os.path.join(tmp, "out")
        subprocess.run([program, "run", scene, "--out", out, "--max-steps", "1", "--quiet"], check=True,
                       stdout=subprocess.DEVNULL)
        shell = M.Shell(out, scene)
        assert shell.columns.shape[0] == layers
        a_m, c_m = shell.reference_mid_axes()
        assert (a_m, c_m) == pytest.approx((4e-6 - thickness / 2, 2e-6 - thickness / 2))
        # Each column climbs from the inner surface to the outer one, one layer at a time.
        level = [np.sqrt((p[:, 0] ** 2 + p[:, 1] ** 2) / 4e-6 ** 2 + p[:, 2] ** 2 / 2e-6 ** 2)
                 for p in (shell.X[row] for row in shell.columns)]
        assert np.all(np.diff(np.array(level), axis=0) > 0)
        assert np.allclose(level[-1], 1.0, atol=1e-12)
        mid = shell.surface("mid", reference=True)
        on_mid = np.sqrt((mid[:, 0] ** 2 + mid[:, 1] ** 2) / a_m ** 2 + mid[:, 2] ** 2 / c_m ** 2)
        if layers % 2 == 1:
            assert np.allclose(on_mid, 1.0, atol=1e-12)  # the middle layer lies on it
        else:
            assert np.allclose(on_mid, 1.0, atol=0.02)   # the two middle layers' mean lies near it
        # One step from rest barely moves it: the current mid-surface is the reference one.
        assert np.max(np.linalg.norm(shell.surface("mid") - mid, axis=1)) < 1e-3 * thickness
