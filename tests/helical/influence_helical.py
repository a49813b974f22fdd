#!/usr/bin/env python3
"""The 3D influence-coefficient model on a helical pair against the exact FE contact path (issue
47, docs/ltca.md §3 "Helical").

usage: influence_helical.py path/to/gearstiff WORK_FOLDER
       [small|built-in|small-fine|small-15-fine|small-5-fine|built-in-fine|built-in-fine-20]
       [--exact | --same-layers]

Runs `Stiffness/contact model = influence coefficients` on a 4-position sweep of the case and
compares it position by position with the exact path's values stored below (or, with --exact,
with the exact per-position sweep run now on the same settings: the measurement that stored
them): k, the loaded TE, the load share of every pair and K_Hβ at issue 47's tolerances (k 1 %,
TE 0.1 µm, shares 0.01, K_Hβ 2 %); the peak pressure and the axial force are printed, not
checked (the exact path's nodal peak at these coarse contact sizes is not converged: docs/ltca.md
"Peak pressure against the converged exact peak"). Exit 1 when one is exceeded.

Cases: `small` (tests/helical/small_pair.py: z 19/29, m_n 2 mm, β ±10°, b 8 mm, 20 N·m, 5 layers,
the coarse sizes; Q1, μ 0) and `built-in` (the split-path pair at β ±15°, ε_β 0.79, 13 layers,
Q1, μ 0, the small pair's coarse sizes scaled to m_n 2.5 mm: tests/helical/sweep_once.py).
`small-fine`, `small-15-fine` and `small-5-fine`: the small pair at β 10°, 15° and 5° on the exact
path's converged contact size (10 layers, h_c 0.075 mm), the references of docs/ltca.md §3 "Line
ends" and "Tip edges". `built-in-fine`:
the built-in pair at h_c 0.094 mm (0.0375·m_n, the small pair's converged relative size), 13
layers; `built-in-fine-20` the same on 20 layers.

The fine cases are compared with the exact path's layer limit (LIMIT below: `Mesh/layer
extrapolation = richardson`, docs/helical.md "Layer extrapolation"; the built-in pair's from its
13- and 20-layer levels), not with the exact path on the same layers, which is still converging
along the face (the small pair at β 15°: +0.5 … +0.9 % from 10 layers to the limit);
`--same-layers` compares with the same-layer values instead.
"""
import json
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
sys.path.insert(0, HERE)
from report_csv import column  # noqa: E402
from small_pair import MESH, PAIR  # noqa: E402

COMMON = ["Finite elements/Element degree=1", "Contact/Friction coefficient=0",
          "Stiffness/published reference=false", "Stiffness/mode=sweep",
          "Stiffness/sweep positions=4"]
CASES = {
    "small": PAIR + MESH,
    "built-in": ["Gear pair/Pinion/helix angle=15", "Gear pair/Wheel/helix angle=-15",
                 "Mesh/dimension=3", "Mesh/contact size=0.1875", "Mesh/fine radius=0.5",
                 "Mesh/body size=0.9375", "Mesh/rim size=3.125"],
}
# The converged exact level of the small pair (docs/ltca.md §3 "Line ends"): 10 layers, h_c
# 0.075 mm (0.075 → 0.0375 mm moved k by −0.10 … +0.24 %), at β 10° and 15°.
FINE = [e for e in MESH if not e.startswith(("Mesh/layers", "Mesh/contact size"))] + [
    "Mesh/layers=10", "Mesh/contact size=0.075"]
BETA_15 = [e for e in PAIR if "helix angle" not in e] + [
    "Gear pair/Pinion/helix angle=15", "Gear pair/Wheel/helix angle=-15"]
CASES["small-fine"] = PAIR + FINE
CASES["small-15-fine"] = BETA_15 + FINE
CASES["small-5-fine"] = [e for e in PAIR if "helix angle" not in e] + [
    "Gear pair/Pinion/helix angle=5", "Gear pair/Wheel/helix angle=-5"] + FINE
# The built-in pair at half its contact size (h_c 0.094 mm = 0.0375·m_n, the small pair's
# converged relative size; 13 layers as `built-in`): the reference of docs/ltca.md §3 "Line ends".
CASES["built-in-fine"] = [e for e in CASES["built-in"] if not e.startswith("Mesh/contact size")] + [
    "Mesh/contact size=0.09375"]
