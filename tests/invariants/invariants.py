#!/usr/bin/env python3
"""Invariants on gears nobody tuned to (issue 41; ctest label `invariants`).

A seeded generator draws own gear pairs -- teeth 17-90, module 1-10 mm, profile shifts
-0.4...+0.6 within the validity checks of `gearstiff gear-pair`, face widths, friction 0-0.1,
external and internal, with and without modifications, one in four with another basic rack
(pressure angle 17.5-25 deg, ISO 53 profile D; rack_sets), one in four with rounded tip edges
(0.05-0.25 m_n, tip_rounding_sets) -- and checks on each the identities that
must hold whatever the gear. None of them compares with a stored number: each is an identity of
the method (two paths to one answer) or of the geometry, so a case can never be "re-blessed".

    once = per position      a rolling sweep (one mesh, turned) against a mesh per position:
                             unloaded TE identical (it is geometry: 1 nm), loaded TE within
                             0.05 um, load shares within 0.005 (issue 41's accuracy), k within
                             0.5 % (the default meshes' own scatter on generated gears: 0.4 %),
                             root stresses within 20 % (their fillets' scatter: 6.8 %)
    zero = none              a modification of amount 0 gives every printed digit of none
    one-gear relief          a tip relief on one gear only: unloaded TE 0 at every position (the
                             unmodified pair carries wherever the relieved one separates)
    tent                     equal long linear tip reliefs C on both gears: the unloaded TE is
                             C*min(x, e-1-x)/(e-1) in the double-contact zone x in [0, e-1] of
                             the mesh cycle and 0 in the single-contact zone (e = eps_alpha; the
                             entering pair's wheel relief falls as the leaving pair's pinion
                             relief rises over the same length): 1 nm
    2 ranks = 1 rank         the same sweep on two MPI ranks: k, TE to 1e-6 relative (the warm
                             start of a position depends on the rank's previous one)
    Python = command line    gearstiff.stiffness(...) returns the command line's numbers (the
                             12 printed digits)
    mesh + contact           `gearstiff mesh` writes the stiffness scene and `gearstiff contact`
                             solves it as a user's mesh (the stiffness command's tooth pairs, a
                             torque hub): its hub rotation less the turn that closes the smallest
                             initial gap is the stiffness command's, 1e-6 relative
    3D between plane models  straight teeth in 3D: k between plane stress and plane strain, at
                             both positions of a 2-position once sweep
    influence 3D = exact     the 3D influence-coefficient model against that 3D sweep (external
                             pairs, unmodified, frictionless): k 1 %, TE 0.1 um, shares 0.01,
                             K_Hbeta 2 %; one layer more than the end faces' limit
                             floor(b / (1.35 h)) refused naming Mesh/layers and that limit
    influence 3D crowned     the same 3D check with lead crowning (C_beta 5-15 um on the pinion,
                             the wheel or both in turn; internal pairs too) at 16 layers; where
                             the model refuses a contact on < 7 node planes (exit 2 naming
                             Mesh/layers, checked), under a torque that spreads the crowned
                             contact over ~10 planes (more layers only if that is refused too);
                             the exact path a mesh per position: k 1 %, TE 0.1 um, shares 0.01,
                             K_Hbeta 2 %
    influence = exact        the influence-coefficient model (docs/ltca.md) against the rolling
                             sweep: k 1 %, TE 0.1 um, shares 0.01, with friction the torque ratio 2 %; and on
                             two ranks (a gear each) every printed value of the one-rank run
    helical unloaded TE      the helical variant's unloaded TE (gearstiff mesh, 4 meshes):
                             0 with a relief on one gear only; equal long reliefs give the
                             spur tent's smallest value over the face's window x +- eps_beta/2
                             (each transverse section is a spur section, shifted; depth C/cos
                             beta_b along the transverse line of action): 1 nm
    helicoid flanks          one helical case in four again with the gaps measured between
                             the involute helicoids, not the hexahedra's chords: k at least
                             and TE at most the chords' (the chords lie inside both bodies);
                             |F_a|/F_bt and the torque balance as above
    layer extrapolation      the helical cases neither widened nor drawn for the helicoid
                             check again with Mesh/layer extrapolation = richardson: its L
                             level is the plain run (1e-6), k is Richardson's in the rotation
                             from the two levels (1e-9), the statics identities as above
    errors name parameters   a wheel of two teeth (gear-pair) and a 1 mm centre distance (mesh)
                             fail with one line naming the parameter typed, not the library's
                             field (issue 45)
    names its build          both sweeps' reports carry the version, revision and libraries
                             `gearstiff --version` prints (summary.json's "gearstiff" block)
    own train                the sweep's stiffness_table.prm runs `gearstiff dynamics` on this
                             pair: its mesh frequency z1*n1/60, its mean stiffness the sweep's,
                             and K_v = 1 at a quasi-static speed without friction (0.5 %);
                             its summary.json as the nonlinear model's TE file: the mean DTE
                             is the model's quasi-static mean of e + W/k (1e-4);
                             the table's Gear 1 torque is the summary's pinion_torque, the load
                             of its k(x) that `dynamics` checks a train against (1e-9); the
                             table given to `cai` and the summary given to `dynamics` as
                             parameters are refused naming the file (exit 2)

A pair `gearstiff gear-pair` accepts must also be one the FE scene accepts (the first defect
this generator found: an automatic ring tip the tooth generator refused as topped).

Every case prints its seed and its full parameter set, and the command that reproduces it:

    invariants.py GEARSTIFF --seed S --cases 1 --first K

usage: invariants.py GEARSTIFF [--seed S] [--cases N] [--first K] [--mpiexec CMD]
           [--python-path DIR]
The number of cases comes from --cases, or GEARSTIFF_INVARIANT_CASES to run more.
"""
import argparse
import collections
import inspect
import json
import math
import os
import random
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

import numpy

MODULES = [1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0]  # mm, ISO 54 first choice
WALL_CLOCK = ("time", "cost", "ranks", "rank")


class CaseFailure(Exception):
    pass


class Runner:
    def __init__(self, gearstiff, mpiexec, python_path, work):
        self.gearstiff = gearstiff
        self.mpiexec = mpiexec
        self.python_path = python_path
        self.work = work
        self.runs = 0
        # Wall seconds of the runs by the identity that asked for them, printed per case so that
        # the suite's cost is visible where it is spent (issue 43).
        self.seconds = collections.Counter()

    def run(self, command, sets, ranks=1, out=None, allowed=(0,)):
        """The command's JSON report (and its exit code), one `--set` per entry of `sets`."""
        args = [self.gearstiff, command, "--json", "--quiet"]
        for key, value in sets.items():
            args += ["--set", f"{key}={value}"]
        if out:
            args += ["-o", out]
        if ranks > 1:
            args = shlex.split(self.mpiexec) + ["-np", str(ranks)] + args
        self.runs += 1
        start = time.monotonic()
        process = subprocess.run(args, capture_output=True, text=True)
        self.seconds[inspect.stack()[1].function] += time.monotonic() - start
        if process.returncode not in allowed:
            raise CaseFailure(f"{command} exited {process.returncode}: "
                              f"{process.stderr.strip()[-600:]}\n  command: {shlex.join(args)}")
        report = json.loads(process.stdout) if process.stdout.strip() else {}
        return report, process.returncode, process.stderr

    def timed(self, args, env=None):
        """A process that is not a `gearstiff <command> --json` run with --set entries (the
        dynamics on a table file, the Python module), timed for its identity all the same."""
        start = time.monotonic()
        process = subprocess.run(args, capture_output=True, text=True, env=env)
        self.seconds[inspect.stack()[1].function] += time.monotonic() - start
        return process


def table(report, name):
    t = report["tables"][name]
    return [dict(zip(t["columns"], row)) for row in t["rows"]]


def value(report, key):
    return report["values"][key]["value"]


# ---- the generator ------------------------------------------------------------------------
def gear_sets(rng):
    """One pair's `Gear pair/...` settings (not yet checked for validity)."""
    internal = rng.random() < 0.25
    module = rng.choice(MODULES)
    if internal:
        z1 = rng.randint(17, 40)
        z2 = rng.randint(z1 + 15, 90)  # a ring close to its planet interferes at its tips
        x1, x2 = round(rng.uniform(0.0, 0.6), 2), round(rng.uniform(0.0, 0.4), 2)
    else:
        z1 = rng.randint(17, 45)
        z2 = rng.randint(z1, 90)
        x1, x2 = round(rng.uniform(-0.4, 0.6), 2), round(rng.uniform(-0.4, 0.6), 2)
    width = round(module * rng.uniform(6., 12.), 1)
    sets = {}
    for gear, z, x in (("Pinion", z1, x1), ("Wheel", z2, x2)):
        sets[f"Gear pair/{gear}/teeth"] = z
        sets[f"Gear pair/{gear}/module"] = module
        sets[f"Gear pair/{gear}/profile shift"] = x
        sets[f"Gear pair/{gear}/face width"] = width
    sets["Gear pair/Wheel/internal"] = "true" if internal else "false"
    return sets


def load_sets(rng, pair_report, sets):
    """A torque that deflects the mesh by 3-8 um at ISO's c' = 14 N/(mm um) over the face width,
    and a friction coefficient 0-0.1."""
    width = float(sets["Gear pair/Pinion/face width"])
    base_radius = value(pair_report, "pinion_base_radius") * 1e-3
    deflection = rng.uniform(3e-6, 8e-6)
    torque = 14e6 * width * deflection * base_radius
    return {"Gear pair scene/pinion torque": round(torque, 3),
            "Contact/Friction coefficient": round(rng.choice([0., rng.uniform(0., 0.1)]), 3)}


MODIFICATIONS = ["none", "long relief both", "relief pinion only", "relief wheel only",
                 "profile mix"]


def modification_sets(rng, kind, module):
    amount = round(rng.uniform(4., 15.), 1)  # um
    if kind == "long relief both":
        return {"Gear pair/Pinion/tip relief": amount, "Gear pair/Wheel/tip relief": amount}
    if kind == "relief pinion only":
        return {"Gear pair/Pinion/tip relief": amount}
    if kind == "relief wheel only":
        return {"Gear pair/Wheel/tip relief": amount}
    if kind == "profile mix":
        return {"Gear pair/Pinion/tip relief": amount,
                "Gear pair/Pinion/tip relief shape": "parabolic",
                "Gear pair/Pinion/tip relief length": round(0.35 * module, 3),
                "Gear pair/Wheel/profile crowning": round(rng.uniform(1., 4.), 1),
                "Gear pair/Wheel/profile slope": round(rng.uniform(-4., 4.), 1)}
    return {}


def tip_rounding_sets(rounding_rng, runner, sets):
    """Rounded tip edges (issue 46) on one case in four: `tip rounding radius` 0.05-0.25 m_n on
    each gear, drawn from a stream of its own (the case's other draws stay as they were), kept
    when `gearstiff gear-pair` accepts it with eps_alpha > 1.05 (a radius that does not fit the
    top land is refused there), else halved once, else none. Returns the settings and the pair's
    report, or ({}, None). Seed 20261201, cases 0-39: cases 14 (helical statics too), 30 and 33
    are rounded; each passed every identity (2026-12-03, 214, 15 and 18 s, loaded machine)."""
    if rounding_rng is None or rounding_rng.random() >= 0.25:
        return {}, None
    module = float(sets["Gear pair/Pinion/module"])
    radii = [rounding_rng.uniform(0.05, 0.25) * module for _ in range(2)]
    for scale in (1., 0.5):
        rounding = {f"Gear pair/{gear}/tip rounding radius": round(scale * radius, 4)
                    for gear, radius in zip(("Pinion", "Wheel"), radii)}
        pair = {k: v for k, v in sets.items() if k.startswith("Gear pair/")}
        report, code, _ = runner.run("gear-pair", dict(pair, **rounding), allowed=(0, 2))
        if code == 0 and value(report, "transverse_contact_ratio") > 1.05:
            return rounding, report
    return {}, None


# Basic racks other than ISO 53 profile A (20°, h_fP* 1.25, rho_fP* 0.38): (pressure angle in
# degrees, dedendum coefficient, root radius coefficient). At 25° profile A's 0.38 does not fit
# (its tip rounds overlap above 0.318: session 48, found on an own gear), so the 25° rack takes
# 0.25; profile D (1.4, 0.39) is the ground gears' rack; 17.5° thins the root, 22.5° the tip.
RACKS = [(25., 1.25, 0.25), (22.5, 1.25, 0.3), (17.5, 1.25, 0.38), (20., 1.4, 0.39)]


