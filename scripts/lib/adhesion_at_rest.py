"""An adhered sphere's run at rest against adhesive contact theory: the measured edge of
the compressive zone and approach of a run of a scene like examples/adhesion/
sphere_at_rest.toml, and the same quantities from JKR, DMT or Maugis-Dugdale
(scripts/lib/contact_theory.py) for the scene's own contact law, radius and moduli.

Why the compressive zone: the contact law is continuous, so no particle's gap jumps at
the theory's contact radius a; what the run does show is where its traction changes
sign, which (for the half-space law of two flat faces) is where the local gap is the
equilibrium gap z0. Maugis-Dugdale predicts that radius too (`md_zero_pressure_radius`:
a in the DMT limit, sqrt(2/3) a in the JKR limit), so the comparison is like for like.
The approach is measured at the sphere's centre: how far it has come below where an
undeformed sphere would rest at the gap z0 on the undeformed block.

    /usr/bin/python3 scripts/lib/adhesion_at_rest.py SCENE RUN_DIR [RUN_DIR ...]

prints one line per run."""
import argparse
import functools
import json
import math
import tomllib

import numpy as np

import contact_theory as T
import contact_traction
import derjaguin_contact
import layered_contact
from rbc_midsurface import last_frame, read_vtu


# The half-width of the local quadratic fit that finds the compressive zone's edge, in the
# sphere's particle spacings (contact_traction.compressive_zone_radius): 2 and 3 give the
# same edge within 0.5 % on the study's finer clouds; the nearest-value parabola alone
# scatters by up to 10 % there.
SMOOTHING_SPACINGS = 3.0


def small_strain_moduli(material):
    """(shear, bulk) [Pa] at F = I of a scene's [body.material] table: neo-Hookean and the
    LCE (mu with Lame's lambda, or bulk, as its K) and Mooney-Rivlin (mu = 2 (c1 + c2),
    K = 4 lambda), as docs/theory/materials.md derives them."""
    model = material["model"]
    if model == "neo_hookean":
        return material["mu"], material["lambda"] + 2.0 * material["mu"] / 3.0
    if model == "lce":
        return material["mu"], material["bulk"] + 2.0 * material["mu"] / 3.0
    if model == "mooney_rivlin":
        return 2.0 * (material["c1"] + material["c2"]), 4.0 * material["lambda"]
    raise ValueError(f"material model {model!r}: no small-strain moduli known here")


class AdhesionScene:
    """The sphere, the flat block and the contact law of a two-body adhesion scene: the
    first body a `sphere` cloud, the second a `block` whose top face it rests on."""

    def __init__(self, scene_path):
        with open(scene_path, "rb") as f:
            scene = tomllib.load(f)
        sphere, block = scene["body"][0], scene["body"][1]
        if sphere["cloud"]["generator"] != "sphere" or block["cloud"]["generator"] != "block":
            raise ValueError(f"{scene_path}: expected a sphere body then a block body")
        self.names = (sphere["name"], block["name"])
        self.R = sphere["cloud"]["radius"]
        self.spacing = 2.0 * self.R / sphere["cloud"]["cells"]
        self.centre = np.array(sphere["cloud"]["center"], float)
        self.block_top = block["cloud"]["origin"][2] + block["cloud"]["size"][2]
        moduli = [T.isotropic_moduli(*small_strain_moduli(b["material"])) for b in (sphere, block)]
        self.E_star = T.combined_modulus(moduli[0][0], moduli[0][1], moduli[1][0], moduli[1][1])
        contact = next(t for t in scene["term"] if t["type"] == "contact")
        self.law = T.contact_term_law(contact["epsilon"], contact["s0"], contact["beta"], contact.get("cutoff"))
        self.law_parameters = (contact["epsilon"], contact["s0"], tuple(contact["beta"]), contact.get("cutoff"))
        self.s0 = contact["s0"]
        self.layer_spacings = layered_contact.cloud_layer_spacings(sphere["cloud"], block["cloud"])

    def theory(self):
        """The three theories at zero load (`contact_theory.adhered_sphere`), and the edge
        of the compressive zone by the one that applies."""
        law = self.law
        sphere = T.adhered_sphere(self.R, law.w, self.E_star, sigma0=law.sigma0, z0=law.z0)
        if sphere.regime == "JKR":
            edge = math.sqrt(2.0 / 3.0) * sphere.a_jkr
        elif sphere.regime == "DMT":
            edge = sphere.a_dmt
        else:
            md = T.maugis_dugdale(self.R, law.w, law.sigma0, self.E_star)
            edge = T.md_zero_pressure_radius(md, self.R, law.sigma0, self.E_star)
        return sphere, edge

    def law_solution(self, profile):
        """(edge of the compressive zone, approach) [m] by the self-consistent solution with
        the contact law's own traction (`derjaguin_contact`), for the paraboloid the
        theories assume or the sphere's own profile."""
        return _law_solution(self.R, self.E_star, self.law_parameters, profile)

    def layered_solution(self):
        """(edge of the compressive zone [m], approach [m]) by the self-consistent solution
        with the traction the runs' particle layers carry (`layered_contact.LayeredTraction`)
        instead of the continuum's, for the sphere's own profile; NaN where Newton's method
        finds none."""
        return _layered_solution(self.R, self.E_star, self.law_parameters, self.layer_spacings)

    def measure(self, run_dir):
        """The run's compressive-zone edge [m], the normal force inside it [N], and the
        height [m] of the particles within a quarter radius of the sphere's centre."""
        frame = last_frame(run_dir)
        other = self.names[1]
        d = read_vtu(frame, ["Points", "body_id", "displacement", f"contact_force_{other}"])
        sphere = d["body_id"] == 0
        positions, forces = d["Points"][sphere], d[f"contact_force_{other}"][sphere]
        reference = positions - d["displacement"][sphere]
        axis_point = positions.mean(axis=0)
        edge, force = contact_traction.compressive_zone_radius(positions, forces, axis_point,
                                                               smoothing=SMOOTHING_SPACINGS * self.spacing)
        core = np.linalg.norm(reference - self.centre, axis=1) < 0.25 * self.R
        return edge, force, float(positions[core, 2].mean())

    def resting_centre(self):
        """Where the undeformed sphere's centre would rest: the gap z0 above the block."""
        return self.block_top + self.law.z0 + self.R


