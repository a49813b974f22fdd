#!/usr/bin/env python3
"""Peak contact pressure and root stresses of a `sweep mesh = once` sweep against `per position`,
each on a refinement ladder (issue 28).

Both methods give k(θ), TE and load sharing within the issue's tolerances on the default mesh
(test_sweep_once), but their nodal maxima — the peak contact pressure and the root stresses —
differ by up to ~10 % / ~4 %. The two methods mesh differently (a band refined along every flank
of the sweep against discs at each position's contact points; the fillets meshed by the body
size either way), so the question is whether that difference is each mesh's own discretisation
error (then it shrinks as both are refined) or a difference of the method (then it stays).

What it runs (one rank per run, default pair and load case, 16 positions, μ = 0.01):
  - the contact size h_c ladder 0.03 (default), 0.0212, 0.015, 0.0106 mm, both methods: the
    peak pressure is resolved by h_c (Hertz half-width a ≈ 0.078 mm at the pitch point);
  - the body size ladder 0.7 (default), 0.35, 0.25 mm, both methods: the fillets, hence the root
    stresses, are meshed by the body size.
Writes <out>/sweep_once_stresses.csv: per run the largest and mean deviation of each quantity
from the finest per-position run of its ladder, and the largest once-vs-per-position difference
at the same sizes. About 10 minutes on one core.

usage: bench/sweep_once_stresses.py [--gearstiff build/app/gearstiff] [--out bench]
"""
import argparse
import csv
import os
import subprocess
import tempfile
import time

CONTACT_SIZES = ["0.03", "0.0212", "0.015", "0.0106"]  # mm
BODY_SIZES = ["0.7", "0.35", "0.25"]  # mm
METHODS = ["once", "per position"]
COLUMNS = {
    "k": "stiffness [N/um]",
    "p_max": "max_pressure [MPa]",
    "sigma_F1": "pinion_root_stress [MPa]",
    "sigma_F2": "wheel_root_stress [MPa]",
}


def sweep(binary, method, key, size, workdir):
    out = os.path.join(workdir, f"{method.replace(' ', '_')}_{key.split('/')[1][:4]}_{size}")
    args = [binary, "stiffness", "--set", "Stiffness/mode=sweep",
            "--set", "Stiffness/sweep positions=16", "--set", "Contact/Friction coefficient=0.01",
            "--set", f"Stiffness/sweep mesh={method}", "--set", f"{key}={size}", "-o", out]
    start = time.time()
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    seconds = time.time() - start
    with open(os.path.join(out, "stiffness_sweep.csv")) as f:
        rows = list(csv.DictReader(f))
    return {name: [float(r[col]) for r in rows] for name, col in COLUMNS.items()}, seconds


def deviation(values, reference):
    d = [100.0 * (a - b) / b for a, b in zip(values, reference)]
    return max(abs(x) for x in d), sum(d) / len(d)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gearstiff", default="build/app/gearstiff")
    parser.add_argument("--out", default="bench")
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as workdir:
        for key, sizes in (("Mesh/contact size", CONTACT_SIZES), ("Mesh/body size", BODY_SIZES)):
            runs = {(m, s): sweep(args.gearstiff, m, key, s, workdir) for s in sizes for m in METHODS}
            reference = runs[("per position", sizes[-1])][0]
            for (method, size), (values, seconds) in runs.items():
                other = runs[("per position" if method == "once" else "once", size)][0]
                row = {"ladder": key, "size [mm]": size, "method": method,
                       "time [s]": f"{seconds:.1f}"}
                for name in COLUMNS:
                    worst, mean = deviation(values[name], reference[name])
                    row[f"{name} max dev [%]"] = f"{worst:.2f}"
                    row[f"{name} mean dev [%]"] = f"{mean:+.2f}"
                    row[f"{name} once-pp max [%]"] = f"{deviation(values[name], other[name])[0]:.2f}"
                rows.append(row)
                print(row, flush=True)
    with open(os.path.join(args.out, "sweep_once_stresses.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
