#!/usr/bin/env python3
"""Claim (issue 27, docs/accuracy.md): the loaded transmission error of a pair with tip relief
equals CalculiX's on the same mesh within 2 %: the modified outline is in the mesh, and so in the
exported deck, not a gap offset only gearstiff's contact engine sees.

The split-path pair (docs/references.md §1, T1 = 49.4 N·m, frictionless) in the middle of the
first double-contact zone (s = 1/2 of [A, B]) with linear long tip relief C = 10 µm on the pinion
only: the entering pair (relieved by the unmodified wheel tip) touches first, the leaving one is
relieved by 10·s = 5 µm (pinion tip) and closes only under load, so the load sharing and the TE
are set by the relief geometry in the mesh. (The entering pair touching at no load keeps ccx's
torque-driven pinion supported from the first increment: with both pairs relieved the deck
starts with a clearance and ccx's rigid pinion runs away, Δφ ~ 1e4 rad, before any contact.) On the ladder mesh of calculix_gear_pair.py (size field ×1, full
rims, three teeth per gear) `gearstiff stiffness` with FE_Q(1) gives TE = r_b1·Δφ + the unloaded
TE (0 here); ccx on the deck of `gearstiff mesh --set Mesh/format=inp` (the same mesh, the C3D8
slice of the same element) gives r_b1·Δφ from the unmodified touching position
(tools/calculix_stiffness.py), at penalty K = 10 and 100 E/h_c, extrapolated to K → ∞ in 1/K
(TE = TE_∞ + c/K: a penalty adds a compliance in series).

Measured 2026-11-26: gearstiff 7.4926 µm, ccx 7.4917 / 7.4869 µm at K = 10 / 100, K → ∞ 7.4864 µm:
+0.082 %. The relief matters here: the unmodified pair's TE at this position is 4.978 µm with
shares 0.479 / 0.521; with the relief 7.493 µm and 0.960 / 0.040 (gearstiff, same mesh). Runtime
≈ 30 s (ccx 8 + 17 s).

`both`: the same with C = 10 µm on both gears. Both pairs then start with a designed separation
of C·s = 5 µm (the tent of issue 27's zero-load rule): the deck's step 1 prescribes the pinion
turn that closes it (the unloaded TE / r_b1, geometry/abaqus_deck.h) plus a tenth of the elastic
turn, and step 2 releases it under the torque, so ccx's torque-driven pinion starts supported;
its equilibrium is that of the same frictionless model whatever step 1 did. Measured 2026-11-26:
gearstiff 9.9837 µm, ccx 9.8706 / 9.8654 µm at K = 10 / 100, K → ∞ 9.8648 µm: +1.21 % (before,
ccx's pinion ran away). The elastic part (TE − 5 µm) differs by 2.4 %, against 0.1–0.15 % for
the one-relief and unmodified cases: not explained yet (both pairs now carry load on relieved
flank zones, where the two contact discretisations differ most).

usage: calculix_relief_te.py GEARSTIFF WORKDIR [both]
"""
import json
import os
import subprocess
import sys

from verify import Checks, require_ccx, run_json, value, work_folder

require_ccx()
import calculix_compare as bench  # noqa: E402  (bench/, on the path through verify)

gearstiff, work = os.path.realpath(sys.argv[1]), work_folder(sys.argv[2])
env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
tool = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools",
                    "calculix_stiffness.py")
both = len(sys.argv) > 3 and sys.argv[3] == "both"
relief = ["Gear pair/Pinion/tip relief=10"] + (["Gear pair/Wheel/tip relief=10"] if both else [])
settings = bench.scene_settings(bench.LADDER_SIZES, 1.0) + relief
pair = run_json(gearstiff, "gear-pair")["values"]
radii = (0.5e-3 * bench.value(pair, "pinion_root_diameter"),
         0.5e-3 * bench.value(pair, "pinion_form_diameter"))

g = run_json(gearstiff, "stiffness", settings + ["Stiffness/mode=double",
                                                 "Finite elements/Element degree=1"])
te_gearstiff = value(g, "transmission_error")  # µm
factors = (10., 100.)
tes = []
for f in factors:
    run = bench.calculix_position(gearstiff, "double", settings, 0., f, work, env, radii)
    folder = os.path.join(work, f"double_f{f:g}")
    out = subprocess.run([sys.executable, tool, folder, "--json"], capture_output=True,
                         text=True, check=True)
    tes.append(json.loads(out.stdout)["transmission_error"])
    print(f"ccx K = {f:g} E/h_c: TE {tes[-1]:.4f} um ({run['time']:.1f} s)")
te_inf = (factors[0] * tes[0] - factors[1] * tes[1]) / (factors[0] - factors[1])
print(f"gearstiff Q1 TE {te_gearstiff:.4f} um; ccx K -> inf {te_inf:.4f} um")

checks = Checks("calculix_relief_te" + ("_both" if both else ""))
# Relief on the pinion: measured +0.082 % (2026-11-26), held to 0.25 %, three times that (the
# unmodified pair's k agrees to 0.15 %, calculix_gear_pair.py). Relief on both gears: measured
# +1.21 %, the elastic part 2.4 % off and not explained yet (the docstring): issue 27's 2 %, the
# target, not three times the measured difference.
checks.near("TE gearstiff / TE ccx(K->inf)", te_gearstiff, te_inf, 0.02 if both else 0.0025)
checks.done()