CASES["built-in-fine-20"] = CASES["built-in-fine"] + ["Mesh/layers=20"]
FAST = ["Stiffness/contact model=influence coefficients"]
EXACT = ["Stiffness/sweep mesh=per position"]

# K_Hβ of the exact path re-measured 2026-12-04 (main 7bd615f, one run each; k, TE, shares and
# p_max unchanged to every stored digit): its line load is now the planes' nodal forces over their
# widths (stiffness/face_load.h), not the pressure integrated again across the profile, which read
# low on a plane where a contact line starts. Moved: small −1.83 % at 0.125; small-15-fine −1.51 %
# at 0.125, +5.31 % at 0.875; built-in +3.66, −0.69, +8.56, −2.61 %; built-in-fine +1.47, −0.38,
# +4.53, −0.70 %; built-in-fine-20 −1.74, −0.20, +5.54, −1.09 % (338 s); small-fine not at all.
# LIMIT's 20-layer K_Hβ (richardson, 2 ranks): small-15-fine −1.60 % at 0.125, +3.33 % at 0.875;
# small-fine and small-5-fine not at all.
# The exact path's values (regression: measured 2026-12-03 with the settings above, the exact
# per-position sweep, `gearstiff` of main a4b173a, one run each): k (N/µm), TE (µm), the shares
# of pairs −1, 0, +1, K_Hβ, the peak pressure (MPa). `small`: 9.5 s, 0.62 GB, 52k-61k DoFs a
# position; `built-in`: 92 s, 2.9 GB, 255k-268k DoFs a position. The fast model refuses helical
# pairs until it meets issue 47's tolerances (docs/ltca.md §3 "Helical"): lift the refusal in
# stiffness/influence_checks.cc (check_influence_settings) by hand to run this script.
STORED = {
    "small": {"k": [144.1177, 144.844, 122.9586, 100.8041], "te": [7.6685, 7.6301, 8.9882, 10.9636],
              "share": [[0, 0.4439, 0.5561], [0, 0.5183, 0.4817], [0, 0.7303, 0.2697], [0, 1, 0]],
              "K_Hb": [1.0461, 1.0335, 1.4086, 1.0115], "p_max": [854.4, 720.0, 1368.3, 930.8]},
    "built-in": {"k": [381.3643, 386.1141, 359.7598, 360.5528],
                 "te": [5.0937, 5.031, 5.3996, 5.3877],
                 "share": [[0, 0.3726, 0.6274], [0, 0.5382, 0.4618], [0.0326, 0.6775, 0.2899],
                           [0.209, 0.7007, 0.0902]],
                 "K_Hb": [1.3167, 1.3686, 1.5667, 1.4538], "p_max": [419.7, 471.4, 479.2, 730.6]},
}

# regression: measured 2026-12-03 (ltca47j, `gearstiff` of main f5441c6, the exact per-position
# sweep with the settings of the case, one unlocked run each): small-fine 32.9 s, 1.95 GB;
# small-15-fine 43.4 s.
STORED["small-fine"] = {
    "k": [145.582, 146.363, 123.697, 101.927], "te": [7.5914, 7.5509, 8.9345, 10.8428],
    "share": [[0, 0.443, 0.557], [0, 0.5215, 0.4785], [0, 0.7381, 0.2619], [0, 1, 0]],
    "K_Hb": [1.0436, 1.0163, 1.4884, 1.0204], "p_max": [1124.1, 928.7, 3564.1, 1083.9]}
STORED["small-15-fine"] = {
    "k": [132.661, 133.502, 111.988, 107.625], "te": [8.1904, 8.1389, 9.7024, 10.0957],
    "share": [[0, 0.4413, 0.5587], [0, 0.529, 0.471], [0, 0.7594, 0.2406], [0.1818, 0.8182, 0]],
    "K_Hb": [1.0726, 1.0332, 1.5712, 1.7758], "p_max": [1152.7, 1530.4, 2446.1, 1733.3]}

# regression: measured 2026-12-03 (ltca47k, the exact per-position sweep with the settings of
# `built-in-fine`, under the build lock, one run): 143 s, 4.85 GB peak. From `built-in` (h_c
# 0.19 mm) k moved +0.67, +0.36, −0.05, +1.21 %.
STORED["built-in-fine"] = {
    "k": [383.9273, 387.5169, 359.5681, 364.9129], "te": [5.0597, 5.0128, 5.4024, 5.3233],
    "share": [[0, 0.378, 0.622], [0, 0.5408, 0.4592], [0.0329, 0.6774, 0.2898],
              [0.2215, 0.6898, 0.0888]],
    "K_Hb": [1.2821, 1.3477, 1.5647, 1.4156], "p_max": [557.3, 591.3, 710.6, 833.0]}