def rack_sets(rack_rng, runner, sets):
    """Another basic rack on both gears (`RACKS`) on one case in four, drawn from a stream of its
    own (the case's other draws stay as they were), kept when `gearstiff gear-pair` accepts the
    pair with eps_alpha > 1.05, else the standard rack. Returns the settings and the pair's
    report, or ({}, None). Seed 20261201, cases 0-29: 3, 6, 16, 19 and 23 draw one."""
    if rack_rng is None or rack_rng.random() >= 0.25:
        return {}, None
    angle, dedendum, root = rack_rng.choice(RACKS)
    rack = {f"Gear pair/{gear}/{key}": number for gear in ("Pinion", "Wheel")
            for key, number in (("pressure angle", angle), ("dedendum coefficient", dedendum),
                                ("root radius coefficient", root))}
    report, code, _ = runner.run("gear-pair", dict(sets, **rack), allowed=(0, 2))
    if code == 0 and value(report, "transverse_contact_ratio") > 1.05:
        return rack, report
    return {}, None


def draw_case(rng, runner, rounding_rng=None, rack_rng=None):
    """A valid own pair (redrawn until `gearstiff gear-pair` accepts it) with a load and a
    modification kind; with `rack_rng`, another basic rack on some cases, with `rounding_rng`,
    rounded tip edges on some."""
    for attempt in range(50):
        sets = gear_sets(rng)
        report, code, _ = runner.run("gear-pair", sets, allowed=(0, 2))
        if code == 0 and value(report, "transverse_contact_ratio") > 1.05:
            break
    else:
        raise CaseFailure("no valid pair in 50 draws")
    rack, rack_report = rack_sets(rack_rng, runner, sets)
    if rack:
        sets.update(rack)
        report = rack_report
    sets.update(load_sets(rng, report, sets))
    kind = rng.choice(MODIFICATIONS)
    module = float(sets["Gear pair/Pinion/module"])
    # Not on the cases the fast model checked when rounding was added (frictionless, unmodified:
    # UNROUNDED_KINDS), which refused a rounded tip until 2026-12-05: those keep their identity,
    # and the seed's cases stay as drawn since.
    rounding = {}
    if float(sets["Contact/Friction coefficient"]) != 0. or kind not in UNROUNDED_KINDS:
        rounding, rounded_report = tip_rounding_sets(rounding_rng, runner, sets)
    if rounding:
        sets.update(rounding)
        report = rounded_report
    # The pair's line of action (mm) for the closed forms of where modified flanks touch.
    geometry = line_geometry(report,
                             str(sets.get("Gear pair/Wheel/internal", "false")) == "true")
    return {"pair": sets, "modification": kind,
            "modifications": modification_sets(rng, kind, module),
            "contact_ratio": value(report, "transverse_contact_ratio"), "geometry": geometry,
            "draws": attempt + 1, "tip_rounding": bool(rounding), "rack": bool(rack)}


# ---- the identities -----------------------------------------------------------------------
def sweep_sets(case, positions, mesh):
    sets = dict(case["pair"])
    sets.update(case["modifications"])
    sets.update({"Stiffness/mode": "sweep", "Stiffness/sweep positions": positions,
                 "Stiffness/sweep mesh": mesh, "Stiffness/published reference": "false"})
    return sets


def check_close(what, a, b, atol, rtol=0.):
    if not abs(a - b) <= atol + rtol * max(abs(a), abs(b)):
        raise CaseFailure(f"{what}: {a!r} against {b!r} (tolerance {atol} + {rtol} relative)")


def shares(row):
    return [row.get(k, 0.) for k in ("share_pair_m1", "share_pair_0", "share_pair_p1")]


SWEEP_POSITIONS = 5  # over one base pitch: both contact zones, and the suite's time in bounds
# The sweeps of once = per position keep the default mesh sizes, although coarser ones were
# tried for the suite's time (issue 43, 2026-12-02, cases 21 and 23 of seed 20261201, single
# runs on the shared 2-core machine, so the times are only indicative): body size x1.5 or x2
# saved nothing measurable (case 23: 14.8 s at the default, 14.1 s at x2) and contact size x2
# none either (17.6 s), while |dk| between the two meshes grew (case 23: 0.074 % at the
# default, 0.18 % at body x2, 0.15 % at contact x2; case 21: 0.106 % -> 0.20 % at contact x2)
# towards the 0.5 % tolerance. A 5-position sweep's cost is its fixed part (the once sweep of
# case 21: 7.9 s of sweep, 6.4 s of it meshing, set-up and factorization at position 1; the
# per-position sweep ~2.2 s a position), which these sizes hardly move.


# The root stresses of the two sweeps' meshes (the largest first principal stress on the fillets,
# stiffness/root_stress.h): each reads the fillets at the body size, so they differ by the two
# meshes' discretisation (docs/accuracy.md: 3.4 % on the built-in pair at the default size, 0.9 %
# at 0.25 mm). Measured 2026-12-07 on the 36 2D cases 0-39 of seed 20261201: worst 6.79 % (case
# 20, a relieved pinion at mu 0.08), 6.46, 6.16, 5.93 % next; 3x that is 20 %. It catches what a
# mesh-made stress does: until the fillet took its flank's removal at the form circle
# (geometry/tooth_modification.cc, FilletBlend), case 15's crowned and sloped ring had a step
# there, 123.8 MPa on the rolling mesh against 85.2 per position (45 %; 86.2 and 87.2 since).
ROOT_STRESS_MESHES = 0.20


def once_equals_per_position(case, runner, log, once_out=None):
    """Returns both sweeps' reports: the later identities reuse them (issue 43: each FE sweep of
    a case runs once)."""
    once, _, _ = runner.run("stiffness", sweep_sets(case, SWEEP_POSITIONS, "once"), out=once_out)
    reference, _, _ = runner.run("stiffness",
                                 sweep_sets(case, SWEEP_POSITIONS, "per position"))
    rows_once, rows_ref = table(once, "stiffness_sweep"), table(reference, "stiffness_sweep")
    worst = [0., 0., 0., 0., 0.]
    for i, (a, b) in enumerate(zip(rows_ref, rows_once)):
        check_close(f"position {i} unloaded TE [um]", b["unloaded_transmission_error"],
                    a["unloaded_transmission_error"], 1e-3)
        check_close(f"position {i} loaded TE [um]", b["transmission_error"],
                    a["transmission_error"], 0.05)
        # 0.5 %, not the built-in pair's 0.3 %: the two are different meshes, each with its own
        # discretisation error, and on generated gears the default per-position mesh alone
        # scatters more (case 8 of seed 20261201, a 24/34 pair of m 5 mm at 22.82°: per
        # position 900.44, 903.81, 902.34 N/um at sizes x1, x0.71, x0.5; once 904.15: 0.41 %
        # from per position, 0.20 % from the finest level).
        check_close(f"position {i} k [N/um]", b["stiffness"], a["stiffness"], 0., 5e-3)
        for sa, sb in zip(shares(a), shares(b)):
            check_close(f"position {i} load share", sb, sa, 5e-3)
        for gear in ("pinion_root_stress", "wheel_root_stress"):
            check_close(f"position {i} {gear} [MPa]", b[gear], a[gear], 0., ROOT_STRESS_MESHES)
        worst = [max(worst[0], abs(b["unloaded_transmission_error"] -
                                   a["unloaded_transmission_error"])),
                 max(worst[1], abs(b["transmission_error"] - a["transmission_error"])),
                 max(worst[2], abs(b["stiffness"] / a["stiffness"] - 1.)),
                 max(worst[3], max(abs(x - y) for x, y in zip(shares(a), shares(b)))),
                 max([worst[4]] + [abs(b[g] / a[g] - 1.)
                                   for g in ("pinion_root_stress", "wheel_root_stress")])]
    log(f"once = per position: |dTE0| {worst[0]:.2g} um, |dTE| {worst[1]:.3g} um, "
        f"|dk| {worst[2] * 100:.3g} %, |dshare| {worst[3]:.2g}, "
        f"|d root stress| {worst[4] * 100:.3g} %")
    return {"once": once, "per position": reference, "once_out": once_out}


# The influence-coefficient contact model (docs/ltca.md) on the case's own pair: the same sweep
# as the exact rolling one within the accuracy it is tested to on the built-in pairs
# (tests/stiffness/test_influence_coefficients.cc: k 1 %, TE 0.1 um, load shares 0.01; the
# unloaded TE is the same geometry, 1 nm). With friction since session 54 (the pairs stick or slip
# as the exact path's contact lets them, docs/ltca.md §4 "Friction"): the 19 2D cases with
# friction among 0-39 of seed 20261201 (mu 0.004-0.096): |dk| 0.52 %, |dTE| 0.024 um, |dshare|
# 0.0063 at most, and the torque ratio 0.70 % (case 20, mu 0.08; checked at 2 %, 3x). It carries
# rounded tips (docs/ltca.md "Tip rounding"): external gears' since
# 2026-12-05 (seed 20261201 cases 33, 61, 63, rounded and relieved or profile-mixed: |dk| 0.339,
# 0.354, 0.307 %, |dTE| 0.012-0.027 um; with the force line's slopes weighted by the strip's
# pressure, session 41: 0.269, 0.297, 0.240 %, |dTE| 0.009-0.023 um), rings' since the same day. INFLUENCE_KINDS: the
# modification kinds it accepts, every one since 2026-12-05 (before: "none"). Cost: one
# `stiffness` run of ~3 s per such case and one on 2 ranks (measured 2026-12-02: case 28 |dk|
# 0.521 %, |dTE| 0.0147 um, |dshare| 0.0018; case 2, a 36/90 pair of m 5 mm, |dk| 0.897 %,
# |dTE| 0.0427 um, |dshare| 0.0066: near the 1 %).
INFLUENCE_KINDS = tuple(MODIFICATIONS)
# The fast model's 2D root stresses (the FE body's fillets under the solved loads, docs/ltca.md
# "Root stress") against the exact rolling sweep's, both gears at every position. Measured
# 2026-12-07 on the 18 frictionless 2D cases among 0-39 of seed 20261201 (after the fillets took
# their flank's removal at the form circle): worst 4.03 % (case 33), 3.74, 3.70, 3.18 % next; on
# the built-in cases of test_influence_coefficients up to 5.75 % (tip rounding). Not 3x that:
# the difference is the two meshes' own fillet discretisation (the default pair at body size
# 0.7 -> 0.25 mm: the exact path moves by up to 3.9 %, the model by 3.3 %, and there they agree
# within 1.6 %), systematic, not noise; 7 % catches a wrong load or read while leaving the
# meshes' difference. Until the fillet blend, case 15's ring (crowned and sloped, a step at its
# form circle) read 123.8 (once), 85.2 (per position) and 135.4 MPa (the model) at its first
# position, and the comparison was left out where the exact meshes disagreed; now 86.2, 87.2
# and 85.4 MPa, every position compared.
INFLUENCE_ROOT_STRESS_RTOL = 0.07
# With friction the model's stick force near the pitch point is larger than the exact path's
# (docs/ltca.md §4 "Friction"): the 19 friction cases above, worst 9.41 % (case 20, mu 0.08, the
# pinion at its third position), 6.77, 5.46, 5.25 % next; 12 %: the frictionless 7 % plus that
# stated model difference, not 3x.
INFLUENCE_ROOT_STRESS_FRICTION_RTOL = 0.12
INFLUENCE_TORQUE_RATIO_RTOL = 0.02
# The kinds draw_case leaves unrounded (the fast model's kinds when rounding was added).
UNROUNDED_KINDS = ("none",)


def influence_equals_exact(case, runner, log, sweeps):
    friction = float(case["pair"]["Contact/Friction coefficient"])
    reasons = ([f"{case['modification']}: not a kind it takes"]
               if case["modification"] not in INFLUENCE_KINDS else [])
    if reasons:
        log(f"influence = exact: skipped ({'; '.join(reasons)})")
        return
    sets = sweep_sets(case, SWEEP_POSITIONS, "once")
    sets["Stiffness/contact model"] = "influence coefficients"
    # Any failure fails the case: case 23 of seed 20261201 (z 24 at x -0.24, m 3 mm) ended in
    # exit 3 "a flank grid point lies outside its gear's mesh" until the loads near the base
    # circle sank under the meshed chords (2026-12-05, stiffness/influence_sweep.cc flank_sink).
    fast, _, _ = runner.run("stiffness", sets)
    fast_equals_exact("influence", table(sweeps["once"], "stiffness_sweep"),
                      table(fast, "stiffness_sweep"), log, unloaded=True,
                      root_stress=INFLUENCE_ROOT_STRESS_RTOL if friction == 0.
                      else INFLUENCE_ROOT_STRESS_FRICTION_RTOL,
                      torque_ratio=INFLUENCE_TORQUE_RATIO_RTOL if friction != 0. else None)
    # Two ranks take a gear each, one rank both in turn, with the same factor of each gear
    # (stiffness/influence_sweep.cc, run_influence): every printed value but the costs equal.
    two, _, _ = runner.run("stiffness", sets, ranks=2)
    check_same_printed("influence on 2 ranks", fast, two, ["stiffness_sweep"])
    log("influence: 2 ranks = 1 rank, every printed value but the costs")
    influence_torque_list(sets, fast, runner, log)


