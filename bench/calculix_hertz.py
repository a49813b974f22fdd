#!/usr/bin/env python3
"""The Hertz cylinders scene solved by ccx and by gearstiff on the same mesh, beside Hertz's
half-width and peak pressure (issue 16, docs/calculix.md); run through bench/calculix_hertz.sh.

`gearstiff mesh --set "Scene/type=cylinders"` writes the scene (R1 = R2 = 10 mm, F' = 100 N/mm,
L = 10 mm, steel, plane strain; h_c = a/10) as .msh and as a deck (cylinder 1's flat face fixed,
cylinder 2's flat face a rigid body pushed by F = F'·L, frictionless here as Hertz's theory):
  - ccx solves the deck at two penalties K = f·E/h_c; the approach δ of the pushed face is
    extrapolated in 1/K (δ(K) = δ∞ + c/K);
  - `gearstiff contact` (FE_Q(1), the element the C3D8 slice reproduces) solves the same .msh with
    cylinder 1's flat face fixed and cylinder 2's moved rigidly by δ∞: its reaction F_gs against
    F is the same-mesh stiffness check;
  - half-width a and peak pressure p0 of both from a least-squares fit of p² = p0²(1 − x²/a²) to
    the closed nodes (as `gearstiff contact`'s built-in case), the nodal maximum beside it, and
    Hertz's (Johnson 1985 eq. 4.43, 4.45) at each solver's own load.
Wall times: processes under GNU time, one core each (OMP_NUM_THREADS=1, one MPI rank).

usage: calculix_hertz.py GEARSTIFF [--factors f1,f2] [--work DIR] [--extra "Key=value" ...]
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

from calculix_compare import frd_blocks, read_deck, run_timed, value


def fit_hertz(x, p):
    """(a, p0) of the least-squares fit p² = p0² − (p0²/a²)·x² (contact/cylinder_pair.cc)."""
    s0, s1, s2 = len(x), sum(v * v for v in x), sum(v ** 4 for v in x)
    t0 = sum(q * q for q in p)
    t1 = sum(q * q * v * v for q, v in zip(p, x))
    det = s0 * s2 - s1 * s1
    squared_peak = (s2 * t0 - s1 * t1) / det
    slope = -(s0 * t1 - s1 * t0) / det
    return math.sqrt(squared_peak / slope), math.sqrt(squared_peak)


def hertz(force_per_length, r1, r2, e, nu):
    """Plane-strain Hertz half-width and peak pressure (Johnson 1985 eq. 4.43, 4.45)."""
    e_star = e / (2. * (1. - nu * nu))
    r_star = r1 * r2 / (r1 + r2)
    a = math.sqrt(4. * force_per_length * r_star / (math.pi * e_star))
    return a, 2. * force_per_length / (math.pi * a)


def deck_approach(dat):
    """u_y of UPPER_REF in the last printed increment (m), and the contact force (N)."""
    approach, force, block = None, None, ""
    with open(dat) as f:
        for line in f:
            if " for set " in line or "total surface force" in line:
                block = line
                continue
            parts = line.split()
            if len(parts) >= 3 and "displacements" in block and "UPPER_REF" in block:
                approach = -float(parts[2])
            elif len(parts) >= 2 and "total surface force" in block:
                force, block = float(parts[1]), ""
    return approach, force


def calculix(gearstiff, factor, work, extra, env):
    folder = os.path.join(work, f"ccx_f{factor:g}")
    command = [gearstiff, "mesh", "-o", folder, "--set", "Scene/type=cylinders",
               "--set", "Mesh/format=msh and inp", "--set", f"Abaqus deck/penalty factor={factor:g}",
               "--set", "Abaqus deck/friction coefficient=0"]
    for s in extra:
        command += ["--set", s]
    out = subprocess.run(command + ["--json"], check=True, capture_output=True, text=True).stdout
    scene = json.loads(out[out.index("{"):])
    scene = scene.get("values", scene)
    _, wall, memory, _ = run_timed(["ccx", "-i", "scene"], cwd=folder, env=env)
    nodes, sets, _ = read_deck(os.path.join(folder, "scene.inp"))
    approach, force = deck_approach(os.path.join(folder, "scene.dat"))
    contact = frd_blocks(os.path.join(folder, "scene.frd"), {"CONTACT"}).get("CONTACT", {})
    # CONTACT: COPEN, CSLIP1, CSLIP2, CPRESS, ...; the z = 0 layer (ids up to the 2D node count).
    layer = (len(nodes) - 2) // 2
    closed = [(nodes[n][0], v[3]) for n, v in contact.items() if n <= layer and v[3] > 0.]
    a, p0 = fit_hertz([x for x, _ in closed], [p for _, p in closed])
    return {"folder": folder, "scene": scene, "approach": approach, "force": force, "a": a,
            "p0": p0, "pmax": max(p for _, p in closed), "closed": len(closed), "time": wall,
            "memory": memory, "dofs": 3 * (len(nodes) - 2)}


def gearstiff_contact(gearstiff, folder, approach, length, work, env):
    out_folder = os.path.join(work, "gearstiff")
    command = [gearstiff, "contact", "--json", "-o", out_folder,
               "--set", f"Mesh/File={os.path.join(folder, 'scene.msh')}",
               "--set", "Mesh/Length unit=1", "--set", "Bodies/Names=cylinder 1, cylinder 2",
               "--set", "Contact/Slave surfaces=cylinder 2 surface",
               "--set", "Contact/Master surfaces=cylinder 1 surface",
               "--set", "Supports/Fixed=cylinder 1 flat face",
               "--set", f"Supports/Displacements=cylinder 2 flat face: 0, {-approach * 1e3:.9g}",
               "--set", f"Finite elements/Thickness={length * 1e3:g}",
               "--set", "Finite elements/Element degree=1", "--set", "Output/VTU=false"]
    stdout, wall, memory, _ = run_timed(command, env=env)
    summary = json.loads(stdout[stdout.index("{"):])
    values = summary.get("values", summary)
    x, p = [], []
    with open(os.path.join(out_folder, "contact_surface.csv")) as f:
        for row in csv.DictReader(f):
            if int(row["state"]) != 0:
                x.append(float(row["x_mm"]) * 1e-3)
                p.append(float(row["pressure_MPa"]) * 1e6)
    a, p0 = fit_hertz(x, p)
    return {"force": -value(values, "support_cylinder 2 flat face_force_y"), "a": a, "p0": p0,
            "pmax": value(values, "max_pressure") * 1e6, "closed": len(x), "time": wall,
            "memory": memory, "dofs": value(values, "dofs"),
            "fe": value(values, "time_total"), "iterations": value(values, "active_set_iterations")}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("gearstiff")
    parser.add_argument("--factors", default="10,100")
    parser.add_argument("--work", default="/tmp/calculix_hertz")
    parser.add_argument("--extra", action="append", default=[],
                        help="more --set entries for the scene, e.g. 'Mesh/contact size=0.02'")
    args = parser.parse_args()
    env = dict(os.environ, OMP_NUM_THREADS="1")
    f1, f2 = (float(f) for f in args.factors.split(","))
    c1 = calculix(args.gearstiff, f1, args.work, args.extra, env)
    c2 = calculix(args.gearstiff, f2, args.work, args.extra, env)
    approach = (f1 * c1["approach"] - f2 * c2["approach"]) / (f1 - f2)
    scene = c1["scene"]
    with open(os.path.join(c1["folder"], "parameters.json")) as f:
        cylinders = json.load(f)["Cylinders"]
    length = float(cylinders["length"]) * 1e-3
    e, nu = float(cylinders["Young's modulus"]) * 1e9, float(cylinders["Poisson's ratio"])
    r1, r2 = float(cylinders["radius 1"]) * 1e-3, float(cylinders["radius 2"]) * 1e-3
    g = gearstiff_contact(args.gearstiff, c1["folder"], approach, length, args.work, env)
    force = abs(c1["force"])  # N, the deck's F = F'·L

    print(f"Hertz cylinders, R1 {r1 * 1e3:g} mm, R2 {r2 * 1e3:g} mm, L {length * 1e3:g} mm, "
          f"F {force:.1f} N; h_c {value(scene, 'contact_size'):.4g} mm, "
          f"{int(value(scene, 'cells'))} cells; frictionless; approach δ∞ = {approach * 1e6:.4f} µm")
    print(f"{'':24} {'F N':>9} {'δ µm':>8} {'a mm':>8} {'a/Hertz-1':>10} {'p0 MPa':>8} "
          f"{'p0/Hertz-1':>10} {'p_max MPa':>9} {'closed':>6} {'wall s':>7} {'RSS MB':>7}")
    rows = [(f"ccx K = {f1:g} E/h_c", c1, c1["approach"]), (f"ccx K = {f2:g} E/h_c", c2, c2["approach"]),
            ("gearstiff Q1 at δ∞", g, approach)]
    for name, r, delta in rows:
        a_h, p_h = hertz(abs(r["force"]) / length, r1, r2, e, nu)
        print(f"{name:24} {abs(r['force']):9.3f} {delta * 1e6:8.4f} {r['a'] * 1e3:8.5f} "
              f"{100 * (r['a'] / a_h - 1):+9.2f}% {r['p0'] / 1e6:8.1f} {100 * (r['p0'] / p_h - 1):+9.2f}% "
              f"{r['pmax'] / 1e6:9.1f} {r['closed']:6d} {r['time']:7.2f} {r['memory']:7.0f}")
    a_h, p_h = hertz(force / length, r1, r2, e, nu)
    print(f"{'Hertz (analytic)':24} {force:9.3f} {'':8} {a_h * 1e3:8.5f} {'':10} {p_h / 1e6:8.1f}")
    ratio = 0.5 * (c1["time"] + c2["time"]) / g["time"]
    print(f"gearstiff: {int(g['dofs'])} DoFs, {int(g['iterations'])} active-set iterations, "
          f"FE {g['fe']:.2f} s; ccx {c1['dofs']} DoFs")
    print(f"calculix_hertz: F gearstiff {g['force']:.2f} N at ccx's approach, CalculiX {force:.2f} N "
          f"({100 * (g['force'] / force - 1):+.3f} %), a {100 * (g['a'] / a_h - 1):+.2f} % / "
          f"{100 * (c2['a'] / a_h - 1):+.2f} %, p0 {100 * (g['p0'] / p_h - 1):+.2f} % / "
          f"{100 * (c2['p0'] / p_h - 1):+.2f} % vs Hertz (gearstiff / ccx K = {f2:g}), "
          f"time ratio {ratio:.1f}x")


if __name__ == "__main__":
    main()
