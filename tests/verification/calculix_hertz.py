#!/usr/bin/env python3
"""Claim (docs/calculix.md, "Hertz cylinders"): on the same mesh gearstiff and CalculiX carry the
same force at the same approach (to 1e-6), and both reproduce Hertz's half-width and peak
pressure (Johnson 1985 eq. 4.43, 4.45; docs/references.md §6) within a fraction of a per cent.

The cylinders scene of `gearstiff mesh --set Scene/type=cylinders` (R1 = R2 = 10 mm,
F' = 100 N/mm, L = 10 mm, steel, plane strain, frictionless) with a coarser contact size than its
default a/10 (h_c = 0.0125 mm ≈ a/6, to keep the two ccx solves short): ccx pushes cylinder 2's
flat face with F = F'·L at K = 10 and 100 E/h_c, the approach is extrapolated to K → ∞, and
`gearstiff contact` (FE_Q(1)) moves the same face of the same .msh by that approach
(bench/calculix_hertz.py, whose functions this test calls).

usage: calculix_hertz.py GEARSTIFF WORKDIR
"""
import json
import os
import sys

from verify import Checks, require_ccx, work_folder

require_ccx()
import calculix_hertz as bench  # noqa: E402  (bench/, on the path through verify)

gearstiff, work = os.path.realpath(sys.argv[1]), work_folder(sys.argv[2])
env = dict(os.environ, OMP_NUM_THREADS="1")
extra = ["Mesh/contact size=0.0125"]
f1, f2 = 10., 100.
c1 = bench.calculix(gearstiff, f1, work, extra, env)
c2 = bench.calculix(gearstiff, f2, work, extra, env)
approach = (f1 * c1["approach"] - f2 * c2["approach"]) / (f1 - f2)
with open(os.path.join(c1["folder"], "parameters.json")) as f:
    cylinders = json.load(f)["Cylinders"]
length = float(cylinders["length"]) * 1e-3
e, nu = float(cylinders["Young's modulus"]) * 1e9, float(cylinders["Poisson's ratio"])
r1, r2 = float(cylinders["radius 1"]) * 1e-3, float(cylinders["radius 2"]) * 1e-3
g = bench.gearstiff_contact(gearstiff, c1["folder"], approach, length, work, env)
force = abs(c1["force"])
a_hertz, p_hertz = bench.hertz(force / length, r1, r2, e, nu)
print(f"F = {force:.3f} N, approach {approach * 1e6:.4f} um; Hertz a = {a_hertz * 1e3:.5f} mm, "
      f"p0 = {p_hertz / 1e6:.1f} MPa; ccx {c1['time']:.1f} + {c2['time']:.1f} s, "
      f"gearstiff {g['time']:.1f} s, {c1['closed']} / {g['closed']} closed nodes")

checks = Checks("calculix_hertz")
# Same mesh, same approach: the reaction equals ccx's applied force. Measured 2026-11-26:
# +6.1e-6 (docs/calculix.md: 1e-6 at h_c = a/10); tolerance 2e-5.
checks.near("gearstiff reaction / ccx force", g["force"], force, 2e-5)
# Against Hertz at the same load (the fit of p² = p0²(1 − x²/a²) to the closed nodes), measured
# 2026-11-26 on this mesh (21 closed nodes): gearstiff a −0.20 %, p0 +0.048 %; ccx at
# K = 100 E/h_c a +0.50 %, p0 +0.12 % (its penalty lets the edge nodes carry a little pressure,
# which widens the fit). Tolerances three times those.
checks.near("gearstiff half-width / Hertz", g["a"], a_hertz, 0.006)
checks.near("gearstiff peak pressure / Hertz", g["p0"], p_hertz, 0.0015)
a2, p2 = bench.hertz(abs(c2["force"]) / length, r1, r2, e, nu)
checks.near("ccx (K = 100 E/h_c) half-width / Hertz", c2["a"], a2, 0.015)
checks.near("ccx (K = 100 E/h_c) peak pressure / Hertz", c2["p0"], p2, 0.004)
checks.done()