# A torque list gives at each of its torques what that torque gives alone: the list solves a
# position at every torque in turn, each warm-started from the torque before, a single torque
# from the position before, and both converge to the one solution of the same problem (Newton
# to 1e-12 of the load a pair). Until session 43 the fast model built each position's force
# lines (levers, tilt, strips) under the list's largest torque: case 1 of seed 20261201 (9.9 um
# reliefs on both) gave k 202.775610 N/um at T within T/2, T, 2T against 202.768179 alone; now
# equal to the 12 printed digits. Tolerance 1e-10 relative (of the value, or absolute below 1):
# the report's 12 significant digits quantize by up to 5e-12, Newton stops at 1e-12 of the load.
TORQUE_LIST_RTOL = 1e-10


def influence_torque_list(sets, single, runner, log):
    torque_key = "Gear pair scene/pinion torque"
    torque = float(sets[torque_key])
    listed_sets = dict(sets)
    listed_sets["Stiffness/torques"] = ",".join(
        repr(t) for t in (0.5 * torque, torque, 2. * torque))
    listed, _, _ = runner.run("stiffness", listed_sets)
    at_torque = [row for row in table(listed, "te_sweep")
                 if abs(row["torque"] - torque) <= 1e-9 * torque]
    alone = table(single, "stiffness_sweep")
    if len(at_torque) != len(alone):
        raise CaseFailure(f"torque list: {len(at_torque)} rows at {torque} N*m, "
                          f"{len(alone)} alone")
    worst = 0.
    for i, (a, b) in enumerate(zip(alone, at_torque)):
        for key in ("stiffness", "transmission_error", "share_pair_m1", "share_pair_0",
                    "share_pair_p1"):
            x, y = a.get(key, 0.), b.get(key, 0.)
            check_close(f"torque list: position {i + 1} {key}", y, x,
                        TORQUE_LIST_RTOL * max(abs(x), 1.), 0.)
            worst = max(worst, abs(y - x) / max(abs(x), 1.))
    log(f"influence: torque list = each torque alone (largest difference {worst:.2g})")


def check_same_printed(label, a, b, tables):
    """Every value and the rows of `tables` of report b as in report a, costs and ranks aside."""
    differences = [k for k, v in a["values"].items()
                   if not any(w in k for w in WALL_CLOCK) and
                   b["values"].get(k, {}).get("value") != v.get("value")]
    for name in tables:
        for i, (x, y) in enumerate(zip(table(a, name), table(b, name))):
            differences += [f"{name}[{i}].{k}" for k, v in x.items()
                            if not any(w in k for w in WALL_CLOCK) and y.get(k) != v]
    if differences or len(table(a, tables[0])) != len(table(b, tables[0])):
        raise CaseFailure(f"{label} differs in {differences[:5]}")


def fast_equals_exact(label, exact_rows, fast_rows, log, unloaded=False, root_stress=None,
                      torque_ratio=None):
    """The influence-coefficient model's sweep rows against the exact path's: k 1 %, TE 0.1 um,
    load shares 0.01 (and the unloaded TE, the same geometry, 1 nm; with `root_stress`, both
    gears' root stresses within that relative tolerance; with `torque_ratio`, |T_wheel/T1|)."""
    worst = [0., 0., 0.]
    worst_root = worst_ratio = 0.
    for i, (a, b) in enumerate(zip(exact_rows, fast_rows)):
        if torque_ratio is not None:
            check_close(f"{label}: position {i} torque ratio", b["torque_ratio"],
                        a["torque_ratio"], 0., torque_ratio)
            worst_ratio = max(worst_ratio, abs(b["torque_ratio"] / a["torque_ratio"] - 1.))
        if root_stress is not None:
            for gear in ("pinion_root_stress", "wheel_root_stress"):
                check_close(f"{label}: position {i} {gear} [MPa]", b[gear], a[gear], 0.,
                            root_stress)
                worst_root = max(worst_root, abs(b[gear] / a[gear] - 1.))
        if unloaded:
            check_close(f"{label}: position {i} unloaded TE [um]",
                        b["unloaded_transmission_error"], a["unloaded_transmission_error"], 1e-3)
        check_close(f"{label}: position {i} k [N/um]", b["stiffness"], a["stiffness"], 0., 1e-2)
        check_close(f"{label}: position {i} TE [um]", b["transmission_error"],
                    a["transmission_error"], 0.1)
        for sa, sb in zip(shares(a), shares(b)):
            check_close(f"{label}: position {i} load share", sb, sa, 1e-2)
        worst = [max(worst[0], abs(b["stiffness"] / a["stiffness"] - 1.)),
                 max(worst[1], abs(b["transmission_error"] - a["transmission_error"])),
                 max(worst[2], max(abs(x - y) for x, y in zip(shares(a), shares(b))))]
    log(f"{label} = exact: |dk| {worst[0] * 100:.3g} %, |dTE| {worst[1]:.3g} um, "
        f"|dshare| {worst[2]:.2g}" +
        (f", |droot stress| {worst_root * 100:.3g} %" if root_stress is not None else "") +
        (f", |dtorque ratio| {worst_ratio * 100:.3g} %" if torque_ratio is not None else ""))


def face_load_factors_equal(label, exact, fast, log):
    """The model's K_Hbeta against the exact path's at every position: the issue's 2 %."""
    worst = 0.
    for i, (a, b) in enumerate(zip(table(exact, "face_load_factor"),
                                   table(fast, "face_load_factor"))):
        check_close(f"{label}: position {i} K_Hbeta", b["face_load_factor"],
                    a["face_load_factor"], 0., 2e-2)
        worst = max(worst, abs(b["face_load_factor"] / a["face_load_factor"] - 1.))
    log(f"{label}: |dK_Hbeta| {worst * 100:.3g} %")


def geometric_te(case, rows, log):
    """The unloaded TE the modification kind implies, at every position (per-position rows)."""
    kind = case["modification"]
    unloaded = [r["unloaded_transmission_error"] for r in rows]
    if kind in ("none", "relief pinion only", "relief wheel only"):
        for i, u in enumerate(unloaded):
            check_close(f"{kind}: position {i} unloaded TE [um]", u, 0., 1e-3)
        log(f"{kind}: unloaded TE 0 at every position")
    elif kind == "long relief both":
        amount = case["modifications"]["Gear pair/Pinion/tip relief"]
        e = case["contact_ratio"] - 1.
        geometry = case["geometry"]
        lowered = 0.
        for i, r in enumerate(rows):
            x = r["mesh_position"] % 1.
            tent = relieved_tent(geometry, geometry["A"] + x * geometry["base_pitch"], x, e,
                                 amount) if x <= e else 0.
            lowered = max(lowered, amount * min(x, e - x) / e - tent if x <= e else 0.)
            check_close(f"tent: position {i} (x = {x:.4f}) unloaded TE [um]",
                        r["unloaded_transmission_error"], tent, 1e-3)
        log(f"tent: the unloaded TE of equal long reliefs ({amount} um) at every position, "
            f"where the relieved flanks touch (at most {lowered:.3g} um below the relief at l)")


def touching(removal, slope, to_kink, radius):
    """Where rigid flanks with a linear relief touch (the closed form of
    geometry::touching_point): the gap removal + slope*x + x^2/(2R) over the tangential offset x
    (mm) down to the relief's start at x = -to_kink, flat 0 beyond it; slope dimensionless, removal
    and result in um, R in mm. Smallest at x = -slope*R (slope^2*R/2 lower) or at the kink."""
    if slope * radius <= to_kink:
        return removal - 0.5 * slope * slope * radius * 1e3
    return to_kink * to_kink / (2. * radius) * 1e3


def relieved_tent(geometry, at, x, e, amount):
    """The unloaded TE (um) at mesh position x (0 <= x <= e = eps_alpha - 1) of equal linear long
    reliefs `amount` (um) from the start of single contact: the entering pair at l = `at` (mm from
    T1) relieved by the wheel's tip, amount*(e - x)/e, the leaving one at l + p_bt by the pinion's,
    amount*x/e, both sloped amount/(e*p_bt) a unit of l; each where its flanks touch (touching),
    the slope across the contact r_b/rho a unit of l, the relative radius rho1*rho2/(rho2 +- rho1)
    (a ring's flank concave)."""
    p_b, r_b1, r_b2 = geometry["base_pitch"], geometry["r_b1"], geometry["r_b2"]
    t1t2, ring = geometry["t1t2"], geometry["internal"]
    per_l = amount * 1e-3 / (e * p_b)  # -, um/mm

    def pair(l, removal, of_wheel, to_kink_l):
        rho1, rho2 = l, (l + t1t2 if ring else t1t2 - l)
        radius = 1. / (1. / rho1 + (-1. if ring else 1.) / rho2)
        k = r_b2 / rho2 if of_wheel else r_b1 / rho1
        return touching(removal, per_l * k, to_kink_l / k, radius)

    return min(pair(at, amount * (e - x) / e, True, (e - x) * p_b),
               pair(at + p_b, amount * x / e, False, x * p_b))


def check_peak_located(label, roll, face, a, e, h_c, half_width):
    """The peak's node on the path A - h_c .. E + h_c (mm, roll from T1) and within the face,
    |face| <= half_width (mm; 0 in 2D)."""
    if not (a - h_c <= roll <= e + h_c and abs(face) <= half_width + 1e-9):
        raise CaseFailure(f"{label}: peak pressure at roll {roll} mm, {face} mm from the middle "
                          f"of the face, off A {a} .. E {e} mm (h_c {h_c}) or b/2 {half_width} mm")


def peak_on_path(label, report, log):
    """Where the largest pressure acts (max_pressure_roll, _face, _wheel_roll): a closed pinion
    node of a loaded pair, so on the path of contact A-E (its roll length from T1) to within one
    contact cell h_c (the wheel tip's corner touches the pinion flank at A; the nodes it closes
    lie within a cell of it; no pinion node lies beyond its tip, E), across the face within b/2
    (2D: 0); the same point on the wheel (its roll on the path's scale) on A - h_c .. E + h_c too
    (no wheel point lies beyond its tip, A). The sweep's tip_edge_contact flag is set exactly
    when the wheel's roll is within h_c of A or the pinion's within h_c of E
    (app/stiffness/stiffness_report.cc). Catches a peak taken from another pair or tooth (off by
    a base pitch), a location left unset (0), a wheel roll on the wrong wheel axis, and the
    flag's wiring."""
    a, e, h_c = (value(report, k) for k in ("contact_start", "contact_end", "contact_size"))
    rows = table(report, "stiffness_sweep")
    off_line = 0.
    for i, r in enumerate(rows):
        roll, wheel_roll = r["max_pressure_roll"], r["max_pressure_wheel_roll"]
        check_peak_located(f"{label}: position {i}", roll, r["max_pressure_face"], a, e, h_c,
                           0.)
        check_peak_located(f"{label}: position {i} (wheel)", wheel_roll, 0., a, e, h_c, 0.)
        off_line = max(off_line, abs(wheel_roll - roll))
        edge = wheel_roll <= a + h_c or roll >= e - h_c
        if bool(r["tip_edge_contact"]) != edge:
            raise CaseFailure(f"{label}: position {i} tip_edge_contact {r['tip_edge_contact']} "
                              f"with the peak at roll {roll} mm, wheel roll {wheel_roll} mm "
                              f"(A {a}, E {e}, h_c {h_c} mm)")
    flagged = sum(1 for r in rows if r["tip_edge_contact"])
    log(f"{label}: every peak pressure on the path A-E, {flagged} of {len(rows)} at a tip edge; "
        f"pinion and wheel roll of the peak at most {off_line:.3g} mm apart")


# The identities that compare two paths on one mesh (zero = none, Python = command line) hold
# for any discretisation, so they run on Q1 elements: the same meshes and code paths at a
# fraction of the Q2 solve (issue 43). The sweeps of once = per position keep the default Q2:
# their tolerances are the two meshes' discretisation differences.
SAME_MESH_IDENTITY = {"Finite elements/Element degree": 1}


def names_its_build(runner, log, sweeps):
    """Every result names the build that produced it (summary.json's "gearstiff" block): both
    sweeps of the case name the version and revision `gearstiff --version` prints, and the
    libraries its second line lists."""
    if not hasattr(runner, "build"):
        lines = runner.timed([runner.gearstiff, "--version"]).stdout.splitlines()
        runner.build = lines[:2]
    for label in ("once", "per position"):
        block = sweeps[label].get("gearstiff", {})
        first = f"gearstiff {block.get('version')} (revision {block.get('revision')})"
        libraries = "built against " + ", ".join(
            f"{name} {version}" for name, version in block.get("libraries", {}).items())
        if [first, libraries] != runner.build:
            raise CaseFailure(f"the {label} sweep names {first!r}, {libraries!r}; "
                              f"gearstiff --version prints {runner.build!r}")
    log(f"names its build: {runner.build[0]}")


