#!/usr/bin/env python3
"""gearstiff cycloid-loads against CalculiX on the same mesh (issue 16); run through
bench/calculix_cycloid.sh.

The nominal Cyclo drive of docs/references.md §4 (M_c = 440 N·m) at one crank angle:
  - `gearstiff cycloid-loads` (frictionless dual mortar contact, plane stress Q1, its default
    mesh sizes), and
  - `ccx` on the deck `gearstiff mesh --set "Scene/type=cycloid" --set "Mesh/format=inp"` writes
    from the same scene and sizes (docs/calculix.md: disc bearing and output member as rigid
    bodies, roller pins fixed, one contact pair per roller and per pin, the C3D8 slice in plane
    stress through the plane-strain-equivalent constants), at two contact penalties
    K = f·E/h_c, extrapolated to K → ∞ as x(K) = x_inf + a/K.
Compared: every roller force P_i and pin force Q_j (ccx: the resultant of the pair's contact
forces on the slave surface, *CONTACT PRINT CF), the output rotation θ and the bearing force R
(the disc bearing's reaction). One core each (OMP_NUM_THREADS=1, one MPI rank).

usage: calculix_cycloid.py GEARSTIFF [--crank-angle deg] [--factors f1,f2] [--work DIR]
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys

from calculix_compare import run_timed, value

# mm: stiffness::default_cycloid_load_scene() (cycloid-loads' defaults), which `gearstiff mesh`
# does not share: passed explicitly so both mesh the same scene.
SCENE = {
    "Mesh/contact size": "0.08",
    "Mesh/fine radius": "0.3",
    "Mesh/body size": "2",
    "Mesh/rim size": "8",
    "Mesh/growth rate": "0.4",
    "Cycloid scene/contact clearance": "0.1",
    "Cycloid scene/outline points per lobe": "61",
}
ROLLERS = 20  # z_k, docs/references.md §4
ARCMIN = math.pi / (180. * 60.)


def table_column(table, column):
    index = table["columns"].index(column)
    return [row[index] for row in table["rows"]]


def gearstiff_loads(gearstiff, crank, env):
    command = [gearstiff, "cycloid-loads", "--json", "--set", "Cycloid loads/profiles=nominal",
               "--set", "Cycloid loads/torsional curve=false",
               "--set", f"Cycloid loads/crank angle={crank:.12g}",
               # the deck's CPS4 elements are bilinear: Q1 here too (cycloid-loads' default is Q2)
               "--set", "Finite elements/Element degree=1"]
    for key, v in SCENE.items():
        command += ["--set", f"{key}={v}"]
    stdout, wall, memory, stderr = run_timed(command, env=env)
    summary = json.loads(stdout[stdout.index("{"):])
    values, tables = summary["values"], summary["tables"]
    # "case 1/1: ..., 46556 DoFs, 11.9 s (scene 6.4 s, setup 0.087 s, solve 5.2 s)"
    times = re.search(r"scene ([0-9.e+-]+) s, setup ([0-9.e+-]+) s, solve ([0-9.e+-]+) s",
                      stderr + stdout)
    scene, setup, solve = (float(t) for t in times.groups())
    return {
        "rollers": table_column(tables["cycloid_rollers"], "force_nominal"),
        "pins": table_column(tables["cycloid_pins"], "force_nominal"),
        "theta": value(values, "output_rotation") * ARCMIN,  # rad
        "bearing": value(values, "bearing_force"),
        "dofs": value(values, "n_dofs"),
        "iterations": value(values, "active_set_iterations"),
        "scene": scene, "fe": setup + solve, "time": wall, "memory": memory,
    }


def read_dat(dat):
    """Last printed value of each block: rotations of the *_ROT sets, forces of the *_REF sets
    and per contact pair (slave set name) the total force on the slave surface."""
    rotations, reactions, pairs = {}, {}, {}
    lines = open(dat).read().splitlines()
    numbers = lambda k: [float(x) for x in lines[k].split()]
    for i, line in enumerate(lines):
        m = re.match(r"\s*displacements \(vx,vy,vz\) for set (\S+) and time", line)
        if m:
            rotations[m.group(1)] = numbers(i + 2)[3]
        m = re.match(r"\s*forces \(fx,fy,fz\) for set (\S+) and time", line)
        if m:
            reactions[m.group(1)] = numbers(i + 2)[1:3]
        m = re.match(r"\s*statistics for slave set (\S+), master set", line)
        if m:
            fx, fy = numbers(i + 4)[:2]
            pairs[m.group(1)] = math.hypot(fx, fy)
    return rotations, reactions, pairs


def calculix_loads(gearstiff, crank, factor, work, env):
    folder = os.path.join(work, f"cycloid_f{factor:g}")
    # The disc rotation of the crank angle (geometry/cycloid_disc.h: ψ = (π − φ_h)/(z_k − 1)).
    psi = (180. - crank) / (ROLLERS - 1)
    command = [gearstiff, "mesh", "-o", folder, "--set", "Scene/type=cycloid",
               "--set", "Mesh/format=inp", "--set", f"Abaqus deck/penalty factor={factor:g}",
               "--set", f"Cycloid scene/disc rotation={psi:.17g}"]
    for key, v in SCENE.items():
        command += ["--set", f"{key}={v}"]
    subprocess.run(command, check=True, capture_output=True)
    stdout, wall, memory, _ = run_timed(["ccx", "-i", "scene"], cwd=folder, env=env)
    own = re.search(r"Total CalculiX Time:\s*([0-9.eE+-]+)", stdout)
    rotations, reactions, pairs = read_dat(os.path.join(folder, "scene.dat"))
    with open(os.path.join(folder, "scene.sta")) as f:
        iterations = sum(int(l.split()[3]) for l in f if re.match(r"\s+\d+\s+\d+\s+\d+\s+\d+", l))
    nodes, in_nodes = 0, False
    with open(os.path.join(folder, "scene.inp")) as f:
        for line in f:
            if line.startswith("*"):
                in_nodes = line.startswith("*NODE,")
            elif in_nodes:
                nodes += 1
    pins = sum(1 for name in pairs if name.startswith("PIN_"))
    return {
        "rollers": [pairs.get(f"ROLLER_{i}", 0.) for i in range(ROLLERS)],
        "pins": [pairs[f"PIN_{j}"] for j in range(pins)],
        "theta": rotations["OUTPUT_ROT"],
        "bearing": math.hypot(*reactions["DISC_BEARING_REF"]),
        "time": wall, "own_time": float(own.group(1)) if own else float("nan"),
        "memory": memory, "iterations": iterations, "nodes": nodes,
    }


def extrapolate(factors, x1, x2):
    """x(K) = x_inf + a/K through (f1, x1), (f2, x2)."""
    f1, f2 = factors
    return (f1 * x1 - f2 * x2) / (f1 - f2)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("gearstiff")
    parser.add_argument("--crank-angle", type=float, default=0., help="φ_h (degrees)")
    parser.add_argument("--factors", default="10,100", help="penalty factors f (K = f·E/h_c)")
    parser.add_argument("--work", default="calculix-cycloid-work")
    args = parser.parse_args()
    factors = [float(f) for f in args.factors.split(",")][:2]
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
    os.makedirs(args.work, exist_ok=True)

    g = gearstiff_loads(args.gearstiff, args.crank_angle, env)
    runs = [calculix_loads(args.gearstiff, args.crank_angle, f, args.work, env) for f in factors]
    # The same mesh: the deck's nodes (two layers of the slice plus four rigid-body nodes) are
    # the DoFs of the 2D mesh (two per node) plus four.
    if runs[0]["nodes"] != g["dofs"] + 4:
        sys.exit(f"calculix_cycloid: the deck has {runs[0]['nodes']} nodes, expected "
                 f"{g['dofs'] + 4:.0f} (2D DoFs + 4): not the same mesh")

    def inf(key, index=None):
        pick = (lambda r: r[key]) if index is None else (lambda r: r[key][index])
        return extrapolate(factors, pick(runs[0]), pick(runs[1]))

    head = "".join(f" {'ccx f=%g' % f:>10s}" for f in factors)
    print(f"cycloid drive (docs/references.md §4, nominal), crank angle {args.crank_angle:g} deg, "
          f"M_c = 440 N·m, {g['dofs']:.0f} DoFs (2D), plane stress Q1 / C3D8 slice")
    print(f"  {'':10s} {'gearstiff':>10s}{head} {'ccx K->inf':>10s} {'diff %':>8s}")

    def row(label, x, ys, y_inf, scale=1., fmt="10.1f"):
        diff = (x / y_inf - 1) * 100 if abs(y_inf) > 1e-9 * max(abs(x), 1.) else float("nan")
        cells = "".join(f" {y * scale:{fmt}}" for y in ys)
        print(f"  {label:10s} {x * scale:{fmt}}{cells} {y_inf * scale:{fmt}} {diff:+8.2f}")

    for i in range(ROLLERS):
        row(f"P_{i} N", g["rollers"][i], [r["rollers"][i] for r in runs], inf("rollers", i))
    for j in range(len(g["pins"])):
        row(f"Q_{j} N", g["pins"][j], [r["pins"][j] for r in runs], inf("pins", j))
    row("R N", g["bearing"], [r["bearing"] for r in runs], inf("bearing"))
    row("theta '", g["theta"], [r["theta"] for r in runs], inf("theta"), 1. / ARCMIN, "10.5f")
    p_max = max(range(ROLLERS), key=lambda i: g["rollers"][i])
    q_max = max(range(len(g["pins"])), key=lambda j: g["pins"][j])
    print(f"  wall s     {g['time']:10.2f}" + "".join(f" {r['time']:10.2f}" for r in runs))
    print(f"  RSS MB     {g['memory']:10.0f}" + "".join(f" {r['memory']:10.0f}" for r in runs))
    print(f"  iterations {g['iterations']:10.0f}" + "".join(f" {r['iterations']:10.0f}" for r in runs)
          + "   (gearstiff: active-set iterations; ccx: Newton iterations, both steps)")
    ccx = sum(r["time"] for r in runs) / len(runs)
    print(f"  times: gearstiff process {g['time']:.2f} s = meshing {g['scene']:.2f} s + FE "
          f"(read, setup, contact solve) {g['fe']:.2f} s + start-up and output; "
          f"ccx process {ccx:.2f} s per solve (mean of the penalties; its own total "
          f"{sum(r['own_time'] for r in runs) / len(runs):.2f} s)")
    print(f"  time ratio ccx process / gearstiff process without meshing "
          f"({g['time'] - g['scene']:.2f} s): {ccx / (g['time'] - g['scene']):.1f}x; "
          f"/ gearstiff FE {ccx / g['fe']:.1f}x; / gearstiff process {ccx / g['time']:.1f}x")
    print(f"calculix_cycloid: P_max gearstiff {g['rollers'][p_max]:.1f} N, CalculiX "
          f"{inf('rollers', p_max):.1f} N ({(g['rollers'][p_max] / inf('rollers', p_max) - 1) * 100:+.2f} %), "
          f"Q_max {g['pins'][q_max]:.1f} N, {inf('pins', q_max):.1f} N "
          f"({(g['pins'][q_max] / inf('pins', q_max) - 1) * 100:+.2f} %), theta "
          f"{(g['theta'] / inf('theta') - 1) * 100:+.2f} %, time ratio "
          f"{ccx / (g['time'] - g['scene']):.1f}x")


if __name__ == "__main__":
    main()
