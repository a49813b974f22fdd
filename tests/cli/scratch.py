#!/usr/bin/python3
"""Scratch files of a run do not outlive it (issue 26).

    scratch.py GEARSTIFF WORKDIR

Runs `gearstiff cycloid-loads` (one profile, one position) with TMPDIR set to an empty folder,
waits until its first scene mesh appears in the process's scratch folder, stops it by SIGTERM
and, in a second run, by SIGINT, and asserts that nothing is left in TMPDIR and the process ended
by the signal. A third run, `gearstiff gear-pair`, ends normally with nothing left. Before, the
meshes were left in /tmp as gearstiff-cycloid-PID-*.msh (1.9 MB each).

MUMPS' out-of-core factors (from 500k DoFs; here forced by PETSC_OPTIONS on the small helical
pair's fast model, two 3D gear bodies of ~50k DoFs): they must appear in the process's scratch
folder, not in /tmp, so that SIGTERM removes them, and after a SIGKILL the next run does. Before
session 42 MUMPS wrote them to /tmp (it does not read TMPDIR) and a stopped run left them there,
1.9 GB a file at the sizes where they are used.
"""
import os
import shutil
import signal
import subprocess
import sys
import time


def stop_when(binary, args, tmp, sig, appeared, what, extra_env=None):
    """Runs `binary args` with TMPDIR=tmp, stops it by `sig` once a file of its scratch folder
    satisfies `appeared` (within 60 s), and returns the problems ("" for none): not ended by the
    signal, anything left in TMPDIR. After a SIGKILL, which nothing can clean up after, another
    run in the same TMPDIR must remove the stale scratch folder."""
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    env = dict(os.environ, TMPDIR=tmp, **(extra_env or {}))
    env.pop("MUMPS_OOC_TMPDIR", None)
    proc = subprocess.Popen([binary] + args, env=env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    folder = os.path.join(tmp, f"gearstiff-scratch-{proc.pid}")
    name = signal.Signals(sig).name
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and proc.poll() is None:
        if os.path.isdir(folder) and any(appeared(n) for n in os.listdir(folder)):
            break
        time.sleep(0.005)
    else:
        proc.kill()
        proc.wait()
        return f"{name}: no {what} appeared in {folder} (ended with {proc.returncode})"
    proc.send_signal(sig)
    code = proc.wait(timeout=30)
    problems = []
    if code != -sig:
        problems.append(f"ended with {code}, not by the signal ({-sig})")
    if sig == signal.SIGKILL:
        subprocess.run([binary, "gear-pair"], env=env, capture_output=True)
    left = os.listdir(tmp)
    if left:
        problems.append(f"left {left} in TMPDIR")
    return f"{name}: " + "; ".join(problems) if problems else ""


def run_and_stop(binary, tmp, sig):
    return stop_when(binary, ["cycloid-loads", "--set", "Cycloid loads/profiles=nominal",
                              "--set", "Cycloid loads/torsional curve=false"],
                     tmp, sig, lambda n: n.endswith(".msh"), "scene mesh")


# The small helical pair's fast-model sweep (tests/helical/small_pair.py, with the settings of
# cli.influence_3d_helical: 6 layers, Q1, 4 positions): two gear bodies factored in ~1 s each.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "helical"))
from small_pair import MESH, PAIR  # noqa: E402

OUT_OF_CORE_RUN = ["stiffness"] + [
    word for entry in PAIR + MESH + ["Mesh/layers=6", "Finite elements/Element degree=1",
                                      "Stiffness/contact model=influence coefficients",
                                      "Stiffness/mode=sweep", "Stiffness/sweep positions=4",
                                      "Stiffness/published reference=false"]
    for word in ("--set", entry)]


def out_of_core_and_stop(binary, tmp, sig):
    problem = stop_when(binary, OUT_OF_CORE_RUN, tmp, sig, lambda n: n.startswith("mumps_"),
                        "MUMPS file", {"PETSC_OPTIONS": "-mat_mumps_icntl_22 1"})
    return "out of core, " + problem if problem else ""


def main():
    binary, work = sys.argv[1], sys.argv[2]
    failures = [p for p in (run_and_stop(binary, os.path.join(work, name), sig)
                            for name, sig in (("term", signal.SIGTERM), ("int", signal.SIGINT)))
                if p]
    failures += [p for p in (out_of_core_and_stop(binary, os.path.join(work, name), sig)
                             for name, sig in (("ooc-term", signal.SIGTERM),
                                               ("ooc-kill", signal.SIGKILL)))
                 if p]
    tmp = os.path.join(work, "normal")
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    out = subprocess.run([binary, "gear-pair", "-o", os.path.join(work, "normal-out")],
                         env=dict(os.environ, TMPDIR=tmp), capture_output=True, text=True)
    if out.returncode != 0 or os.listdir(tmp):
        failures.append(f"gear-pair: exit {out.returncode}, left {os.listdir(tmp)} in TMPDIR")
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
