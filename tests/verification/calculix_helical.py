#!/usr/bin/env python3
"""Claim (docs/helical.md, docs/calculix.md, issue 46): on the same twisted 3D mesh of a helical
pair gearstiff's mesh stiffness equals CalculiX's penalty-corrected one within 1 % at a
single-contact and at a double-contact position.

The small coarse helical pair of tests/helical/sweep_dynamics.py (z 19/29, m_n 2 mm, β ±10°,
b 8 mm, 5 layers, Q1, frictionless) at `Gear pair scene/position` single and double: solved by
`gearstiff stiffness` (FE_Q(1): the trilinear hexahedron ccx's C3D8 is) and by ccx on the deck
`gearstiff mesh --set Mesh/format=inp` writes from the same scene and mesh (docs/calculix.md:
pinion bore a rigid body turned by T1 about its axis, held axially and in tilt as gearstiff's
rigid hub is; the wheel bore held), at the contact penalties K = 10 and 100 E/h_c, extrapolated
to K → ∞ in 1/K as verification.calculix_gear_pair does (k(K) = k_∞ + a/K).
k = T1/(r_b1²·Δφ) with Δφ the rotation of the deck's ROT NODE (tools/calculix_stiffness.py).

usage: calculix_helical.py GEARSTIFF WORKDIR [crack]

With `crack` (verification.calculix_helical_crack, docs/faults.md "Helical teeth"): the single
position with a 1 mm root crack at 45° on the loaded pinion tooth over 60 % of the face from
z = 0 (the open 40 µm slit; its cells left out after the sections are turned back to the
transverse model, geometry/face_width.cc), so the deck must carry a partial crack that follows
the helix; checked against ccx and against the healthy k of the same run (the crack matters).
Run by hand (about 5 minutes: ccx on the cracked mesh, 107k DoFs, takes 97 + 156 s), not in ctest:
`test_scene_helical`'s partial-crack check (the same cells left out in every cracked layer) is
what the suite holds the twisted slit to. Measured 2026-12-02: gearstiff 96.337 N/µm, ccx
95.420 / 95.884 N/µm at K = 10 / 100 E/h_c, K → ∞ 95.935 N/µm: +0.419 %; the crack −4.72 %
against the healthy 101.107 N/µm (ccx's −5.12 %).

Measured 2026-12-02 (docs/accuracy.md's row): single position +0.106 % (101.107 against ccx
101.000 N/µm, 1 loaded pair), double position +0.578 % (145.298 against 144.463 N/µm, 2 loaded
pairs; ccx at K = 10 and 100 E/h_c: 143.219, 144.338). The double position differed by −2.02 %
until gearstiff stopped taking a helical scene's negative mortar gap (−0.20 µm on pair 1, an
artifact of the dual basis where the gap varies across a face, not an overlap of the built
flanks) out of the rotation as a turn to touching (stiffness/mesh_stiffness.cc); ccx's rotation
counts from the built position. Both solvers pair the same two tooth pairs (the deck's
`*CONTACT PAIR` list is gearstiff's candidate pairs) and split the load alike (ccx 0.494/0.506,
gearstiff 0.489/0.511 of the pinion torque). What remains at the double position is the same
artifact inside the contact solve: pair 1 starts 0.2 µm "overlapped", so gearstiff's hub turns
0.6 % less than ccx's (more layers should shrink it with the artifact; not measured).
Tolerances: single 0.35 % (≈3× the measured deviation); double the issue's 1 % (3× the measured
0.58 % would exceed it).
"""
import os
import sys

from verify import Checks, require_ccx, run_json, value, work_folder

require_ccx()
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import calculix_compare as bench  # noqa: E402  (bench/, on the path through verify)
from calculix_stiffness import rotation_node  # noqa: E402

# The pair and mesh of tests/helical/sweep_dynamics.py (its CASE; tests/helical/small_pair.py).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "helical"))
from small_pair import MESH, PAIR  # noqa: E402