def zero_equals_none(case, runner, log, sweeps):
    """Zero modifications and a zero crack on a modelled tooth give every printed value of the
    plain pair. (A crack on a tooth out of mesh is no such identity: the scene refuses a tooth it
    does not model, and a modelled unloaded tooth's cracked root still feels the rim's bending.)"""
    sets = dict(case["pair"], **SAME_MESH_IDENTITY)
    plain, _, _ = runner.run("stiffness", sets)
    variants = [{"Gear pair/Pinion/tip relief": 0}, {"Gear pair/Wheel/profile crowning": 0},
                {"Gear pair/Pinion/root relief": 0},
                {"Gear pair/Pinion/faulty tooth": 1, "Gear pair/Pinion/crack depth": 0}]
    for variant in variants:
        report, _, _ = runner.run("stiffness", dict(sets, **variant))
        differences = [k for k, v in plain["values"].items()
                       if not any(w in k for w in WALL_CLOCK) and
                       report["values"].get(k, {}).get("value") != v.get("value")]
        if differences:
            raise CaseFailure(f"{variant} differs from none in {differences[:5]}")
    log("zero modification = none, zero crack = healthy: every printed value equal")


def ranks_agree(case, runner, log, sweeps):
    # The one-rank run is the per-position sweep of once = per position (same settings).
    one = sweeps["per position"]
    two, _, _ = runner.run("stiffness", sweep_sets(case, SWEEP_POSITIONS, "per position"),
                           ranks=2)
    for i, (a, b) in enumerate(zip(table(one, "stiffness_sweep"), table(two, "stiffness_sweep"))):
        check_close(f"position {i} k [N/um], 2 ranks", b["stiffness"], a["stiffness"], 0., 1e-6)
        check_close(f"position {i} TE [um], 2 ranks", b["transmission_error"],
                    a["transmission_error"], 1e-6)
    log("2 ranks = 1 rank: k and TE to 1e-6")


def mesh_contact_equals_stiffness(runner, log, sets, single):
    """`gearstiff mesh` writes the stiffness command's scene (`Scene/gear pair defaults =
    stiffness`, coordinates in metres) and `gearstiff contact` solves it as a user's own mesh:
    bodies `pinion body, wheel body`, every pinion flank against every wheel flank, the wheel bore
    fixed, a torque hub on the pinion bore about the origin (the pinion's axis in a scene), the
    face width as the thickness. Its hub rotation less the turn that closes the smallest initial
    gap (the meshed chords start nanometres apart; the stiffness command takes that turn out,
    stiffness/mesh_stiffness.cc) is the stiffness command's pinion rotation: the same discrete
    problem solved by two commands, 1e-6 relative (3e-9 measured on the built-in pair at its
    pitch point, Q2, mu 0 and 0.01, session 48)."""
    out = tempfile.mkdtemp(prefix="mesh", dir=runner.work)
    mesh_sets = {k: v for k, v in sets.items() if k.startswith(("Gear pair/", "Gear pair scene/"))}
    # The mesh command's default position with the stiffness defaults is the stiffness command's
    # `single` one (the pitch point in single contact, else the single zone's middle); a typed
    # roll angle of the same position (12 digits) meshed the contact zone otherwise (case 6:
    # 0.06 % apart).
    mesh_sets["Scene/gear pair defaults"] = "stiffness"
    runner.run("mesh", mesh_sets, out=os.path.join(out, "scene"))
    path = os.path.join(out, "scene", "scene.msh")
    with open(path) as f:
        names = f.read().split("$PhysicalNames")[1].split("$EndPhysicalNames")[0]
    # The stiffness command's tooth pairs: those on the path of contact at the position (its
    # load_share_pair_<j> keys, m for minus). A pair just beyond the path is a free surface there
    # by design (docs/calculix.md): seed 20261201 case 2 (36/90, m 5 mm, 443.6 N·m, unmodified)
    # has the leaving pair's pinion tip corner 0.66 mm beyond E with a 1.31 um gap against a
    # 6.58 um TE, which `contact` with every flank closes (hub rotation 77.80 -> 60.61 urad).
    pairs = [key[len("load_share_pair_"):].replace("m", "-") for key in single["values"]
             if key.startswith("load_share_pair_")]
    groups = re.findall(r'"((?:pinion|wheel) flank -?\d+)"', names)
    flanks = {gear: ", ".join(f"{gear} flank {j}" for j in pairs) for gear in ("pinion", "wheel")}
    for gear in ("pinion", "wheel"):
        for j in pairs:
            if f"{gear} flank {j}" not in groups:
                raise CaseFailure(f"mesh + contact: the scene has no group '{gear} flank {j}'")
    torque = float(sets["Gear pair scene/pinion torque"])
    contact_sets = {
        "Mesh/File": path, "Mesh/Length unit": 1, "Bodies/Names": "pinion body, wheel body",
        "Contact/Slave surfaces": flanks["pinion"], "Contact/Master surfaces": flanks["wheel"],
        "Contact/Friction coefficient": sets["Contact/Friction coefficient"],
        "Supports/Fixed": "wheel bore", "Supports/Displacements": "",
        "Supports/Hub torques": f"pinion bore: {torque}, 0, 0",
        "Finite elements/Thickness": min(float(sets[f"Gear pair/{g}/face width"])
                                          for g in ("Pinion", "Wheel")),
        "Finite elements/Element degree": sets.get("Finite elements/Element degree", 2)}
    contact, _, _ = runner.run("contact", contact_sets)
    shutil.rmtree(out, ignore_errors=True)
    gap = value(contact, "initial_gap")  # um
    turn = 1e3 * gap / value(single, "pinion_base_radius")  # um / mm = 1e-3 rad: urad
    rotation = value(contact, "support_pinion bore_rotation") - turn
    check_close("mesh + contact: pinion rotation less the touching turn [urad]", rotation,
                value(single, "pinion_rotation"), 0., 1e-6)
    log(f"mesh + contact = stiffness: pinion rotation {rotation:.6f} urad (hub "
        f"{rotation + turn:.6f} less {turn:.6f} for the initial gap {gap:.3g} um), "
        f"pairs {', '.join(pairs)}")


def python_equals_cli(case, runner, log, sweeps):
    """The Python module's stiffness equals the command line's; and the same single position
    through `gearstiff mesh` and `gearstiff contact` (mesh_contact_equals_stiffness)."""
    sets = dict(case["pair"], **SAME_MESH_IDENTITY)
    sets.update(case["modifications"])
    cli, _, _ = runner.run("stiffness", sets)
    mesh_contact_equals_stiffness(runner, log, sets, cli)
    if not runner.python_path:
        log("Python = command line: skipped (no --python-path)")
        return
    # The module takes the .prm's sections as a nested dict.
    params = {}
    for key, v in sets.items():
        *sections, name = key.split("/")
        node = params
        for section in sections:
            node = node.setdefault(section, {})
        node[name] = str(v)
    script = ("import gearstiff, json, sys\n"
              "r = gearstiff.stiffness(json.loads(sys.argv[1]))\n"
              "print(json.dumps({'k': r['values']['mesh_stiffness']['value'],"
              " 'te': r['values']['transmission_error']['value']}))\n")
    env = dict(os.environ, PYTHONPATH=runner.python_path)
    process = runner.timed([sys.executable, "-c", script, json.dumps(params)], env=env)
    if process.returncode != 0:
        raise CaseFailure(f"Python: {process.stderr.strip()[-600:]}")
    python = json.loads(process.stdout.strip().splitlines()[-1])
    # The command line prints 12 significant digits (app/core/report.cc): 1e-11 relative.
    check_close("Python k [N/um]", python["k"], value(cli, "mesh_stiffness"), 0., 1e-11)
    check_close("Python TE [um]", python["te"], value(cli, "transmission_error"), 0., 1e-11)
    log("Python = command line: k and TE")


def own_train(case, runner, log, sweeps):
    """The sweep's stiffness_table.prm runs this pair in `gearstiff dynamics`: its mesh frequency
    is z1*n1/60, its mean stiffness the sweep's mean k (uniform positions over one base pitch:
    the mean of the periodic linear interpolation is the mean of the samples), and at a
    quasi-static speed, without tooth friction (whose moments change the static force by about
    mu*tan(alpha_w), ~0.5-1 %), the mesh force is the static one: K_v = 1. The residual
    vibration each stiffness ramp of the table leaves grows with the speed (measured on a 25/40
    pair, m 8 mm: K_v - 1 = 0.0216, 0.0070, 0.0032, 0.0016 at 5, 2, 1, 0.5 % of the resonance
    speed); at 0.5 % the tolerance is 0.5 %, three times that. The sweep is the rolling one of
    once = per position (5 positions, was a sweep of 6 of its own), written to a folder for this
    identity: K_v - 1 = 0.0007 ... 0.0016 on the 7 own-train cases of the suite's 30 (seed
    20261201, measured 2026-12-01)."""
    sweep, out = sweeps["once"], sweeps["once_out"]
    table_file = os.path.join(out, "stiffness_table.prm")
    with open(table_file) as f:
        text = f.read()
    z1 = int(case["pair"]["Gear pair/Pinion/teeth"])
    if f"z {z1}/" not in text:
        raise CaseFailure(f"stiffness_table.prm does not name this pair:\n{text[:400]}")
    # The table runs the train at the torque its k(x) was solved at, which the summary states
    # (`pinion_torque`, read by `gearstiff dynamics` for its load check): the same number.
    gear1 = re.search(r"subsection Gear 1\n(?:.*\n)*?\s*set torque = ([-+0-9.eE]+)", text)
    if gear1 is None:
        raise CaseFailure(f"stiffness_table.prm sets no Gear 1 torque:\n{text[:400]}")
    check_close("table torque = summary pinion_torque [N m]", float(gear1.group(1)),
                value(sweep, "pinion_torque"), 0., 1e-9)
    resonance = float(text.split("resonance speed n_E1 = ")[1].split()[0])
    speed = 0.005 * resonance
    args = [runner.gearstiff, "dynamics", table_file, "--json", "--quiet",
            "--set", f"Train/input speed={speed:.8g}",
            "--set", "Mesh 1/friction coefficient=0"]
    process = runner.timed(args)
    if process.returncode != 0:
        raise CaseFailure(f"dynamics on stiffness_table.prm exited {process.returncode}: "
                          f"{process.stderr.strip()[-600:]}")
    dynamics = json.loads(process.stdout)
    check_close("mesh frequency [Hz]", value(dynamics, "mesh_frequency"), z1 * speed / 60.,
                0., 1e-6)
    k = [r["stiffness"] for r in table(sweep, "stiffness_sweep")]
    check_close("mean stiffness [N/um]", value(dynamics, "mesh1_mean_stiffness"),
                sum(k) / len(k), 0., 1e-6)
    check_close("K_v max at quasi-static speed", value(dynamics, "mesh1_kv_max"), 1., 5e-3)
    log(f"own train: dynamics runs this pair (f_z {value(dynamics, 'mesh_frequency'):.5g} "
        f"Hz, mean k {sum(k) / len(k):.5g} N/um, quasi-static K_v "
        f"{value(dynamics, 'mesh1_kv_max'):.5f})")
    own_train_nonlinear(runner, log, sweep, out, table_file, speed)
    own_outputs_as_inputs(runner, log, out, table_file)
    own_cai_train(case, runner, log, sweep)


def own_cai_train(case, runner, log, sweep):
    """`gearstiff cai` on the case's pair fits its curve to the same FE sweep as `stiffness`'s
    once sweep (the same settings and positions: its FE mean k is that sweep's mean to the
    printed digits, 1e-9), and its cai_calibrated.prm runs this pair alone in `gearstiff
    dynamics` (until session 49 it put the curve on the built-in split-path gearbox): the mesh
    frequency z1*n1/60 and the calibrated curve's mean stiffness over this pair's eps_alpha
    (cai_mean_mesh_stiffness; the scale carried with 10 digits: 1e-6)."""
    out = os.path.join(runner.work, f"cai-{case['pair']['Gear pair/Pinion/teeth']}")
    sets = sweep_sets(case, SWEEP_POSITIONS, "once")
    del sets["Stiffness/mode"]
    cai, _, _ = runner.run("cai", sets, out=out)
    k = [r["stiffness"] for r in table(sweep, "stiffness_sweep")]
    check_close("cai's FE mean k = the stiffness sweep's [N/um]",
                value(cai, "fe_mean_mesh_stiffness"), sum(k) / len(k), 0., 1e-9)
    # The report says when the curve misses the FE mean by more than 5 % (scale-only fits of
    # relieved pairs: +5 ... +16 % on cases 3, 7, 11, 15), and only then.
    deviation = value(cai, "cai_mean_mesh_stiffness") / value(cai, "fe_mean_mesh_stiffness") - 1.
    if (abs(deviation) > 0.05) != ("fit check" in cai.get("text", {})):
        raise CaseFailure(f"cai: the curve's mean is {deviation:+.2%} off the FE's, its fit check "
                          f"is {'missing' if abs(deviation) > 0.05 else 'given'}")
    prm = os.path.join(out, "cai_calibrated.prm")
    with open(prm) as f:
        text = f.read()
    z1 = int(case["pair"]["Gear pair/Pinion/teeth"])
    if f"z {z1}/" not in text or "subsection Mesh 2" in text:
        raise CaseFailure(f"cai_calibrated.prm is not this pair's one-mesh train:\n{text[:600]}")
    speed = 1000.
    process = runner.timed([runner.gearstiff, "dynamics", prm, "--json", "--quiet",
                            "--set", f"Train/input speed={speed:g}",
                            "--set", "Speed sweep/points=0"])
    if process.returncode != 0:
        raise CaseFailure(f"dynamics on cai_calibrated.prm exited {process.returncode}: "
                          f"{process.stderr.strip()[-600:]}")
    dynamics = json.loads(process.stdout)
    check_close("cai train mesh frequency [Hz]", value(dynamics, "mesh_frequency"),
                z1 * speed / 60., 0., 1e-9)
    check_close("cai train mean k = the curve's [N/um]", value(dynamics, "mesh1_mean_stiffness"),
                value(cai, "cai_mean_mesh_stiffness"), 0., 1e-6)
    log(f"own cai: the FE mean {value(cai, 'fe_mean_mesh_stiffness'):.6g} N/um = the sweep's, "
        f"the curve's {deviation:+.2%} off it{' (stated)' if abs(deviation) > 0.05 else ''}; "
        f"the calibrated curve (scale {value(cai, 'cai_scale'):.5g} N/um, relative rms "
        f"{value(cai, 'fit_relative_rms'):.3g}) drives this pair, mean k "
        f"{value(dynamics, 'mesh1_mean_stiffness'):.6g} N/um")


