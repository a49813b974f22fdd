#!/usr/bin/env python3
"""gearstiff against CalculiX on the same mesh (issue 16); run through bench/calculix_compare.sh.

For the single- and double-pair positions of the split-path pair (docs/references.md §1) the scene of
`gearstiff stiffness` (full rims, three teeth per gear, its explicit sizes) is solved
  - by `gearstiff stiffness` with FE_Q(1) (the element ccx's C3D8 slice reproduces exactly), and
  - by `ccx` on the deck `gearstiff mesh --set "Mesh/format=inp"` writes from the same mesh
    (docs/calculix.md), at two contact penalties K = f·E/h_c; k(K) = k_inf + a/K, so the
    penalty-free value is k_inf = (f1·k1 − f2·k2)/(f1 − f2).
k = T1/(r_b1²·Δφ) (docs/references.md §1), Δφ from the rigid body's rotation node. Both solvers run on
one core (one MPI rank; OMP_NUM_THREADS=1). Peak memory is the process's maximum resident set.
Time ratio R (last line) = one ccx process (mean of the penalties) / the gearstiff process
without its meshing (process wall time − its in-process meshing time): both from a finished
mesh. Printed beside it: against the whole gearstiff process, and against gearstiff's FE time on
the mesh (reading, setup, contact solve; in-process timers).

usage: calculix_compare.py GEARSTIFF [--size-scale s] [--factors f1,f2] [--work DIR]
       [--positions single,double] [--csv FILE] [--internal]
With --internal the wheel is the ring of docs/references.md §2's planetary stage geometry as
`gearstiff stiffness` builds it for `Gear pair/Wheel/internal=true` (docs/internal-gears.md): the
same comparison for a ring–planet pair.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from calculix_stiffness import last_rotation  # noqa: E402  (one reader of ccx's rotation)

SIZES = {  # mm: stiffness::default_stiffness_scene()
    "Mesh/contact size": 0.03,
    "Mesh/fine radius": 0.15,
    "Mesh/body size": 0.7,
    "Mesh/rim size": 2.8,
    "Mesh/growth rate": 0.35,
}
# bench/accuracy_cost.py's size field (its factor scales every entry, the growth rate too).
LADDER_SIZES = {"Mesh/contact size": 0.04, "Mesh/body size": 1.0, "Mesh/rim size": 4.0,
                "Mesh/growth rate": 0.5}
SCENE = ["Gear pair scene/rim=full", "Gear pair scene/pinion teeth modelled=3",
         "Gear pair scene/wheel teeth modelled=3"]
# tests/stiffness/test_internal_mesh_stiffness.cc's ring-planet pair: planet 24 / ring 69,
# m = 2.5 mm, ring tip at an addendum of 0.5·m (a standard ring tip interferes), rim 5·m.
INTERNAL = ["Gear pair/Pinion/teeth=24", "Gear pair/Wheel/teeth=69",
            "Gear pair/Pinion/tip diameter=0", "Gear pair/Wheel/internal=true",
            "Gear pair/Wheel/tip diameter=170", "Gear pair/Wheel/bore diameter=0",
            "Gear pair scene/wheel rim thickness=12.5"]
ANSYS_SINGLE = 327.222  # N/um, docs/references.md §1 k'_j


def scene_settings(sizes, scale):
    settings = list(SCENE)
    for key, value in sizes.items():
        settings.append(f"{key}={value * scale:.6g}")
    return settings


def run_timed(command, cwd=None, env=None):
    """Runs `command` under GNU time: (stdout, wall s, peak resident MB, stderr)."""
    marker = "@@calculix_compare"
    full = ["/usr/bin/time", "-f", f"{marker} %e %M"] + command
    process = subprocess.run(full, cwd=cwd, env=env, capture_output=True, text=True)
    if process.returncode != 0:
        sys.exit(f"{os.path.basename(sys.argv[0])}: {' '.join(command)} failed ({process.returncode}):\n"
                 + process.stderr[-2000:] + process.stdout[-2000:])
    line = [l for l in process.stderr.splitlines() if l.startswith(marker)][-1]
    wall, kbytes = line.split()[1:3]
    return process.stdout, float(wall), float(kbytes) / 1024., process.stderr


def value(summary, key):
    entry = summary[key]
    return entry["value"] if isinstance(entry, dict) else entry


def gearstiff_position(gearstiff, position, settings, friction, env):
    command = [gearstiff, "stiffness", "--json", "--set", f"Stiffness/mode={position}",
               "--set", "Finite elements/Element degree=1",
               "--set", f"Contact/Friction coefficient={friction:g}"]
    for s in settings:
        command += ["--set", s]
    stdout, wall, memory, _ = run_timed(command, env=env)
    summary = json.loads(stdout[stdout.index("{"):])
    values = summary.get("values", summary)
    return {
        "k": value(values, "mesh_stiffness"),                 # N/µm
        "rotation": value(values, "pinion_rotation"),         # µrad
        "pressure": value(values, "max_contact_pressure"),    # MPa
        "root": value(values, "pinion_root_stress"),          # MPa
        "cells": value(values, "cells"),
        "dofs": value(values, "dofs"),
        # In-process timers: meshing (gmsh, writing the .msh), and the FE work on the finished
        # mesh (reading it, DoFs, stiffness, mortar coupling, contact iterations).
        "scene": value(values, "time_scene"),
        "fe": value(values, "time_setup") + value(values, "time_solve"),
        "time": wall, "memory": memory,
    }


def read_deck(deck):
    """Nodes (id -> (x, y)), C3D8 connectivity per element set, the rotation node's id."""
    nodes, sets, current, rot = {}, {}, None, None
    with open(deck) as f:
        for line in f:
            if line.startswith("**"):
                continue
            if line.startswith("*"):
                current = line.strip().upper()
                if current.startswith("*ELEMENT"):
                    name = current.split("ELSET=")[1].split(",")[0]
                    sets[name] = []
                    current = ("ELEMENT", name)
                elif current.startswith("*RIGID BODY"):
                    rot = int(current.split("ROT NODE=")[1].split(",")[0])
                continue
            parts = [p.strip() for p in line.split(",")]
            if current == "*NODE, NSET=NALL":
                nodes[int(parts[0])] = (float(parts[1]), float(parts[2]))
            elif isinstance(current, tuple):
                sets[current[1]].append([int(p) for p in parts[1:]])
    return nodes, sets, rot


