#!/usr/bin/env python3
"""Claim (docs/biplanetary_dynamics.md, "Natural frequencies"): in the bi-planetary train model
(purely rotational Lin & Parker model, docs/references.md §2 train, FE mean stiffness of its four
meshes) the planet modes are repeated — multiplicity N − 1 = 2 for the three outer planets (Lin
& Parker, J. Vib. Acoust. 121 (1999) 316: a purely rotational model of N equally spaced
planets has planet modes of multiplicity N − 1 that involve neither the central members nor
the carrier), 9125 Hz ×6 (three inner sets of three planets 4, two each) — and suspending ring 7
(variant II, k_s = 1e6 N·m/rad) leaves those modes unchanged (they do not move ring 7), adds one
mode (ring 7's rotation) and puts the lowest mode far below the fixed ring's.

`gearstiff dynamics bench/dynamics_biplanetary.prm` with the FE tables of
bench/biplanetary_meshes/ (as cli.dynamics_biplanetary_fe), ring 7 fixed and suspended.

usage: biplanetary_modes.py GEARSTIFF WORKDIR
"""
import os
import sys

from verify import SOURCE, Checks, column, run_json, work_folder

gearstiff, work = os.path.realpath(sys.argv[1]), work_folder(sys.argv[2])
settings = []
for n, pair in enumerate(["1-2", "3-4", "4-5", "6-7"], start=1):
    settings.append(f"Train mesh {n}/stiffness file="
                    + os.path.join(SOURCE, "bench", "biplanetary_meshes", pair, "sweep.json"))
prm = os.path.join(SOURCE, "bench", "dynamics_biplanetary.prm")


def frequencies(extra):
    summary = run_json(gearstiff, "dynamics", settings + extra, extra=[prm], cwd=work)
    return sorted(f for f in column(summary, "dynamics_modes", "frequency") if f > 1.)


def clusters(values, relative=1e-6):
    """Groups of frequencies equal to `relative`: [(frequency, multiplicity)]."""
    groups = []
    for f in values:
        if groups and abs(f / groups[-1][0] - 1.) <= relative:
            groups[-1][1] += 1
        else:
            groups.append([f, 1])
    return groups


fixed = frequencies([])
suspended = frequencies(["Train/suspended members=7: 1e6 50"])
fixed_groups, suspended_groups = clusters(fixed), clusters(suspended)
print("ring 7 fixed:     " + ", ".join(f"{f:.0f}" + (f" (x{m})" if m > 1 else "") for f, m in fixed_groups))
print("ring 7 suspended: " + ", ".join(f"{f:.0f}" + (f" (x{m})" if m > 1 else "") for f, m in suspended_groups))

checks = Checks("biplanetary_modes")
repeated = [(f, m) for f, m in fixed_groups if m > 1]
# Lin & Parker: the outer planet sets (three planets 2(+3) on carrier h, three carriers H with
# ring 5 and gear 6) give multiplicity-2 modes; the nine planets 4 (three sets of three on the
# carriers H) give a six-fold one (three sets × (3 − 1)). Repeated to round-off of the
# symmetric eigensolver (grouped at 1e-6 relative).
checks.holds("fixed ring: repeated modes are double except one six-fold (planets 4)",
             sorted(m for _, m in repeated) == [2] * (len(repeated) - 1) + [6])
checks.holds("suspension adds exactly one mode", len(suspended) == len(fixed) + 1)
# The repeated modes do not involve ring 7: unchanged by its suspension. Measured 2026-11-26:
# equal to 1e-9 and better; tolerance 1e-6 relative (eigensolver round-off).
suspended_repeated = [(f, m) for f, m in suspended_groups if m > 1]
checks.holds("suspension keeps the multiplicities",
             [m for _, m in suspended_repeated] == [m for _, m in repeated])
for (f, _), (g, _) in zip(repeated, suspended_repeated):
    checks.near(f"repeated mode {f:.0f} Hz, suspended / fixed", g, f, 1e-6)
# docs/biplanetary_dynamics.md: the suspension adds a low ring mode (239 Hz at 1e6 N·m/rad)
# below the fixed ring's first mode (1032 Hz). Both are model results with assumed inertias, no
# published value: regression, measured 2026-11-26 (239.147 and 1032.343 Hz; deterministic
# eigenvalues, tolerance 1e-4).
checks.holds("suspended lowest mode below a third of the fixed ring's lowest",
             suspended[0] < fixed[0] / 3.)
checks.near("suspended lowest mode [Hz] (regression: measured 2026-11-26)", suspended[0], 239.147, 1e-4)
checks.near("fixed lowest mode [Hz] (regression: measured 2026-11-26)", fixed[0], 1032.343, 1e-4)
checks.done()