@functools.lru_cache(maxsize=None)
def _law_solution(R, E_star, law_parameters, profile):
    epsilon, s0, beta, cutoff = law_parameters
    state = derjaguin_contact.adhered_sphere(R, E_star, epsilon, s0, beta, cutoff, profile=profile)
    return state.compressive_radius, state.delta


@functools.lru_cache(maxsize=None)
def _layered_solution(R, E_star, law_parameters, layer_spacings):
    epsilon, s0, beta, cutoff = law_parameters
    law = layered_contact.LayeredTraction(*layer_spacings, epsilon, s0, math.sqrt(beta[0] * beta[1]),
                                          T.cutoff_or_default(cutoff, s0))
    try:
        state = derjaguin_contact.AdheredSphereSolver(R, E_star, law, law.z0, profile="sphere").at_load(0.0)
    except ArithmeticError:
        return math.nan, math.nan
    return state.compressive_radius, state.delta


def compare(scene_path, run_dir):
    """One run against the theory: a dict of the measures, the theory and the errors."""
    scene = AdhesionScene(scene_path)
    sphere, edge_theory = scene.theory()
    edge, force, core_z = scene.measure(run_dir)
    summary = json.load(open(f"{run_dir}/summary.json"))
    delta_theory = {"JKR": sphere.delta_jkr, "DMT": sphere.delta_dmt, "MD": sphere.delta_md}[sphere.regime]
    a_law, approach_law = scene.law_solution("sphere")
    a_layered, _ = scene.layered_solution()
    return {
        "particles": summary["total_particles"], "sphere_particles": summary["particle_counts"][scene.names[0]],
        "converged": summary.get("converged"), "steps": summary["steps"], "wall_s": summary["wall_time"],
        "tabor": sphere.tabor, "maugis_lambda": sphere.lam, "theory": sphere.regime,
        "E_star": scene.E_star, "w": scene.law.w, "R": scene.R, "s0": scene.s0,
        "a_sim": edge, "a_theory": edge_theory, "rel_error": edge / edge_theory - 1.0,
        "contact_radius_theory": {"JKR": sphere.a_jkr, "DMT": sphere.a_dmt, "MD": sphere.a_md}[sphere.regime],
        "core_z": core_z, "approach_sim": scene.resting_centre() - core_z, "approach_theory": delta_theory,
        "compressive_force": force,
        "a_law_paraboloid": scene.law_solution("paraboloid")[0], "a_law_sphere": a_law,
        "rel_error_law": edge / a_law - 1.0, "approach_law": approach_law,
        "a_layered": a_layered, "rel_error_layered": edge / a_layered - 1.0,
    }


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene")
    parser.add_argument("runs", nargs="+")
    args = parser.parse_args(argv)
    for run in args.runs:
        c = compare(args.scene, run)
        print(f"{run}: {c['particles']} particles, Tabor {c['tabor']:.3f} (lambda {c['maugis_lambda']:.3f}, "
              f"{c['theory']}): compressive zone {c['a_sim'] * 1e6:.4f} um against {c['a_theory'] * 1e6:.4f} "
              f"({100 * c['rel_error']:+.2f} %), approach {c['approach_sim'] * 1e9:.1f} nm against "
              f"{c['approach_theory'] * 1e9:.1f}, {c['steps']} steps, {c['wall_s']:.1f} s")


if __name__ == "__main__":
    main()