def frd_blocks(frd, names):
    """The last nodal result block of each name in `names`: name -> {node: [values]}."""
    blocks, current, data = {}, None, None
    with open(frd) as f:
        for line in f:
            if line.startswith(" -4"):
                name = line.split()[1]
                current = name if name in names else None
                data = {}
            elif current and line.startswith(" -1"):
                node = int(line[3:13])
                text = line[13:].rstrip("\n")
                data[node] = [float(text[i:i + 12]) for i in range(0, len(text), 12)]
            elif current and line.startswith(" -3"):
                blocks[current] = data
                current = None
    return blocks


def fillet_nodes(nodes, elements, root, form):
    """Bottom-layer pinion nodes on the free outline between the root and form circles."""
    count = {}
    for element in elements:
        bottom = element[:4]
        for i in range(4):
            edge = tuple(sorted((bottom[i], bottom[(i + 1) % 4])))
            count[edge] = count.get(edge, 0) + 1
    outline = {n for edge, c in count.items() if c == 1 for n in edge}
    result = []
    for n in outline:
        r = math.hypot(*nodes[n])
        if root * (1 - 1e-6) <= r <= form and abs(r - root) > 1e-9:
            result.append(n)
    return result


def calculix_position(gearstiff, position, settings, friction, factor, work, env, radii):
    folder = os.path.join(work, f"{position}_f{factor:g}")
    command = [gearstiff, "mesh", "-o", folder, "--set", f"Gear pair scene/position={position}",
               "--set", "Mesh/format=inp", "--set", f"Abaqus deck/penalty factor={factor:g}",
               "--set", f"Abaqus deck/friction coefficient={friction:g}"]
    for s in settings:
        command += ["--set", s]
    subprocess.run(command, check=True, capture_output=True)
    stdout, wall, memory, _ = run_timed(["ccx", "-i", "scene"], cwd=folder, env=env)
    own = [l for l in stdout.splitlines() if l.startswith("Total CalculiX Time:")]
    nodes, sets, rot = read_deck(os.path.join(folder, "scene.inp"))
    rotation = last_rotation(os.path.join(folder, "scene.dat"), rot)
    blocks = frd_blocks(os.path.join(folder, "scene.frd"), {"STRESS", "CONTACT"})
    # CONTACT: COPEN, CSLIP1, CSLIP2, CPRESS, CSHEAR1, CSHEAR2
    pressure = max((v[3] for v in blocks.get("CONTACT", {}).values()), default=float("nan"))
    root_stress = 0.
    for n in fillet_nodes(nodes, sets["PINION_BODY"], *radii):
        sxx, syy, _, sxy = blocks["STRESS"][n][:4]
        root_stress = max(root_stress, 0.5 * (sxx + syy) + math.hypot(0.5 * (sxx - syy), sxy))
    return {"rotation": rotation, "pressure": pressure / 1e6, "root": root_stress / 1e6,
            "time": wall, "memory": memory, "dofs": 3 * len(nodes),
            "own_time": float(own[-1].split(":")[1]) if own else float("nan")}