# The same on 20 layers (regression: measured 2026-12-03, ltca47k, under the build lock beside
# another engineer's 2-rank run, one run): 521 s, 4.87 GB peak. From 13 layers k moved +1.40,
# +1.78, +2.44, +1.67 %: the exact path is not converged along the face at 13 layers.
STORED["built-in-fine-20"] = {
    "k": [389.3218, 394.3983, 368.3328, 370.9951], "te": [4.9896, 4.9253, 5.2739, 5.2360],
    "share": [[0, 0.3867, 0.6133], [0, 0.5486, 0.4514], [0.0452, 0.6768, 0.278],
              [0.2213, 0.6913, 0.0874]],
    "K_Hb": [1.2935, 1.3366, 1.5706, 1.4507], "p_max": [645.6, 970.6, 1059.0, 1353.0]}

# The exact path's layer limit (regression: measured 2026-12-03, session 29, `gearstiff` of main
# 5e49a9e, the exact per-position sweep of the case with `Mesh/layer extrapolation = richardson`
# on 2 ranks, one run each, 71-107 s): k, TE and shares extrapolated from 10 and 20 layers; K_Hβ
# and p_max are the 20-layer level's (not extrapolated: the exact K_Hβ moved by +5.5 % and +6.0 %
# from 10 to 20 layers at the tip-edge positions 0.625 and 0.875 of β 15°, so it is not converged
# there). From 10 layers k moved by β 10° +0.42, +0.40, +0.21, +0.29 %; β 15° +0.73, +0.89,
# +0.48, +0.69 %; β 5° +0.04, +0.05, +0.16, +0.01 %.
LIMIT = {
    "small-fine": {
        "k": [146.1965, 146.941, 123.9572, 102.2176], "te": [7.5595, 7.5212, 8.9158, 10.812],
        "share": [[0, 0.4428, 0.5572], [0, 0.5221, 0.4779], [0, 0.7404, 0.2596], [0, 1, 0]],
        "K_Hb": [1.0558, 1.0317, 1.5121, 1.0261], "p_max": [1135.8, 959.6, 3970.2, 1122.3]},
    "small-15-fine": {
        "k": [133.6294, 134.6838, 112.5292, 108.3652], "te": [8.1311, 8.0674, 9.6557, 10.0268],
        "share": [[0, 0.4413, 0.5587], [0, 0.5316, 0.4684], [0, 0.7638, 0.2362],
                  [0.1799, 0.8201, 0]],
        "K_Hb": [1.0767, 1.0402, 1.6573, 1.8478], "p_max": [1144.4, 1370.9, 3431.9, 2315.4]},
    "small-5-fine": {
        "k": [153.6085, 155.0177, 131.7137, 106.508], "te": [7.268, 7.2019, 8.4761, 10.4821],
        "share": [[0, 0.4396, 0.5604], [0, 0.5174, 0.4826], [0, 0.7255, 0.2745], [0, 1, 0]],
        "K_Hb": [1.044, 1.0291, 1.3485, 1.0279], "p_max": [1199.5, 1007.5, 3199.8, 1161.5]},
}


def richardson(coarse, fine, l_coarse, l_fine):
    """The limit of a quantity with an error ∝ 1/L² from two layer counts (docs/helical.md)."""
    return fine + (fine - coarse) * l_coarse ** 2 / (l_fine ** 2 - l_coarse ** 2)


# The built-in pair's limit from its stored 13- and 20-layer levels (h_c 0.094 mm); K_Hβ and
# p_max the 20-layer level's. This k is low: the exact path at 40 layers (2026-12-04, single
# positions, one run each) gives 395.427, 399.829, 374.354, 376.921 N/µm, and the range its two
# finest levels extrapolate to (1/L² … 1/L) is 398.4–402.2, 401.9–404.5, 376.4–380.6 and
# 379.5–383.4 N/µm (docs/ltca.md §3 "Where the rest of the bias is not"): no single limit is known
# to 1 %, so k within 1 % of LIMIT is not the test on this pair; read it against the range.
LIMIT["built-in-fine"] = {
    key: ([richardson(a, b, 13, 20) for a, b in zip(STORED["built-in-fine"][key],
                                                     STORED["built-in-fine-20"][key])]
          if key in ("k", "te") else
          [[richardson(x, y, 13, 20) for x, y in zip(a, b)] for a, b in
           zip(STORED["built-in-fine"][key], STORED["built-in-fine-20"][key])]
          if key == "share" else STORED["built-in-fine-20"][key])
    for key in ("k", "te", "share", "K_Hb", "p_max")}
