#!/usr/bin/env python3
"""Claim (docs/calculix.md, "Cycloid drive"): on the same mesh gearstiff's roller and pin forces
equal CalculiX's penalty-corrected ones (P_max −0.28 %, Q_max −0.00 %, θ +0.03 % on the
cycloid-loads mesh).

The nominal drive of docs/references.md §4 (M_c = 440 N·m, crank angle 0, frictionless, plane
stress, Q1 — the order of the deck's elements) on a coarser mesh than cycloid-loads' default (h_c = 0.12 mm, body 3 mm, 33 388 DoFs; the
default's ccx solves take ~30 s each; at h_c = 0.2 mm the coarse chords leave an output pin
untouched and the FE solve has a free body),
solved by `gearstiff cycloid-loads` and by ccx on the deck `gearstiff mesh` writes from the same
scene at K = 10 and 100 E/h_c, extrapolated to K → ∞ in 1/K (bench/calculix_cycloid.py, whose
functions this test calls; it checks that the deck's nodes are the 2D mesh's).

usage: calculix_cycloid.py GEARSTIFF WORKDIR
"""
import concurrent.futures
import os
import sys

from verify import Checks, require_ccx, work_folder

require_ccx()
import calculix_cycloid as bench  # noqa: E402  (bench/, on the path through verify)

gearstiff, work = os.path.realpath(sys.argv[1]), work_folder(sys.argv[2])
bench.SCENE = {
    "Mesh/contact size": "0.12",
    "Mesh/fine radius": "0.3",
    "Mesh/body size": "3",
    "Mesh/rim size": "8",
    "Mesh/growth rate": "0.4",
    "Cycloid scene/contact clearance": "0.1",
    "Cycloid scene/outline points per lobe": "61",
}
env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
factors = (10., 100.)
g = bench.gearstiff_loads(gearstiff, 0., env)
# The two penalty solves run side by side (one core each; the test reserves two): ~35 s wall.
with concurrent.futures.ThreadPoolExecutor(2) as pool:
    runs = list(pool.map(lambda f: bench.calculix_loads(gearstiff, 0., f, work, env), factors))
if runs[0]["nodes"] != g["dofs"] + 4:
    sys.exit(f"calculix_cycloid: the deck has {runs[0]['nodes']} nodes, expected "
             f"{g['dofs'] + 4:.0f} (2D DoFs + 4): not the same mesh")


def extrapolated(pick):
    return bench.extrapolate(factors, pick(runs[0]), pick(runs[1]))


p = max(range(len(g["rollers"])), key=lambda i: g["rollers"][i])
q = max(range(len(g["pins"])), key=lambda j: g["pins"][j])
print(f"{g['dofs']:.0f} DoFs; gearstiff {g['time']:.1f} s, ccx {runs[0]['time']:.1f} + "
      f"{runs[1]['time']:.1f} s")
checks = Checks("calculix_cycloid")
# Measured 2026-11-26 on this mesh: P_max +0.41 %, Q_max −0.018 %, θ +0.13 %, R −0.039 %
# (docs/calculix.md on the default mesh: −0.28 %, −0.00 %, +0.03 %, −0.19 %). ccx's own scatter
# is ~0.3 %: its Newton iteration stops at a residual of 0.5 % of the mean force, and its P_i and
# R move by up to 0.3 % between penalties without a 1/K trend (docs/calculix.md). Tolerances:
# three times the measured difference, but not below that 0.3 % for P, θ and R; Q_max, which
# agrees to 0.02 % on both meshes, to 0.1 %: five times the measured, not below the 1/K
# extrapolation's own ~0.1 % (calculix_gear_pair.py).
checks.near(f"P_max (roller {p}) gearstiff / ccx", g["rollers"][p],
            extrapolated(lambda r: r["rollers"][p]), 0.012)
checks.near(f"Q_max (pin {q}) gearstiff / ccx", g["pins"][q], extrapolated(lambda r: r["pins"][q]),
            0.001)
checks.near("output rotation gearstiff / ccx", g["theta"], extrapolated(lambda r: r["theta"]), 0.004)
checks.near("bearing force gearstiff / ccx", g["bearing"], extrapolated(lambda r: r["bearing"]),
            0.003)
checks.done()