def single_pair_against_ccx(gearstiff, settings, work, env, factors=(10., 100.)):
    """The split-path pair (T1 = 49.4 N·m, docs/references.md §1) at the single-pair position,
    frictionless: gearstiff Q1 and ccx on its deck at the penalty factors `factors`, and ccx's k
    extrapolated to K -> inf in 1/K. Returns (gearstiff run, ccx k per factor, k_inf, ccx runs)."""
    pair = json.loads(subprocess.run([gearstiff, "gear-pair", "--json", "--quiet"], check=True,
                                     capture_output=True, text=True).stdout)["values"]
    r_b1 = 1e-3 * value(pair, "pinion_base_radius")
    radii = (0.5e-3 * value(pair, "pinion_root_diameter"),
             0.5e-3 * value(pair, "pinion_form_diameter"))
    torque = 49.4  # N·m, T1 of both commands
    g = gearstiff_position(gearstiff, "single", settings, 0., env)
    runs = [calculix_position(gearstiff, "single", settings, 0., f, work, env, radii)
            for f in factors]
    ks = [torque / (r_b1 ** 2 * run["rotation"]) / 1e6 for run in runs]
    k_inf = (factors[0] * ks[0] - factors[1] * ks[1]) / (factors[0] - factors[1])
    return g, ks, k_inf, runs


def append_csv(path, header):
    """`path` opened for appending rows; a new file starts with the `header` line."""
    new = not os.path.exists(path)
    out = open(path, "a")
    if new:
        out.write(header + "\n")
    return out