LIMIT["built-in-fine-20"] = LIMIT["built-in-fine"]

K_TOLERANCE = 1e-2  # relative: issue 47
TE_TOLERANCE = 0.1  # µm: issue 47
SHARE_TOLERANCE = 1e-2  # issue 47
FACE_LOAD_TOLERANCE = 2e-2  # relative, K_Hβ: issue 47


def run(gearstiff, work, case, model):
    args = [gearstiff, "stiffness", "--json", "--quiet"]
    for entry in COMMON + CASES[case] + model:
        args += ["--set", entry]
    start = time.monotonic()
    out = subprocess.run(args, cwd=work, capture_output=True, text=True)
    wall = time.monotonic() - start
    if out.returncode != 0:
        sys.exit(f"influence_helical: exited {out.returncode}: {out.stderr.strip()[-1500:]}")
    with open(os.path.join(work, f"{case}_{'fast' if model is FAST else 'exact'}.json"), "w") as f:
        f.write(out.stdout)
    return json.loads(out.stdout), wall


def columns(report):
    """Per position: k, TE, the shares of pairs −1, 0, +1, K_Hβ and the peak pressure."""
    return {"k": column(report, "stiffness_sweep", "stiffness"),
            "te": column(report, "stiffness_sweep", "transmission_error"),
            "share": [list(s) for s in zip(*(column(report, "stiffness_sweep", name) for name in
                                             ("share_pair_m1", "share_pair_0", "share_pair_p1")))],
            "K_Hb": column(report, "face_load_factor", "face_load_factor"),
            "p_max": column(report, "stiffness_sweep", "max_pressure")}


def main():
    gearstiff, work = os.path.realpath(sys.argv[1]), sys.argv[2]
    case = sys.argv[3] if len(sys.argv) > 3 and not sys.argv[3].startswith("--") else "small"
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    fast, wall_fast = run(gearstiff, work, case, FAST)
    b = columns(fast)
    if "--exact" in sys.argv:
        exact, wall_exact = run(gearstiff, work, case, EXACT)
        a = columns(exact)
        print(f"exact ({case}, per position, {wall_exact:.1f} s): " + json.dumps(
            {key: a[key] for key in ("k", "te", "share", "K_Hb", "p_max")}))
    elif case in LIMIT and "--same-layers" not in sys.argv:
        a = LIMIT[case]
    else:
        a = STORED[case]
    failed = 0
    for i in range(len(a["k"])):
        checks = [("k", b["k"][i] / a["k"][i] - 1., K_TOLERANCE, "relative"),
                  ("TE", b["te"][i] - a["te"][i], TE_TOLERANCE, "µm"),
                  ("share", max(abs(x - y) for x, y in zip(a["share"][i], b["share"][i])),
                   SHARE_TOLERANCE, ""),
                  ("K_Hb", b["K_Hb"][i] / a["K_Hb"][i] - 1., FACE_LOAD_TOLERANCE, "relative")]
        for name, deviation, tolerance, unit in checks:
            ok = abs(deviation) <= tolerance
            failed += not ok
            print(f"{'ok  ' if ok else 'FAIL'} position {i + 1} {name}: {deviation:+.4g} {unit} "
                  f"(tolerance {tolerance:g})")
        print(f"     position {i + 1}: k {a['k'][i]:.6g} / {b['k'][i]:.6g} N/µm, TE "
              f"{a['te'][i]:.5g} / {b['te'][i]:.5g} µm, shares {a['share'][i]} / "
              f"{[round(x, 5) for x in b['share'][i]]}, K_Hb {a['K_Hb'][i]:.5g} / "
              f"{b['K_Hb'][i]:.5g}, p_max {a.get('p_max', [float('nan')] * 4)[i]:.5g} / "
              f"{b['p_max'][i]:.5g} MPa (exact / fast)")
    print(f"{case}: fast model {wall_fast:.1f} s wall")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