def own_outputs_as_inputs(runner, log, out, table_file):
    """The sweep's outputs given where they do not belong (since 2026-12-06 bad input, exit 2
    naming the file): its stiffness_table.prm to `cai` holds nothing `cai` takes and names
    `gearstiff dynamics`, which reads it (it ran the built-in pair under a note); its summary.json
    as `dynamics`' parameter file is a result summary, not parameters (it was refused by its
    first array)."""
    for command, given, expected in (
            ("cai", table_file, r"stiffness_table\.prm: holds no parameter `cai` takes: "
                                r".*`gearstiff dynamics` reads it"),
            ("dynamics", os.path.join(out, "summary.json"),
             r"summary\.json: is the result summary of `gearstiff stiffness`, "
             r"not a parameter file")):
        process = runner.timed([runner.gearstiff, command, given, "--quiet"])
        if process.returncode != 2 or not re.search(expected, process.stderr):
            raise CaseFailure(f"{command} {os.path.basename(given)}: expected exit 2 matching "
                              f"'{expected}', got {process.returncode}: "
                              f"{process.stderr.strip()[-300:]}")
    log("own outputs as inputs: the table refused by cai, the summary by dynamics (exit 2)")


def own_train_nonlinear(runner, log, sweep, out, table_file, speed):
    """The sweep's summary.json as the nonlinear model's TE file: at the quasi-static speed its
    mean dynamic TE is the model's own quasi-static one, the cycle mean of e(x) + W/k(x) with k
    and e interpolated linearly between the table's positions and W = k·(s − e) of the rows
    (dynamics/README.md "The split of the FE loaded STE"). Modified teeth carry e != 0: this is
    the path that refused every modified pair until session 19 (k·s is not one load case when
    k = W/(s − e); and an internal pair's file was refused as "another pair", z2 -86 against
    86). 1e-4: the seven own-train cases of the suite agree to the 6 digits logged (measured
    2026-12-02); the vibration left at this speed (K_v - 1 below 2e-3) averages out of the mean
    to 1e-4 in the model's own quasi-static test (tests/dynamics/test_nonlinear_mesh.cc)."""
    args = [runner.gearstiff, "dynamics", table_file, "--json", "--quiet",
            "--set", f"Train/input speed={speed:.8g}", "--set", "Mesh 1/friction coefficient=0",
            "--set", "Simulation/mesh model=nonlinear", "--set", "Mesh 1/backlash=1000",
            "--set", "Mesh 1/transmission error file=" + os.path.join(out, "summary.json"),
            "--set", "Speed sweep/points=0"]
    process = runner.timed(args)
    if process.returncode != 0:
        raise CaseFailure(f"nonlinear dynamics with the sweep's TE exited {process.returncode}: "
                          f"{process.stderr.strip()[-600:]}")
    rows = table(sweep, "stiffness_sweep")
    x = numpy.array([r["mesh_position"] for r in rows]) % 1.
    k = numpy.array([r["stiffness"] for r in rows])
    e = numpy.array([r["unloaded_transmission_error"] for r in rows])
    load = numpy.mean(k * (numpy.array([r["transmission_error"] for r in rows]) - e))
    # The model's k(x) and e(x): periodic linear interpolation over one base pitch.
    at = (numpy.arange(4000) + 0.5) / 4000
    quasi_static = numpy.mean(numpy.interp(at, x, e, period=1.) +
                              load / numpy.interp(at, x, k, period=1.))
    dynamic = json.loads(process.stdout)
    check_close("nonlinear mean DTE [um]", value(dynamic, "mesh1_mean_dte"), quasi_static, 0.,
                1e-4)
    log(f"own train, nonlinear with the sweep's TE: mean DTE "
        f"{value(dynamic, 'mesh1_mean_dte'):.6g} um = quasi-static {quasi_static:.6g} um "
        f"(unloaded TE up to {numpy.abs(e).max():.3g} um)")


THREE_D_POSITIONS = 2  # one in each contact zone of the base pitch (double, then single)


def three_d_between_plane_models(case, runner, log):
    """A straight 3D tooth pair is stiffer than plane stress (its middle is held across the face)
    and softer than plane strain (its end faces are free): k_stress < k_3D < k_strain at every
    position, all three Q1 on the same in-plane cell sizes. The 3D sweep is also the reference of
    the 3D influence-coefficient model (influence_3d_equals_exact)."""
    # Frictionless: the identity is about the bodies' stiffness. With friction 3D needs the
    # Tresca fixed point to converge, which it did not at mu = 0.098 on case 19 of seed 20261201
    # (exit 3 after 40 and after 150 iterations, "0 nodes still changing state"): a known limit
    # of the 3D frictional solver, not of this identity.
    sets = dict(case["pair"], **{"Finite elements/Element degree": 1,
                                 "Contact/Friction coefficient": 0,
                                 "Stiffness/published reference": "false",
                                 "Stiffness/mode": "sweep",
                                 "Stiffness/sweep positions": THREE_D_POSITIONS,
                                 "Stiffness/sweep mesh": "once"})
    k, three_d = {}, None
    for name, extra in (("plane stress", {"Finite elements/Planar model": "plane stress"}),
                        ("plane strain", {"Finite elements/Planar model": "plane strain"}),
                        ("3D", {"Mesh/dimension": 3, "Mesh/layers": 4})):
        report, _, _ = runner.run("stiffness", dict(sets, **extra))
        k[name] = [row["stiffness"] for row in table(report, "stiffness_sweep")]
        if name == "3D":
            three_d = report
    for i, (stress, solid, strain) in enumerate(zip(k["plane stress"], k["3D"], k["plane strain"])):
        if not stress < solid < strain:
            raise CaseFailure(f"position {i}: 3D k {solid} N/um not between plane stress "
                              f"{stress} and plane strain {strain} N/um")
    log("3D between the plane models: " + "; ".join(
        f"{a:.5g} < {b:.5g} < {c:.5g} N/um" for a, b, c in
        zip(k["plane stress"], k["3D"], k["plane strain"])))
    influence_3d_equals_exact(case, runner, log, dict(sets, **{"Mesh/dimension": 3,
                                                               "Mesh/layers": 4}), three_d)
    influence_3d_crowned_equals_exact(case, runner, log, dict(sets, **{"Mesh/dimension": 3}),
                                      table(three_d, "stiffness_sweep"))


# The 3D influence-coefficient model (docs/ltca.md, 3D) on the case's own pair, against the exact
# 3D sweep of the same settings (Q1, 4 layers, frictionless, unmodified) at the accuracy it is
# tested to on the built-in pair (tests/stiffness/test_influence_3d.cc: k 1 %, TE 0.1 um, load
# shares 0.01). Internal pairs too since 2026-12-03 (ltca47k: end faces in plane stress, since 2026-12-05 the quarter-space's layer; the
# ring's rim cells at most a third of its thickness): cases 69 and 79 of seed 20261201 (21/-64 m 6,
# 29/-72 m 1.25), run through the command line with this check's settings: |dk| 0.241, 0.311 %,
# |dTE| 0.0154, 0.0135 um, |dshare| 5e-5, 0.0007 (single runs, exact 28-35 s, the model 4.5-5 s).
# Measured 2026-12-02 (seed 20261201, loaded machine): cases 9, 19, 29 (31/74 m 2, 23/50 m 4,
# 25/85 m 2): |dk| 0.46, 0.51, 0.45 %, |dTE| 0.024, 0.037, 0.011 um, |dshare| <= 0.0006; the
# model's run 11-26 s beside the three sweeps of three_d_between_plane_models' 38-62 s. With the
# rim coarse beyond the modelled teeth (ltca47g, the same day): |dk| 0.567, 0.494, 0.425 %,
# |dTE| 0.026, 0.036, 0.011 um, the model's run 5.5-8.7 s.
def influence_3d_equals_exact(case, runner, log, sets, exact):
    model = {"Stiffness/contact model": "influence coefficients"}
    fast, _, _ = runner.run("stiffness", dict(sets, **model))
    fast_equals_exact("influence 3D", table(exact, "stiffness_sweep"),
                      table(fast, "stiffness_sweep"), log)
    # K_Hbeta of the uncrowned face: the end planes' layer (stiffness::end_face_layer_excess)
    # decides it, so the model must meet the issue's 2 % here too (the built-in and planet-ring
    # pairs at 4 layers: +0.49 ... +0.56 %, tests/stiffness/test_influence_3d*.cc).
    face_load_factors_equal("influence 3D", exact, fast, log)
    # The end faces' limit: node planes at least 1.35 matching depths h = 3 * 0.08 * m_n apart
    # (stiffness/influence_checks.cc, min_uncrowned_spacing; docs/ltca.md section 3 "End faces").
    # One layer more than floor(b / (1.35 h)) is refused before any mesh, naming Mesh/layers and
    # that floor (a few tenths of a second).
    width = min(float(case["pair"][f"Gear pair/{g}/face width"]) for g in ("Pinion", "Wheel"))
    depth = 3 * 0.08 * float(case["pair"]["Gear pair/Pinion/module"])
    most = width / (1.35 * depth)
    if abs(most - round(most)) < 1e-6:
        return  # on the boundary: round-off decides
    most = math.floor(most)
    _, code, stderr = runner.run("stiffness", dict(sets, **model, **{"Mesh/layers": most + 1}),
                                 allowed=(2,))
    refusal = re.search(r"error: Mesh/layers: .*uncrowned face .* use at most (\d+) layers",
                        stderr)
    if code != 2 or refusal is None or int(refusal.group(1)) != most:
        raise CaseFailure(f"influence 3D at {most + 1} layers: expected exit 2 naming Mesh/layers "
                          f"and at most {most} layers, got exit {code}: {stderr.strip()[-300:]}")
    log(f"influence 3D: {most + 1} layers refused, names Mesh/layers and at most {most}")


# Lead crowning through the 3D fast model on the case's own pair (issue 47: "each with and
# without ... lead crowning"): C_beta 5-15 um drawn from a stream of its own (the case's other
# draws stay as they were) on the pinion, the wheel or both in turn, against the exact path on
# the same settings: k 1 %, TE 0.1 um, shares 0.01, and the sweep's K_Hbeta 2 % (the issue's; the
# built-in and planet-ring pairs at C_beta 10 um are within 0.76 % and 0.58 %,
# tests/stiffness/test_influence_3d_lead.cc). The layers: 16 (the fewest the model takes with
# crowning); where a light load's crowned contact ends inside the face on fewer node planes than
# the model resolves (7), it refuses with the layers it needs (exit 2 naming Mesh/layers; its
# numbers checked here). Both paths then run under a torque raised by (`resolved_planes` /
# planes)² on the same 16 layers (the crowned contact's width grows about as the root of the
# approach, the approach about as the load), and only if that is refused too on enough layers
# for `resolved_planes` planes. Not on more layers first: case 29 of seed 20261201 (C_beta 13 um
# on both gears, 5 planes at 16.02 N·m) on 32 layers (11 planes) was within +0.11/+0.34 % of the
# exact path (2026-12-04), but the exact path's 790k DoFs a position factor out of core
# (fem/stiffness_factorization.cc, from 500k): 1035 s of the check's 1158 s on 2 ranks (one run,
# 2026-12-06), and the shard timed out in CI beside another. At 4 × 16.02 N·m on 16 layers
# (490k DoFs, in core) the model is accepted and within +0.31/+0.17 % of the exact path (TE
# 0.046/0.026 um, shares 0.0012/0.0017, K_Hbeta +0.82/+0.57 %); the check 331 s (model refused
# 27 s, accepted 28 s, exact 276 s; one run each, 2026-12-06). At 24 layers (7 planes) the case
# had the model +1.04/+0.88 % above the exact path, mostly the exact path's own layer error
# (−0.75/−0.52 % against its 32 layers, the model's +0.17/+0.01 %). An accepted run stays at 16
# layers: the exact path's k moves by a few
# tenths of a percent between neighbouring layer counts on such faces without trend (case 9:
# 9 planes at 16 and at 18 layers, exact 245.58 → 244.98 N/um, model 247.20 → 247.51; the
# check passed at 16 with 0.66 %, failed at 18 with 1.03 %), so more layers are no better
# reference unless they add planes.
resolved_planes = 10