def write_accuracy_rows(args, rows):
    """The single-pair CalculiX point (penalty-corrected; its cost: both penalty solves) and the
    gearstiff point of the same run, in bench/accuracy_results.csv's columns."""
    with append_csv(args.accuracy_csv,
                    "variant,teeth,degree,model,size_factor,stiffness,iso,dofs,solve_time,"
                    "wall_time,error_own_converged,error_reference,error_ansys") as out:
        for position, g, runs, ks, k_inf in rows:
            if position != "single":
                continue
            cost = sum(run["time"] for run in runs)
            for name, k, time_s, dofs in (
                    ("CalculiX C3D8 slice K->inf (2 ccx processes)", k_inf, cost, runs[0]["dofs"]),
                    ("gearstiff Q1 same meshes (whole process)", g["k"], g["time"], g["dofs"])):
                error = abs(k / args.reference - 1) if args.reference > 0 else float("nan")
                out.write(f"{name},3,1,plane strain,{args.size_scale:g},{k:.9g},nan,"
                          f"{dofs:.0f},{time_s:.3f},{time_s:.3f},nan,{error:.6g},"
                          f"{abs(k / ANSYS_SINGLE - 1):.6g}\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("gearstiff")
    parser.add_argument("--size-scale", type=float, default=1.0,
                        help="scale of every mesh size of the default stiffness scene")
    parser.add_argument("--factors", default="10,100", help="penalty factors f (K = f·E/h_c)")
    parser.add_argument("--positions", default="single,double")
    parser.add_argument("--work", default="calculix-work")
    parser.add_argument("--friction", type=float, default=0.01,
                        help="Coulomb μ of both solvers (docs/references.md §1: 0.01)")
    parser.add_argument("--csv", default="", help="append one row per position to this CSV")
    parser.add_argument("--ladder", action="store_true",
                        help="bench/accuracy_cost.py's size field (scaled by --size-scale), μ = 0")
    parser.add_argument("--accuracy-csv", default="",
                        help="append the penalty-corrected CalculiX single-pair point in "
                             "bench/accuracy_results.csv's columns to this file")
    parser.add_argument("--extra", action="append", default=[], metavar="SECTION/KEY=VALUE",
                        help="a further setting of both solvers' scene (repeatable)")
    parser.add_argument("--internal", action="store_true",
                        help="an internal wheel (ring-planet pair, docs/internal-gears.md)")
    parser.add_argument("--reference", type=float, default=0.,
                        help="converged k (N/um) for the accuracy CSV's error_reference")
    args = parser.parse_args()
    if args.ladder:
        args.friction = 0.
    factors = [float(f) for f in args.factors.split(",")]
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
    settings = scene_settings(LADDER_SIZES if args.ladder else SIZES, args.size_scale)
    if args.internal:
        settings += INTERNAL
    settings += args.extra
    os.makedirs(args.work, exist_ok=True)

    pair_command = [args.gearstiff, "gear-pair", "--json"]
    for s in settings:
        if s.startswith("Gear pair/"):
            pair_command += ["--set", s]
    pair = json.loads(subprocess.run(pair_command, check=True,
                                     capture_output=True, text=True).stdout)["values"]
    r_b1 = 1e-3 * value(pair, "pinion_base_radius")
    root = 0.5e-3 * value(pair, "pinion_root_diameter")
    form = 0.5e-3 * value(pair, "pinion_form_diameter")
    torque = 49.4  # N·m, the default T1 of both commands (docs/references.md §1)

    rows, headline = [], None
    times = {"gearstiff": 0., "gearstiff_scene": 0., "gearstiff_fe": 0., "ccx": 0., "ccx_own": 0.}
    for position in args.positions.split(","):
        g = gearstiff_position(args.gearstiff, position, settings, args.friction, env)
        runs = [calculix_position(args.gearstiff, position, settings, args.friction, f,
                                  args.work, env, (root, form)) for f in factors]
        ks = [torque / (r_b1 ** 2 * run["rotation"]) / 1e6 for run in runs]  # N/µm
        f1, f2 = factors[0], factors[-1]
        k_inf = (f1 * ks[0] - f2 * ks[-1]) / (f1 - f2)
        print(f"{position} pair, {g['cells']:.0f} cells, FE_Q(1) / C3D8 slice:")
        print(f"  {'':24s} {'k N/um':>9s} {'dphi urad':>10s} {'p_max MPa':>10s}"
              f" {'root MPa':>9s} {'wall s':>8s} {'RSS MB':>8s}")
        print(f"  {'gearstiff (dual mortar)':24s} {g['k']:9.3f} {g['rotation']:10.3f}"
              f" {g['pressure']:10.1f} {g['root']:9.1f} {g['time']:8.2f} {g['memory']:8.0f}")
        for f, k, run in zip(factors, ks, runs):
            print(f"  {'ccx, K = %g E/h_c' % f:24s} {k:9.3f} {run['rotation'] * 1e6:10.3f}"
                  f" {run['pressure']:10.1f} {run['root']:9.1f} {run['time']:8.2f}"
                  f" {run['memory']:8.0f}")
        print(f"  {'ccx, K -> infinity':24s} {k_inf:9.3f} {torque / (r_b1**2 * k_inf * 1e6) * 1e6:10.3f}")
        print(f"  gearstiff / ccx(K->inf) - 1 = {(g['k'] / k_inf - 1) * 100:+.2f} %")
        print(f"  times: gearstiff process {g['time']:.2f} s = meshing {g['scene']:.2f} s"
              f" + FE on the mesh (read, setup, contact solve) {g['fe']:.2f} s"
              f" + start-up and output {g['time'] - g['scene'] - g['fe']:.2f} s; ccx process"
              + "".join(f" {run['time']:.2f} s (own {run['own_time']:.2f} s)" for run in runs))
        times["gearstiff"] += g["time"]
        times["gearstiff_scene"] += g["scene"]
        times["gearstiff_fe"] += g["fe"]
        times["ccx"] += sum(run["time"] for run in runs) / len(runs)
        times["ccx_own"] += sum(run["own_time"] for run in runs) / len(runs)
        rows.append((position, g, runs, ks, k_inf))
        if headline is None:
            headline = (g["k"], k_inf)
    if args.csv:
        with append_csv(args.csv, "position,size_scale,cells,solver,penalty_factor,"
                        "k_N_per_um,wall_s,memory_MB") as out:
            for position, g, runs, ks, k_inf in rows:
                out.write(f"{position},{args.size_scale},{g['cells']:.0f},gearstiff,,"
                          f"{g['k']:.6g},{g['time']:.3f},{g['memory']:.0f}\n")
                for f, k, run in zip(factors, ks, runs):
                    out.write(f"{position},{args.size_scale},{g['cells']:.0f},ccx,{f:g},"
                              f"{k:.6g},{run['time']:.3f},{run['memory']:.0f}\n")
                out.write(f"{position},{args.size_scale},{g['cells']:.0f},ccx,inf,{k_inf:.6g},,\n")
    if args.accuracy_csv:
        write_accuracy_rows(args, rows)
    x, y = headline
    # Both from a finished mesh: the ccx process (reads the deck, solves, writes) against the
    # gearstiff process without its meshing (start-up, reading the .msh, solve, output) — ccx
    # gets its mesh from the deck, gearstiff meshes in-process. The other two ratios beside it.
    finished = times["gearstiff"] - times["gearstiff_scene"]
    ratio = times["ccx"] / finished
    print(f"time ratio (one ccx solve, mean of the penalties, summed over the positions):")
    print(f"  ccx process {times['ccx']:.2f} s / gearstiff process without meshing "
          f"{finished:.2f} s = {ratio:.1f}x (headline)")
    print(f"  ccx process / gearstiff whole process {times['gearstiff']:.2f} s = "
          f"{times['ccx'] / times['gearstiff']:.1f}x")
    print(f"  ccx process / gearstiff FE on the mesh {times['gearstiff_fe']:.2f} s = "
          f"{times['ccx'] / times['gearstiff_fe']:.1f}x (ccx's own total {times['ccx_own']:.2f} s)")
    print(f"calculix_compare: k gearstiff {x:.3f} N/um, CalculiX {y:.3f} N/um "
          f"({(x / y - 1) * 100:+.2f} %), time ratio {ratio:.1f}x")


if __name__ == "__main__":
    main()
