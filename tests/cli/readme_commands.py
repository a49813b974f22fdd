#!/usr/bin/env python3
"""Runs every command line of the README as written (issue 25: the examples must work).

usage: readme_commands.py README.md path/to/gearstiff WORK_FOLDER

The command lines are the indented code lines that start with `gearstiff`, `mpirun` or
`bash tools/` (a trailing backslash continues a line). Each runs with bash in WORK_FOLDER, with
the gearstiff binary first on PATH and `tools/` read as the source tree's. Changes made for a
test and why:
  - `mpirun` gets `--allow-run-as-root --oversubscribe --bind-to none` (CI runs as root on a
    shared machine, docs/developers.md) and keeps the README's -np 2;
  - the lines in SMALLER get a few `--set` appended (before a trailing comment), so that the whole
    test stays under a minute or two (the README's sizes are a user's, not a test's);
  - synopsis lines with placeholders (`gearstiff <command> [file.prm] ...`) are not commands;
  - `bash tools/run.sh` and `bash tools/test.sh` are not run: they install packages, build the
    project and run the whole suite (test.sh is CI itself); the command run.sh ends with,
    `gearstiff run`, is in the README's examples through the same commands it chains.
A line that calls `ccx` is skipped when ccx is not installed, and the test then exits 77 (ctest:
skipped) after every other line passed. Exit 1 names the first failing line and its stderr.

Each line is then checked by its numbers (NUMBERS, issue 43): values of the `summary.json` its
`-o` folder holds, or of its printed report (the quantity's description as printed), each
against a cited reference with its tolerance; a line with numbers that none of its checks finds
fails. The line that `cli.calculix_stiffness_scene` runs command for command (the README's ccx
line) is left to that test, which checks its k against gearstiff's to 0.1 % (SHARED).
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

# Substring of a README line -> settings added after `gearstiff <command>` for the test.
SMALLER = {
    # ~1 M DoFs, ~200 s, ~11 GB as written: one hexahedron layer of Q1, 42k DoFs, ~10 s.
    "Mesh/dimension=3": ['--set Mesh/layers=1', '--set "Finite elements/Element degree=1"'],
    # a 32-position sweep: 4 positions show the same path.
    "Stiffness/mode=sweep": ['--set "Stiffness/sweep positions=4"'],
    # 12 solves and two friction loops (~2 min on a loaded machine): one profile, Q1.
    "cycloid-loads": ['--set "Cycloid loads/profiles=nominal"',
                      '--set "Finite elements/Element degree=1"'],
    # the cycloid deck as written is 205k cells, ~65 s of gmsh (half of this test's time, issue
    # 43): the coarse sizes of cli.mesh_inp_cycloid, 14k cells, write the same kind of deck.
    "-o cdeck": ['--set "Mesh/contact size=0.2"', '--set "Mesh/fine radius=0.4"',
                 '--set "Mesh/body size=3"', '--set "Mesh/rim size=8"',
                 '--set "Mesh/growth rate=0.4"', '--set "Cycloid scene/outline points per lobe=21"',
                 '--set "Cycloid scene/contact clearance=0.1"'],
}
NOT_RUN = ("bash tools/run.sh", "bash tools/test.sh")
# README lines another test runs as written, command for command, and checks by its numbers.
SHARED = {
    "(cd deck && ccx -i scene) && python3 tools/calculix_stiffness.py deck":
        "cli.calculix_stiffness_scene (tests/cli/calculix_stiffness_scene.py)",
}

# Substring of a README line -> its numbers: (source, key, reference, relative tolerance) with
# source "summary.json of DIR" (the line's -o folder) or "printed" (the first number after the
# quantity's description in the report on stdout). References: regression, measured 2026-12-01
# on the line as run here (SMALLER), unless another source is named; the solvers are
# deterministic, so 1e-6 relative is the regression tests' own tolerance
# (tests/regression/compare.py).
#   The gear-pair lines: d = z·m_n and r_b = d/2·cos 20° (exact: the pinion z = 21 and 24, m_n =
#   2.5 mm; a profile shift changes neither), to the printed 6 digits.
NUMBERS = {
    'gear-pair --set "Gear pair/Pinion/profile shift=0.5"': [
        ("printed", "pinion reference diameter d", 52.5, 1e-9),
        ("printed", "pinion base radius r_b", 26.25 * math.cos(math.radians(20.)), 1e-5)],
    "# a ring–planet pair": [
        ("printed", "pinion reference diameter d", 60., 1e-9),
        ("printed", "pinion base radius r_b", 30. * math.cos(math.radians(20.)), 1e-5)],
    # The FE lines (issue 43), as run here (SMALLER). r_b1 = 26.25·cos 20° and a = 97.5 mm are
    # exact (§1); Hertz's a and p0 for P' = 100 N/mm, R = 5 mm, E* = 210 GPa/(2·0.91) are exact
    # (Johnson 1985 eq. 4.43, docs/references.md §6); the 4-position sweep on one rank equals the
    # one on two (the same positions and meshes: 2 ranks = 1 rank, to the printed digits); the
    # dynamics default's K_v is tests/regression/dynamics.json's kv_max and its mean stiffness the
    # closed form 1.275·327.2 N/µm for ε_α = 1.5 (§1); every other value: regression, measured
    # 2026-12-02 (printed values carry 7 digits: 1e-6 covers their rounding).
    "Stiffness/mode=double": [
        ("out/double", "pinion_base_radius", 26.25 * math.cos(math.radians(20.)), 1e-9),
        ("out/double", "mesh_stiffness", 396.383135527, 1e-6),
        ("out/double", "load_share_pair_0", 0.478968003175, 1e-6)],
    'mpirun -np 2 gearstiff stiffness --set "Stiffness/mode=sweep"': [
        ("out/sweep", "centre_distance", 97.5, 1e-9),
        ("out/sweep", "mean_stiffness", 340.953704266, 1e-6),
        ("out/sweep", "min_stiffness", 284.115165242, 1e-6),
        ("out/sweep", "max_stiffness", 395.199586899, 1e-6)],
    "Stiffness/sweep positions=256": [
        ("printed", "smallest k (single-contact zone)", 284.115165242, 1e-6)],
    "gearstiff dynamics --print-parameters": [
        ("printed", "Mesh 1 K_v max (simulated)", 1.55215381554, 1e-6),
        ("printed", "Mesh 1 mean mesh stiffness over a mesh cycle", 1.275 * 327.2, 1e-6)],
    '"Gear pair/Pinion/teeth=23"': [
        ("printed", "mesh stiffness T1/(r_b1²·Δφ)", 427.2477, 1e-6),
        ("printed", "ISO 6336-1 method B c_γα·b (mean mesh stiffness)", 610.7062, 1e-6)],
    "# its mesh stiffness (the ring held": [
        ("printed", "mesh stiffness T1/(r_b1²·Δφ)", 419.5195, 1e-6)],
    "-o cdeck": [
        ("cdeck", "rollers", 20, 1e-12), ("cdeck", "lobes", 19, 1e-12),
        ("cdeck", "cells", 14406, 1e-12),
        ("cdeck", "deck_closing_rotation_OUTPUT", 22.7347883598, 1e-6)],
    "-o out/cyc": [
        ("out/cyc", "max_pin_force", 3891.2888463, 1e-6),
        ("out/cyc", "torsional_stiffness", 585.682487878, 1e-6),
        ("out/cyc", "hysteresis", 0.00615615212156, 1e-6)],
    "-o hdeck": [
        ("hdeck", "hertz_half_width", 0.0742790102285, 1e-8),
        ("hdeck", "hertz_peak_pressure", 857.065502636, 1e-8),
        ("hdeck", "cells", 5666, 1e-12)],
    "Mesh/dimension=3": [
        ("printed", "single-pair mesh stiffness k'_j", 280.477, 1e-6)],
}


def readme_commands(readme):
    lines, current = [], None
    with open(readme) as f:
        for raw in f:
            if not raw.startswith("    "):
                current = None
                continue
            text = raw.rstrip("\n")[4:]
            if current is not None:
                current += " " + text.strip()
            elif re.match(r"(gearstiff|mpirun|bash tools/)\b", text):
                current = text.strip()
            else:
                continue
            if current.endswith("\\"):
                current = current[:-1].rstrip()
            else:
                lines.append(current)
                current = None
    return lines


def prepared(line, source):
    for key, settings in SMALLER.items():
        if key in line:
            # After the README's own settings (a later --set wins), before a trailing comment.
            command, hash_mark, comment = line.partition(" #")
            line = command.rstrip() + " " + " ".join(settings) + (
                "  " + hash_mark.strip() + comment if hash_mark else "")
    line = line.replace("mpirun ", "mpirun --allow-run-as-root --oversubscribe --bind-to none ")
    return re.sub(r"(?<![\w/.])tools/", os.path.join(source, "tools") + "/", line)


def printed_value(stdout, description):
    """The first number after `description` at the start of a report line."""
    for line in stdout.splitlines():
        line = line.strip()
        if line.startswith(description):
            match = re.search(r"[-+]?\d+(\.\d*)?([eE][-+]?\d+)?", line[len(description):])
            if match:
                return float(match.group(0))
    raise KeyError(f"no printed line '{description}'")


def check_numbers(line, stdout, work):
    """The NUMBERS of a README line; returns the failures (empty: all within tolerance)."""
    failures = []
    for key, checks in NUMBERS.items():
        if key not in line:
            continue
        for source, name, reference, tolerance in checks:
            try:
                if source == "printed":
                    value = printed_value(stdout, name)
                else:
                    with open(os.path.join(work, source, "summary.json")) as f:
                        entry = json.load(f)["values"][name]
                    value = entry["value"] if isinstance(entry, dict) else entry
            except (KeyError, OSError, ValueError) as error:
                failures.append(f"{name}: not found ({error})")
                continue
            deviation = value / reference - 1.
            ok = abs(deviation) <= tolerance
            print(f"   {'ok  ' if ok else 'FAIL'} {name} = {value:.10g} against {reference:.10g}: "
                  f"{deviation * 100:+.3g} % (tolerance ±{tolerance * 100:g} %)")
            if not ok:
                failures.append(f"{name} = {value:.10g}, expected {reference:.10g}")
    return failures


def main():
    readme, gearstiff, work = sys.argv[1:4]
    source = os.path.dirname(os.path.abspath(readme))
    shutil.rmtree(work, ignore_errors=True)  # the README's -o folders must not exist yet
    os.makedirs(work)
    env = dict(os.environ)
    env["PATH"] = os.path.dirname(os.path.abspath(gearstiff)) + os.pathsep + env["PATH"]
    commands = readme_commands(readme)
    if len(commands) < 10:
        sys.exit(f"readme_commands: found only {len(commands)} command lines in {readme}")
    skipped = 0
    for line in commands:
        if line.startswith(NOT_RUN):
            print(f"not run (installs, builds, runs the suite): {line}")
            continue
        if re.search(r"<\w+>", line):
            print(f"not run (a synopsis with placeholders): {line}")
            continue
        shared = [test for key, test in SHARED.items() if key in line]
        if shared:
            print(f"run and checked by {shared[0]}: {line}")
            continue
        if re.search(r"\bccx\b", line) and shutil.which("ccx") is None:
            print(f"skipped (no ccx): {line}")
            skipped += 1
            continue
        command = prepared(line, source)
        start = time.monotonic()
        process = subprocess.run(["bash", "-c", "set -o pipefail; " + command], cwd=work, env=env,
                                 capture_output=True, text=True)
        elapsed = time.monotonic() - start
        if process.returncode != 0:
            print(f"FAILED (exit {process.returncode}, {elapsed:.1f} s): {line}\nran: {command}\n"
                  f"stderr:\n{process.stderr[-3000:]}\nstdout:\n{process.stdout[-2000:]}")
            return 1
        print(f"ok {elapsed:6.1f} s: {line}")
        with open(os.path.join(work, f"line{commands.index(line):02d}.stdout"), "w") as f:
            f.write(line + "\n" + process.stdout)  # what its checks read, kept for a failure
        failures = check_numbers(line, process.stdout, work)
        if failures:
            print(f"FAILED (numbers): {line}\n  " + "\n  ".join(failures))
            return 1
    return 77 if skipped else 0


if __name__ == "__main__":
    sys.exit(main())