def one_position_sweep(sets, theta):
    """`sets` as a sweep of one position at pinion roll angle theta [deg]: an interval of a
    hundredth of a base pitch centred on it."""
    pitches = 0.01
    step = pitches * 360. / float(sets["Gear pair/Pinion/teeth"])
    return dict(sets, **{"Stiffness/sweep positions": 1, "Stiffness/sweep base pitches": pitches,
                         "Stiffness/sweep start": theta - 0.5 * step})


def influence_3d_crowned_model(runner, sets, layers, torque):
    """The fast model on `layers` (2 ranks): its report and None, or the refusal's loaded planes
    and the layers it names (exit 2 naming Mesh/layers; any other exit 2 fails the case). A
    crowned contact or a lead slope's, whichever the case drew."""
    fast, code, stderr = runner.run(
        "stiffness", dict(sets, **{"Stiffness/contact model": "influence coefficients",
                                   "Mesh/layers": layers}), ranks=2, allowed=(0, 2))
    if code == 0:
        return fast, None
    refusal = re.search(r"Mesh/layers: the (?:crowned contact|contact under the lead slope) is "
                        r"carried by only (\d+) node planes.*use at least (\d+) layers", stderr)
    if refusal is None:
        raise CaseFailure(f"influence 3D crowned at {torque} N·m: exit 2 without the layers' "
                          f"refusal: {stderr.strip()[-400:]}")
    return fast, (int(refusal.group(1)), int(refusal.group(2)))