TORQUE = 20.  # N·m, T1 of both commands (PAIR)
FACTORS = (10., 100.)
# Relative bounds on k (module docstring): ≈3× the measured deviation, at most the 1 %.
TOLERANCE = {"single": 0.0035, "double": 0.01}
# With the partial crack (measured 2026-12-02: +0.419 %, 96.337 against ccx's 95.935 N/µm): the 1 % (3x the measured deviation would exceed it).
TOLERANCE_CRACK = 0.01

gearstiff, work = os.path.realpath(sys.argv[1]), work_folder(sys.argv[2])
CRACK = ["Gear pair/Pinion/crack depth=1", "Gear pair/Pinion/crack width fraction=0.6"]
cracked = sys.argv[3:] == ["crack"]
if cracked:
    TOLERANCE = {"single": TOLERANCE_CRACK}
env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
pair = run_json(gearstiff, "gear-pair", [s for s in PAIR if s.startswith("Gear pair/")])
r_b1 = 1e-3 * value(pair, "pinion_base_radius")


def gearstiff_k(position, fault=()):
    # The deck's model: its hexahedra's own faces, chords of the helices between the layers (the
    # default, stated: `helicoid` would measure the gaps between the helicoids, docs/helical.md).
    report = run_json(gearstiff, "stiffness", PAIR + MESH + list(fault) + [
        f"Stiffness/mode={position}", "Mesh/helical flanks=chords",
        "Finite elements/Element degree=1", "Contact/Friction coefficient=0",
        "Stiffness/published reference=false"], ["--quiet"])
    return value(report, "mesh_stiffness"), report["values"].get("loaded_pairs", {}).get("value")


def ccx_k(position, factor):
    folder = os.path.join(work, f"{position}_f{factor:g}")
    run_json(gearstiff, "mesh", PAIR + MESH + (CRACK if cracked else []) + [
        "Scene/gear pair defaults=stiffness", f"Gear pair scene/position={position}",
        "Mesh/format=inp", f"Abaqus deck/penalty factor={factor:g}",
        "Abaqus deck/friction coefficient=0"], ["--quiet", "-o", folder])
    _, wall, _, _ = bench.run_timed(["ccx", "-i", "scene"], cwd=folder, env=env)
    rotation = abs(bench.last_rotation(os.path.join(folder, "scene.dat"),
                                       rotation_node(os.path.join(folder, "scene.inp"))))
    return TORQUE / (r_b1 ** 2 * rotation) / 1e6, wall


checks = Checks("calculix_helical_crack" if cracked else "calculix_helical")
for position in TOLERANCE:
    k, loaded = gearstiff_k(position, CRACK if cracked else ())
    runs = [ccx_k(position, f) for f in FACTORS]
    ks = [run[0] for run in runs]
    k_inf = (FACTORS[0] * ks[0] - FACTORS[1] * ks[1]) / (FACTORS[0] - FACTORS[1])
    print(f"{position}: gearstiff Q1 {k:.5f} N/um ({loaded} loaded pairs); ccx K = 10, 100 "
          f"E/h_c: {ks[0]:.5f}, {ks[1]:.5f} N/um ({runs[0][1]:.1f} + {runs[1][1]:.1f} s); "
          f"K -> inf {k_inf:.5f} N/um")
    checks.near(f"{position}: k gearstiff / k ccx(K->inf)", k, k_inf, TOLERANCE[position])
    if cracked:
        healthy, _ = gearstiff_k(position)
        print(f"healthy gearstiff Q1 {healthy:.5f} N/um: the crack {k / healthy - 1.:+.4%}, "
              f"ccx's {k_inf / healthy - 1.:+.4%}")
        checks.holds(f"the crack lowers k by more than 1 % (else the first check would not "
                     f"test the deck's slit): {k / healthy - 1.:+.4%}", k < 0.99 * healthy)
checks.done()