# A lead slope and an end relief (carried on spur pairs since 2026-12-07: own-plane loads and the
# layer kernel, docs/ltca.md section 3 "End faces") take turns with crowning: a slope every other
# 3D case (CI's 19: on the wheel), an end relief every other of the rest (CI's 29: on both), the
# amount the same 5-15 um, the slope's sign and then L_I (a tenth to a quarter of the face)
# drawn after it from the same stream (the other draws stay as they were), to the same accuracy
# (the built-in and planet-ring pairs at 10 um: K_Hbeta within 1.12 % (slope) and 1.44 % (end
# relief), k within 0.40 %; tests/stiffness/test_influence_3d_lead.cc). They load the face
# without crowning's unloaded ends, so the uncrowned face's spacing holds (16 layers at least
# 1.35 h apart): a face too narrow for both is refused naming the contact model, checked, and
# the case is then crowned instead. Measured with the kernel at each plane's own line load
# (2026-12-07, seed 20261201, one run each, cases run one at a time; |dk|, |dK_Hbeta|): case 9
# crowned 13.2 um on the pinion 0.217 %, 0.08 % (0.611 %, 1.0 % with the hat); 19 slope 12.8 um
# on the wheel 0.139 %, 1.11 %; 29 end relief 13.0 um on both 0.129 %, 1.03 % (crowned before:
# 0.433 %, 0.858 % at 64.068 N·m); 39 slope 5.6 um on the pinion 0.044 %, 0.72 %; 59 slope
# 10.2 um on both 0.28 % K_Hbeta; 69 (internal, 21/-64 m 6) end relief 13.2 um on the pinion
# 0.068 %, 1.41 %. The uncrowned 4-layer check on cases 9, 19, 29, 39, 69: |dK_Hbeta| 0.45, 0.43,
# 0.57, 0.43, 0.64 %.
def influence_3d_crowned_equals_exact(case, runner, log, sets, uncrowned_rows):
    rng = random.Random(f"{case['seed']}:{case['index']}:crowning")
    amount = round(rng.uniform(5., 15.), 1)
    slope = amount * rng.choice((-1., 1.))
    # The crowned gear in turn (the 3D cases are every tenth: CI's 9, 19, 29 take one each).
    gears = [("Pinion",), ("Wheel",), ("Pinion", "Wheel")][case["index"] // 10 % 3]
    lead = "lead slope" if case["index"] // 10 % 2 == 1 else "lead crowning"
    if lead == "lead crowning" and case["index"] // 20 % 2 == 1:
        lead = "end relief"
    if lead != "lead crowning":
        width = min(float(case["pair"][f"Gear pair/{g}/face width"]) for g in ("Pinion", "Wheel"))
        depth = 3 * 0.08 * float(case["pair"]["Gear pair/Pinion/module"])
        if width / (1.35 * depth) < 16 - 1e-6:
            sloped = dict(sets, **{f"Gear pair/{gear}/lead slope": slope for gear in gears})
            _, code, stderr = runner.run("stiffness", dict(sloped, **{
                "Stiffness/contact model": "influence coefficients", "Mesh/layers": 16}),
                allowed=(2,))
            if code != 2 or not re.search(r"error: Stiffness/contact model: influence "
                                          r"coefficients with a lead slope or end relief need "
                                          r"16 layers", stderr):
                raise CaseFailure(f"influence 3D slope on a {width} mm face: expected exit 2 "
                                  f"naming the contact model, got exit {code}: "
                                  f"{stderr.strip()[-300:]}")
            log(f"influence 3D {lead}: refused on the {width} mm face (16 layers 1.35 h apart "
                "need more), names the contact model; crowned instead")
            lead = "lead crowning"
    value = slope if lead == "lead slope" else amount
    sets = dict(sets, **{f"Gear pair/{gear}/{lead}": value for gear in gears})
    if lead == "end relief":
        # L_I a tenth to a quarter of the face from each end, drawn after the slope's sign.
        width = min(float(case["pair"][f"Gear pair/{g}/face width"]) for g in ("Pinion", "Wheel"))
        length = round(width * rng.uniform(0.1, 0.25), 2)
        sets = dict(sets, **{f"Gear pair/{gear}/end relief length": length for gear in gears})
    # One position, the uncrowned check's double-contact one or its single-contact one in turn
    # (CI's 9 and 29 double, 19 single), as a one-position sweep centred on its roll angle, the
    # exact path on one rank. Two positions on 2 ranks (a position a rank) took the same wall
    # time and twice the processors: the exact path's 490k DoFs a position were 224-326 s of
    # cases 9 and 29 (2026-12-06), the costliest part of the suite after case 14's helicoids.
    # Measured alone, one run each (2026-12-06): case 9 at 14.6474 deg (double) |dk| 0.611 %,
    # K_Hbeta 1.0 %, exact 156 s; case 19 at 26.8693 deg (single) 0.49 %, 0.43 %, 69 s; case 29
    # at 10.5328 deg (double, 64.068 N·m) 0.433 %, 0.858 %, 264 s (the case 368 s, 1 core busy).
    # Since session 48 case 19 carries a 25 deg rack (rack_sets): at 33.4068 deg (single) 0.485 %,
    # 0.519 %, exact 32 s, the case 73 s alone (2026-12-06).
    theta = uncrowned_rows[case["index"] // 10 % 2]["roll_angle"]
    sets = one_position_sweep(sets, theta)
    torque_key = "Gear pair scene/pinion torque"
    layers = 16
    start = time.monotonic()
    fast, refused = influence_3d_crowned_model(runner, sets, layers, sets[torque_key])
    if refused:
        planes, needed = refused
        if planes >= 7:  # stiffness/influence_checks.cc, min_loaded_planes
            raise CaseFailure(f"influence 3D crowned: refused on {planes} planes (7 resolve)")
        check_close("influence 3D crowned refusal: the layers named", needed,
                    math.ceil(layers * 7 / planes), 0.)
        torque = round(float(sets[torque_key]) * (resolved_planes / planes) ** 2, 3)
        log(f"influence 3D crowned: refused at {layers} layers ({planes} node planes, "
            f"names Mesh/layers and {needed} layers); checked at {torque} N·m")
        sets = dict(sets, **{torque_key: torque})
        fast, refused = influence_3d_crowned_model(runner, sets, layers, torque)
        if refused:
            layers = math.ceil(layers * resolved_planes / refused[0])
            fast, refused = influence_3d_crowned_model(runner, sets, layers, torque)
            if refused:
                raise CaseFailure(f"influence 3D crowned at {torque} N·m: still refused on "
                                  f"{layers} layers (chosen to load {resolved_planes} planes)")
    middle = time.monotonic()
    # The exact path a mesh per position: at 16 layers its `once` sweep of two positions took
    # 199 s against 76 s (case 9, 2 ranks, one run each; the once path's unit responses grow
    # with the contact nodes, four times the 4-layer check's).
    exact, _, _ = runner.run("stiffness", dict(sets, **{"Stiffness/sweep mesh": "per position",
                                                        "Mesh/layers": layers}))
    check_close("influence 3D crowned: the position's roll angle [deg]",
                table(exact, "stiffness_sweep")[0]["roll_angle"], theta, 1e-9)
    label = (f"influence 3D {lead} ({value} um on {' and '.join(gears).lower()}, {layers} "
             f"layers, {sets[torque_key]} N·m, roll {theta:.4f} deg; model "
             f"{middle - start:.0f} s, exact {time.monotonic() - middle:.0f} s on 1 rank)")
    fast_equals_exact(label, table(exact, "stiffness_sweep"), table(fast, "stiffness_sweep"), log)
    face_load_factors_equal(label, exact, fast, log)


def helical_statics(case, runner, log):
    """The case as a helical pair (docs/helical.md): hands as ISO 21771 pairs them (external
    opposite, internal the same), beta 8-25 deg drawn from its own stream (the case's own draws
    stay as they were), 3D Q1 with the fewest layers the twist allows, frictionless. Without
    friction every contact force is normal to the involute helicoid: |F_a|/F_bt = tan beta_b
    (0.5 %) and the torques balance (1.2e-4: the faceted flank normals)."""
    rng = random.Random(f"{case['seed']}:{case['index']}:helix")
    beta = round(rng.uniform(8., 25.), 1)
    internal = case["pair"]["Gear pair/Wheel/internal"] == "true"
    # Wide faces (docs/helical.md "Teeth modelled"): the case's own widths (6-12 modules) give
    # eps_beta below 1.7, so one helical case in three widens its face to eps_beta 1.9-2.3, where
    # the pairs +-2 touch near the face ends and `teeth modelled = auto` (the default) models a
    # fourth tooth on each gear; the torque keeps its load per unit face width. Drawn after beta
    # from the helix stream, so beta and the other cases' draws stay as they were.
    wide = round(rng.uniform(1.9, 2.3), 2) if rng.random() < 1. / 3. else None
    helicoid = random.Random(f"{case['seed']}:{case['index']}:helicoid").random() < 0.25
    pair_sets = dict(case["pair"])
    module = float(pair_sets["Gear pair/Pinion/module"])
    if wide:
        width = round(wide * math.pi * module / math.sin(math.radians(beta)), 2)
        scale = width / float(pair_sets["Gear pair/Pinion/face width"])
        for gear in ("Pinion", "Wheel"):
            pair_sets[f"Gear pair/{gear}/face width"] = width
        pair_sets["Gear pair scene/pinion torque"] = round(
            float(pair_sets["Gear pair scene/pinion torque"]) * scale, 3)
        # The identities hold on any mesh; at the automatic contact size (a tenth of the Hertz
        # half-width) a face this wide is over the 2e5 hexahedra limit whatever the bodies
        # (docs/helical.md "Default mesh": 7e5 on the study pair at eps_beta 2), so the contact
        # size is the face-width study's 0.15 mm at m_n 2 mm, scaled with the module; the body
        # size stays automatic (coarsened by the scene if the limit needs it). Case 4 of seed
        # 20261201 (24/32 teeth, m_n 2.5 mm, beta 8.1 deg, b 122.07 mm, eps_beta 2.19): 4/4 teeth,
        # 18 layers refused for the contact lines and 27 taken, |F_a|/F_bt 0.133591 against
        # tan beta_b 0.133580; the helical identity 291 s of the case's 349 s on the loaded
        # machine (2026-12-02; case 24's helical statics on its own face: 55 s).
        log(f"helical: face widened to {width} mm (eps_beta {wide}), contact size "
            f"{round(0.075 * module, 4)} mm")
    if wide or helicoid:
        # The same coarse contact size where the helicoid check runs (helicoid_flanks: chords
        # against helicoids on one mesh, a bracket that holds on any mesh). At the automatic
        # contact size its two solves were the costliest part of the suite: case 14 of seed
        # 20261201 (m_n 6 mm, b 47.4 mm, beta 21 deg, 15 layers, contact size 0.072 mm) took
        # 590 s for the statics and 561 s for the helicoids of the case's 1175 s in the fresh
        # clone of a9474c3 (2026-12-06). The cases that go on to the layer extrapolation keep
        # the automatic size: the fast model is checked there against the exact path's k to 1 %.
        pair_sets["Mesh/contact size"] = round(0.075 * module, 4)
        pair_sets["Mesh/fine radius"] = round(0.2 * module, 4)
    sets = dict(pair_sets, **{"Gear pair/Pinion/helix angle": beta,
                                 "Gear pair/Wheel/helix angle": beta if internal else -beta,
                                 "Mesh/dimension": 3, "Finite elements/Element degree": 1,
                                 "Contact/Friction coefficient": 0,
                                 "Stiffness/published reference": "false"})
    # gear-pair takes the pair's own settings only (--set of another command's section is bad
    # input there; only parameter files carry other sections, with a note).
    pair_sets = {k: v for k, v in sets.items() if k.startswith("Gear pair/")}
    pair, _, _ = runner.run("gear-pair", pair_sets)
    sets["Mesh/layers"] = max(2, math.ceil(8 * value(pair, "overlap_ratio") - 1e-9))
    # Geometry first: it needs no solve, and the statics below may be skipped at the cell limit.
    helical_unloaded_te(case, runner, log, sets, pair)
    # A 3D helical scene has layers × the 2D cells: one over the 2e5 hexahedra limit is refused
    # (exit 2 naming Mesh/body size, as it must be) and skipped here, printed. The fewest layers
    # the twist allows may still be too few for the contact lines, which cross the layers at
    # beta_b: the mortar gap of a node on a line comes out negative by an error that falls as the
    # layer height squared (case 24 of seed 20261201, 22/31 teeth, m 1.5, b 16.4 mm, 4 layers:
    # 1.71 um beyond the 1 um overlap tolerance, measured 2026-12-02). The scene then refuses
    # them naming Mesh/layers and the count that cures it, which this case takes (once).
    # The refused run stops in the set-up, before any factorization: on case 24 it costs 8.1 s
    # (3.9 s of meshing 4 layers, then reading and the mortar pairing; single run, 2026-12-02) of
    # the identity's 55 s; the 8-layer solve is the rest. Starting from a predicted count would
    # save those 8 s only, and the overlap it must predict comes from the mortar gap itself.
    report, code, stderr = runner.run("stiffness", sets, allowed=(0, 2))
    needed = "Mesh/layers: too few for the contact lines"
    if code == 2 and needed in stderr:
        given = sets["Mesh/layers"]
        sets["Mesh/layers"] = int(stderr.split("use at least ")[1].split()[0])
        log(f"helical beta {beta} deg: {given} layers refused naming Mesh/layers, "
            f"{sets['Mesh/layers']} taken")
        report, code, stderr = runner.run("stiffness", sets, allowed=(0, 2))
    if code == 2:
        if "the mesh would have about" not in stderr:
            raise CaseFailure(f"stiffness exited 2: {stderr.strip()[-600:]}")
        log(f"helical beta {beta} deg: skipped, the 3D scene is over the cell limit even with "
            f"the automatic body size coarsened (docs/helical.md \"Default mesh\")")
        return
    teeth = report["text"]["model"].split(" teeth modelled")[0].split(", ")[-1]
    if wide and teeth == "3/3":
        log(f"helical: eps_beta {wide} modelled with {teeth} teeth (no position has four pairs)")
    ratio, tan_b = value(report, "axial_over_tangential"), value(report, "tan_base_helix")
    check_close("|F_a|/F_bt against tan beta_b", ratio, tan_b, 0., 5e-3)
    # Not solver precision: the faceted helicoid's normals (tests/helical/CMakeLists.txt: 3.8e-5
    # measured on the built-in pair at beta 15 deg, 7 layers; 2.1e-4 on case 4 of seed 20261201,
    # measured 2026-12-01, with the fewest layers the twist allows): 3x the largest seen.
    check_close("torque balance", value(report, "torque_balance_deviation"), 0., 6.3e-4)
    # The line load w(z) is the transverse load per unit face width (stiffness/face_load.h): the
    # plane's nodal forces over its width, so on Q1 the trapezoidal ∫ w dz is F_bt up to the
    # faceted normals (|n_xy| against the projection on the line of action), as the torque balance
    # above: 6.3e-4. Measured 2026-12-04 on case 4 of seed 20261201: 2.2e-5 (it was -1.0 % while w
    # integrated the nodal pressures across the profile again, and failed the CI).
    rows = table(report, "face_load")
    line = sum(0.5 * (p["line_load"] + q["line_load"]) * (q["z"] - p["z"])
               for p, q in zip(rows, rows[1:]))
    check_close("integral of the line load against F_bt", line, value(report, "tangential_force"),
                0., 6.3e-4)
    # Where the largest pressure acts (peak_on_path): on the path, inside the face.
    roll, face = value(report, "max_pressure_roll"), value(report, "max_pressure_face")
    a, e, h_c = (value(pair, "contact_start"), value(pair, "contact_end"),
                 value(report, "contact_size"))
    width = min(float(sets[f"Gear pair/{g}/face width"]) for g in ("Pinion", "Wheel"))
    check_peak_located("helical", roll, face, a, e, h_c, 0.5 * width)
    check_peak_located("helical (wheel)", value(report, "max_pressure_wheel_roll"), 0., a, e, h_c,
                       0.)
    log(f"helical beta {beta} deg, {sets['Mesh/layers']} layers, {teeth} teeth modelled: "
        f"|F_a|/F_bt {ratio:.6f}, tan beta_b {tan_b:.6f}; peak pressure at roll {roll:.3f} mm "
        f"(A {a:.3f}, E {e:.3f}), {face:.3f} mm across the face")
    if helicoid:
        helicoid_flanks(case, runner, log, sets, report)
    elif not wide:
        layer_extrapolation(runner, log, sets, report)


def layer_extrapolation(runner, log, sets, chords):
    """The helical cases that are neither widened nor drawn for the helicoid check (the cheaper
    ones: their L and 2L solves cost about 4.5 times L), again with `Mesh/layer extrapolation =
    richardson` (stiffness/layer_extrapolation.h): its L level is the chords run above, to 1e-6
    (the same scene: the levels differ in their layers alone, the L scene meshed with the 2L
    scene's body size, which an automatic size keeps unless 2L layers pass the memory limit);
    the extrapolated k is Richardson's in the pinion rotation from the two levels it reports;
    the statics identities hold for the extrapolated forces as for each level. A correction over
    5 % fails with exit 3 naming the layer extrapolation (never a number), which is logged. Fewer
    layers than the option takes are refused naming Mesh/layers and the count, which is taken.
    Then the influence-coefficient model on the same position against that limit."""
    extrapolated = dict(sets, **{"Mesh/layer extrapolation": "richardson"})
    report, code, stderr = runner.run("stiffness", extrapolated, allowed=(0, 2, 3))
    if code == 2:
        # The option needs 16 layers per unit of eps_beta, the chords run takes the twist's 8
        # (cases 84 and 94 of seed 20261201: 7 layers, 13 and 14 named): refused naming
        # Mesh/layers and the count, which is taken; that run's L level is then its own.
        refusal = re.search(r"error: Mesh/layers: (\d+) layers are too few for Mesh/layer "
                            r"extrapolation: at least (\d+)", stderr)
        if refusal is None or int(refusal.group(1)) != int(sets["Mesh/layers"]):
            raise CaseFailure(f"layer extrapolation exited 2: {stderr.strip()[-600:]}")
        log(f"layer extrapolation: {refusal.group(1)} layers refused, names Mesh/layers and at "
            f"least {refusal.group(2)}, taken")
        sets = dict(sets, **{"Mesh/layers": int(refusal.group(2))})
        extrapolated = dict(sets, **{"Mesh/layer extrapolation": "richardson"})
        chords = None
        report, code, stderr = runner.run("stiffness", extrapolated, allowed=(0, 3))
    if code == 3:
        if "layer extrapolation" not in stderr:
            raise CaseFailure(f"layer extrapolation exited 3: {stderr.strip()[-600:]}")
        log(f"layer extrapolation: refused, {stderr.strip()[-300:]}")
        return
    k1, k2 = value(report, "stiffness_coarse_layers"), value(report, "stiffness_fine_layers")
    k = value(report, "mesh_stiffness")
    if chords is not None:
        check_close("layer extrapolation: its L level against the plain L run", k1,
                    value(chords, "mesh_stiffness"), 0., 1e-6)
    check_close("layer extrapolation: Richardson in the rotation", 1. / k,
                1. / k2 + (1. / k2 - 1. / k1) / 3., 0., 1e-9)
    check_close("extrapolated |F_a|/F_bt against tan beta_b", value(report, "axial_over_tangential"),
                value(report, "tan_base_helix"), 0., 5e-3)
    check_close("extrapolated torque balance", value(report, "torque_balance_deviation"), 0.,
                6.3e-4)
    log(f"layer extrapolation: k {k1:.4f} ({sets['Mesh/layers']} layers), {k2:.4f} (x2) -> "
        f"{k:.4f} N/um ({value(report, 'layer_correction'):+.3f} % on the finer level), TE "
        f"{value(report, 'transmission_error'):.5f} um")
    influence_helical_equals_limit(runner, log, sets, report)


def influence_helical_equals_limit(runner, log, sets, limit):
    """The influence-coefficient model on the case's own helical pair (docs/ltca.md section 3
    "Helical pairs accepted"), on the case's layers at the exact position (a one-position sweep
    centred on its roll angle), against the exact path's layer limit from layer_extrapolation:
    k and TE, and K_Hbeta left out of its report with the reason."""
    theta = value(limit, "pinion_roll_angle")
    fast_sets = dict(one_position_sweep(sets, theta),
                     **{"Stiffness/contact model": "influence coefficients",
                        "Stiffness/mode": "sweep"})
    # Node planes at most 0.74 m_n apart (stiffness/influence_checks.cc,
    # max_helical_spacing_modules): more are refused before any mesh, naming Mesh/layers and the
    # count, checked here and taken.
    width = min(float(sets[f"Gear pair/{g}/face width"]) for g in ("Pinion", "Wheel"))
    module = float(sets["Gear pair/Pinion/module"])
    needed = math.ceil(width / (0.74 * module) - 1e-9)
    fast, code, stderr = runner.run("stiffness", fast_sets, allowed=(0, 2))
    if code == 2:
        refusal = re.search(r"error: Mesh/layers: influence coefficients on a helical pair .* "
                            r"use at least (\d+) layers", stderr)
        if (refusal is None or int(refusal.group(1)) != needed
                or int(sets["Mesh/layers"]) >= needed):
            raise CaseFailure(f"influence helical at {sets['Mesh/layers']} layers: expected exit 2 "
                              f"naming Mesh/layers and at least {needed} layers, got: "
                              f"{stderr.strip()[-300:]}")
        log(f"influence helical: {sets['Mesh/layers']} layers refused, names Mesh/layers and "
            f"at least {needed}")
        # `Mesh/layers = auto` takes the count the model is verified on where the exact path's
        # automatic one (16 per unit of eps_beta, at least 8) is fewer, and says so in the input
        # notes (stiffness::influence_least_layers; since 2026-12-06 it refused them as above).
        pair, _, _ = runner.run("gear-pair", {key: v for key, v in sets.items()
                                              if key.startswith("Gear pair/")})
        automatic = max(8, math.ceil(16 * value(pair, "overlap_ratio") - 1e-9))
        fast, _, _ = runner.run("stiffness", dict(fast_sets, **{"Mesh/layers": "auto"}))
        taken = re.match(r"(\d+) layers", fast["text"].get("layer error", ""))
        note = fast["text"].get("input notes", "")
        if (taken is None or int(taken.group(1)) != max(automatic, needed)
                or (f"Mesh/layers = auto takes {needed} layers ({automatic} for the exact path)"
                    in note) != (automatic < needed)):
            raise CaseFailure(f"influence helical at Mesh/layers = auto: expected "
                              f"{max(automatic, needed)} layers (the exact path's {automatic}, "
                              f"the model's {needed}) and the note where it raised them, got "
                              f"'{fast['text'].get('layer error', '')[:40]}', notes '{note}'")
        log(f"influence helical: Mesh/layers = auto takes {int(taken.group(1))} layers (the "
            f"exact path's {automatic})")
    row = table(fast, "stiffness_sweep")[0]
    check_close("influence helical: the position's roll angle [deg]", row["roll_angle"], theta,
                1e-9)
    k, k_limit = row["stiffness"], value(limit, "mesh_stiffness")
    check_close("influence helical: k against the exact layer limit", k, k_limit, 0.,
                helical_fast_tolerance)
    check_close("influence helical: TE against the exact layer limit [um]",
                row["transmission_error"], value(limit, "transmission_error"), 0.1)
    if "face_load_factor" in fast["tables"] or not fast["text"].get("face load", "").startswith(
            "not reported: on a helical pair"):
        raise CaseFailure("influence helical: K_Hbeta reported, or left out without the reason")
    log(f"influence helical: k {k:.4f} against the exact limit {k_limit:.4f} N/um "
        f"({k / k_limit - 1.:+.3%}), TE {row['transmission_error']:.5f} against "
        f"{value(limit, 'transmission_error'):.5f} um; K_Hbeta left out")


# Relative, the influence-coefficient model's k on an own helical pair against the exact path's
# two-level layer limit: the issue's 1 %, measured against limits from three or more levels.
helical_fast_tolerance = 1e-2


def helicoid_flanks(case, runner, log, sets, chords):
    """On one helical case in four (its own stream, drawn in helical_statics): the same scene
    with `Mesh/helical flanks = helicoid`, the gaps measured between the involute helicoids
    instead of the hexahedra's chords (docs/helical.md "Layers and the helicoids"). The chords
    lie inside both bodies, so the helicoids start closer: k is at least the chords' and the TE
    at most theirs (the two bracket the layers' limit), and the statics identities hold as
    before."""
    # On the helicoids the dual mortar's negative gap where a line crosses a face ("Layers and
    # the contact lines") is no longer offset by the chords' sag, so the overlap refusal can come
    # at the count the chords took (case 14 of seed 20261201: 1.07 um there, 22 layers named,
    # two more solves of ~5 min each at 8 GB). The comparison is about the flanks on one mesh,
    # not the refusal, so the tolerance admits that artifact (5 um) instead.
    helicoid = dict(sets, **{"Mesh/helical flanks": "helicoid", "Contact/Overlap tolerance": 5e-3})
    report, code, stderr = runner.run("stiffness", helicoid, allowed=(0, 2))
    if code == 2:
        raise CaseFailure(f"stiffness with helicoid flanks exited 2: {stderr.strip()[-600:]}")
    k_c, k_h = value(chords, "mesh_stiffness"), value(report, "mesh_stiffness")
    te_c, te_h = value(chords, "transmission_error"), value(report, "transmission_error")
    if not (k_h >= k_c * (1. - 1e-9) and te_h <= te_c * (1. + 1e-9)):
        raise CaseFailure(f"helicoid flanks: k {k_h!r} against chords {k_c!r} N/um, TE {te_h!r} "
                          f"against {te_c!r} um: the helicoids must start closer than the chords")
    check_close("helicoid |F_a|/F_bt against tan beta_b", value(report, "axial_over_tangential"),
                value(report, "tan_base_helix"), 0., 5e-3)
    check_close("helicoid torque balance", value(report, "torque_balance_deviation"), 0., 6.3e-4)
    log(f"helicoid flanks: k {k_h:.4f} against chords {k_c:.4f} N/um ({k_h / k_c - 1.:+.3%}), "
        f"TE {te_h:.5f} against {te_c:.5f} um")


def helical_tent(x, half_window, amount, e, geometry):
    """The unloaded TE of equal long tip reliefs on a helical pair at mesh position x: each
    transverse section z is a spur section at x + tan(beta_b)*(z - b/2)/p_bt, so the smallest
    separation along the contact lines is the spur tent's (relieved_tent: each pair where its
    relieved flanks touch, in the transverse section) smallest value over the window
    x +- eps_beta/2, sampled at 2001 sections as the geometry does. The tent is 0 on its
    single-contact zone [e, 1] (mod 1)."""
    lo, hi = x - half_window, x + half_window
    for k in range(math.floor(lo) - 1, math.floor(hi) + 1):
        if k + e <= hi and k + 1. >= lo:
            return 0.
    return min(relieved_tent(geometry, geometry["A"] + (y % 1.) * geometry["base_pitch"],
                             y % 1., e, amount)
               for y in (lo + (hi - lo) * i / 2000. for i in range(2001)))


def line_geometry(report, internal):
    """The pair's line of action (mm) from a `gear-pair` report, for relieved_tent."""
    return {"r_b1": value(report, "pinion_base_radius"),
            "r_b2": value(report, "wheel_base_radius"),
            "t1t2": value(report, "centre_distance") *
            math.sin(math.radians(value(report, "working_pressure_angle"))),
            "base_pitch": value(report, "transverse_base_pitch"),
            "A": value(report, "contact_start"), "internal": internal}


HELICAL_TE_POSITIONS = (0.25, 0.5, 0.75)  # mesh positions x, fractions of e from A


def helical_unloaded_te(case, runner, log, sets, pair):
    """The helical unloaded TE (geometry; `gearstiff mesh` prints it) against closed forms, with
    reliefs of its own (drawn from a stream of their own, 4-15 um; the case's own modification
    may be one no closed form covers): equal long tip reliefs on both gears at three positions
    give the spur tent's smallest value over the face's window (helical_tent; the depth taken
    along the transverse line of action, depth/cos beta_b), and a relief on
    one gear only gives 0 (the unmodified flank carries somewhere along every line): 1 nm.
    The face is narrowed to eps_beta 0.2-0.8 (e = eps_alpha - 1), so that the window
    x +- eps_beta/2 stays inside the double-contact zone at some positions (a wider face reaches
    the single-contact zone, where the tent is 0, from every position). Coarse 3D meshes: the
    value is the designed geometry, not the mesh's (tests/helical/test_helical_unloaded_error.cc
    checks it against the meshed flanks' gap)."""
    rng = random.Random(f"{case['seed']}:{case['index']}:helical te")
    amount = round(rng.uniform(4., 15.), 1)  # um
    one_gear = rng.choice(("Pinion", "Wheel"))
    e = value(pair, "transverse_contact_ratio") - 1.  # of the helical pair (alpha_t)
    overlap = round(rng.uniform(0.2, 0.8) * e, 3)
    module = float(sets["Gear pair/Pinion/module"])
    beta = abs(float(sets["Gear pair/Pinion/helix angle"]))
    width = round(overlap * math.pi * module / math.sin(math.radians(beta)), 4)
    mesh_sets = {k: v for k, v in sets.items() if k.startswith("Gear pair/")}
    mesh_sets.update({"Gear pair/Pinion/face width": width, "Gear pair/Wheel/face width": width,
                      "Mesh/dimension": 3, "Mesh/layers": max(2, math.ceil(8 * overlap)),
                      "Mesh/contact size": round(0.3 * module, 4),
                      "Mesh/fine radius": round(0.6 * module, 4),
                      "Mesh/body size": round(1.5 * module, 4),
                      "Gear pair scene/position": "roll angle"})
    start, pitch = value(pair, "contact_start"), value(pair, "transverse_base_pitch")
    radius = value(pair, "pinion_base_radius")
    half = 0.5 * width * math.sin(math.radians(beta)) / (math.pi * module)
    # A relief is a normal depth (docs/helical.md); along the transverse line of action, where
    # the TE is measured, it separates the flanks by depth/cos(beta_b): cos(alpha_t) from
    # p_bt = pi*m_n/cos(beta)*cos(alpha_t), tan(beta_b) = tan(beta)*cos(alpha_t).
    cos_alpha_t = pitch * math.cos(math.radians(beta)) / (math.pi * module)
    transverse = amount * math.sqrt(1. + (math.tan(math.radians(beta)) * cos_alpha_t) ** 2)
    both = {"Gear pair/Pinion/tip relief": amount, "Gear pair/Wheel/tip relief": amount}
    geometry = line_geometry(pair, str(sets.get("Gear pair/Wheel/internal", "false")) == "true")
    checks = [(f * e, both, helical_tent(f * e, half, transverse, e, geometry))
              for f in HELICAL_TE_POSITIONS]
    checks.append((0.5 * e, {f"Gear pair/{one_gear}/tip relief": amount}, 0.))
    worst = 0.
    for x, reliefs, expected in checks:
        roll = math.degrees((start + x * pitch) / radius)
        report, _, _ = runner.run("mesh", dict(mesh_sets, **reliefs, **{
            "Gear pair scene/pinion roll angle": round(roll, 9)}))
        got = value(report, "unloaded_transmission_error") * 1e3  # mm -> um
        check_close(f"helical unloaded TE, x = {x:.4f}, {reliefs} [um]", got, expected, 1e-3)
        worst = max(worst, abs(got - expected))
    log(f"helical unloaded TE (face {width} mm, eps_beta {2 * half:.3f}): tent of {amount} um "
        f"reliefs at x = {', '.join(f'{c[0]:.4f}' for c in checks[:3])} "
        f"({', '.join(f'{c[2]:.4f}' for c in checks[:3])} um), {one_gear} relief only 0; "
        f"|d| {worst:.2g} um")


def errors_name_parameters(case, runner, log):
    """Library errors name library fields ("wheel.teeth", "pair.centre_distance"); the command
    maps each to the parameter the user typed (app/core/field_names.h). On this pair: a wheel of
    two teeth (`gear-pair`) and a centre distance far below the pair's (`mesh`, which reads the
    same pair) each give one line naming the typed parameter, exit 2, no field name."""
    for command, key, bad, expected in (
            ("gear-pair", "Gear pair/Wheel/teeth", "2",
             "Gear pair/Wheel/teeth: must be at least 3"),
            ("mesh", "Gear pair/centre distance", "1", "Gear pair/centre distance: ")):
        pair = {k: v for k, v in case["pair"].items() if k.startswith("Gear pair/")}
        _, code, stderr = runner.run(command, dict(pair, **{key: bad}), allowed=(2,))
        lines = [line for line in stderr.splitlines() if line.strip()]
        if len(lines) != 1 or f"gearstiff: error: {expected}" not in lines[0]:
            raise CaseFailure(f"{command} with {key}={bad}: expected one line naming {key}, "
                              f"got {stderr.strip()[-300:]!r}")
    log("errors name the parameters typed: Gear pair/Wheel/teeth (gear-pair), "
        "Gear pair/centre distance (mesh)")


# Which identities a case checks: every case the rolling sweep and the geometry of its
# modification; the costlier ones in turn.
ROTATION = [zero_equals_none, ranks_agree, python_equals_cli, own_train]


def run_case(seed, index, runner):
    start = time.monotonic()
    runner.seconds.clear()
    passed = check_case(seed, index, runner)
    spent = ", ".join(f"{name} {seconds:.1f}" for name, seconds in runner.seconds.most_common())
    print(f"  case {index}: {time.monotonic() - start:.1f} s ({spent})", flush=True)
    return passed


def check_case(seed, index, runner):
    rng = random.Random(f"{seed}:{index}")
    lines = []
    log = lines.append
    case = draw_case(rng, runner, random.Random(f"{seed}:{index}:rounding"),
                     random.Random(f"{seed}:{index}:rack"))
    settings = dict(case["pair"], **case["modifications"])
    print(f"case {index} (seed {seed}): {case['modification']}, eps_alpha "
          f"{case['contact_ratio']:.4f}; " + "; ".join(f"{k}={v}" for k, v in settings.items()),
          flush=True)
    try:
        identity = ROTATION[index % len(ROTATION)]
        once_out = os.path.join(runner.work, f"case{index}") if identity is own_train else None
        errors_name_parameters(case, runner, log)
        sweeps = once_equals_per_position(case, runner, log, once_out)
        names_its_build(runner, log, sweeps)
        influence_equals_exact(case, runner, log, sweeps)
        geometric_te(case, table(sweeps["per position"], "stiffness_sweep"), log)
        peak_on_path("peak pressure (per position)", sweeps["per position"], log)
        peak_on_path("peak pressure (once)", sweeps["once"], log)
        identity(case, runner, log, sweeps)
        if index % 10 == 9:  # 3D is the costly one: every tenth case
            three_d_between_plane_models(dict(case, seed=seed, index=index), runner, log)
        if index % 10 == 4:  # the helical variant of the case, also 3D
            helical_statics(dict(case, seed=seed, index=index), runner, log)
    except CaseFailure as failure:
        for line in lines:
            print("  " + line)
        print(f"  FAILED: {failure}")
        print(f"  reproduce: {sys.argv[0]} {runner.gearstiff} --seed {seed} --cases 1 "
              f"--first {index}")
        return False
    for line in lines:
        print("  " + line)
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("gearstiff")
    parser.add_argument("--seed", type=int, default=20261201)
    parser.add_argument("--cases", type=int,
                        default=int(os.environ.get("GEARSTIFF_INVARIANT_CASES", "6")))
    parser.add_argument("--first", type=int, default=0)
    parser.add_argument("--mpiexec", default=os.environ.get("GEARSTIFF_MPIEXEC", "mpiexec"))
    parser.add_argument("--python-path", default=os.environ.get("GEARSTIFF_PYTHON_PATH", ""))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="gearstiff-invariants-") as work:
        runner = Runner(args.gearstiff, args.mpiexec, args.python_path, work)
        results = [run_case(args.seed, i, runner)
                   for i in range(args.first, args.first + args.cases)]
    failed = results.count(False)
    print(f"invariants: {len(results)} cases from seed {args.seed} (first {args.first}), "
          f"{runner.runs} runs: {len(results) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
