#!/usr/bin/env python3
"""The claims of docs/cycloid.md on the default `gearstiff cycloid-loads` case (the drive of
docs/references.md §4, M_c = 440 N·m, crank angle 0, Q2 default mesh, frictionless; nominal and
corrected ε = 0.27 profiles, the torsional levels ±3 %, ±50 %, ±100 % M_c).

usage: cycloid_claims.py GEARSTIFF WORKDIR corrected SUMMARY   corrected profile: FE against analytic
       cycloid_claims.py GEARSTIFF WORKDIR torsion SUMMARY     torsional stiffness, lost motion, backlash

SUMMARY is the summary.json of the default case, both profiles (the corrected one's values
prefixed `corrected_`), written by the test regression.cycloid_loads, whose fixture these claims
require: the drive is solved once for the suite (issue 43), not again here. Its values equal
those of a run of one profile to round-off (checked 2026-12-01: every value but the ~1e-13 N
force balances identical to the printed 12 digits).
"""
import json
import os
import sys

from verify import Checks, run_json, value

gearstiff, work, claim, summary_path = os.path.realpath(sys.argv[1]), sys.argv[2], sys.argv[3], \
    sys.argv[4]
os.makedirs(work, exist_ok=True)
with open(summary_path) as f:
    summary = json.load(f)


def nominal(key):
    return value(summary, key)


def corrected(key):
    return value(summary, "corrected_" + key)


checks = Checks(f"cycloid_{claim}")
if claim == "corrected":
    # docs/cycloid.md: with the corrected profile only the rollers nearest the largest levers
    # carry load, the disc deformation matters less, and FE and the rigid-disc analytic model
    # (stiffness/cycloid_analytic.h) agree closely. Measured 2026-11-26: P_max −0.66 %
    # (2393.8 against 2409.6 N); tolerance 1 % (1.5× the measured deviation: the FE value moves
    # by +0.5 % from the default mesh to the converged one, docs/cycloid.md refinement study).
    checks.near("corrected P_max FE / analytic", corrected("max_roller_force"),
                corrected("analytic_max_roller_force"), 0.01)
    # Q_max: measured −3.2 % (3902.9 against 4031.8 N: the FE disc is not rigid, so the pins
    # share the torque more evenly); tolerance 10 %, three times that.
    checks.near("corrected Q_max FE / analytic", corrected("max_pin_force"),
                corrected("analytic_max_pin_force"), 0.10)
    # The contrast the claim rests on: on the nominal profile, where the FE disc bends, FE lies
    # 7 % below the rigid-disc P_max (docs/cycloid.md: 1426 against 1533 N). Measured 2026-11-26:
    # 0.9307; tolerance ±0.005, the rounding of the documented 7 %.
    checks.near("nominal P_max FE / analytic", nominal("max_roller_force")
                / nominal("analytic_max_roller_force"), 0.93, 0.005, False)
elif claim == "torsion":
    # The nominal profile has no play: backlash exactly 0 (a rigid rotation to touching).
    checks.near("nominal backlash [arcmin]", nominal("backlash"), 0., 1e-9, False)
    # docs/cycloid.md: the corrected profile's backlash is about 2δ (the correction thins the
    # lobes and its rotation δ turns the profile back onto the working flank, which leaves twice δ
    # on the other), δ the correction's rotation as `gearstiff cycloid` computes it for ε = 0.27
    # (0.196789°; the paper prints 0.197962°, docs/references.md §4). Measured 2026-11-26:
    # 23.6272 against 2δ = 23.6147 arcmin, +0.053 % (the lobe thinning r_k, q_k adds a little);
    # tolerance 0.16 %.
    delta = value(run_json(gearstiff, "cycloid", cwd=work), "delta")  # degrees
    checks.near("corrected backlash / 2 delta", corrected("backlash"), 2. * delta * 60., 0.0016)
    # Lost motion θ(+3 %) − θ(−3 %) is the backlash plus the elastic rotation between ±3 % M_c:
    # larger than the backlash. Measured 2026-11-26: by 0.1020 arcmin.
    checks.holds("corrected lost motion > its backlash",
                 corrected("lost_motion") > corrected("backlash"))
    # The FE adds the disc's, the roller rings' and the pins' compliance to the contact
    # compliance of the rigid-body model (stiffness/cycloid_analytic.h): its output rotation under
    # M_c exceeds the analytic one. Measured 2026-11-26: 0.8489 against 0.6058 arcmin (nominal).
    checks.holds("nominal: FE output rotation > rigid-body analytic",
                 nominal("output_rotation") > nominal("analytic_output_rotation"))
    # The figures docs/cycloid.md quotes have no independent value: regression, measured
    # 2026-11-26 (deterministic; tolerance 0.1 %). The nominal lost motion was re-measured after
    # the session's merges changed the cycloid mesh (cells sized from the case's own load,
    # mesh-size retries): 0.066180 → 0.065885 arcmin (−0.45 %, a 0.07 arcmin figure).
    checks.near("nominal torsional stiffness [N·m/arcmin] (regression)",
                nominal("torsional_stiffness"), 549.297, 0.001)
    checks.near("corrected torsional stiffness [N·m/arcmin] (regression)",
                corrected("torsional_stiffness"), 433.010, 0.001)
    checks.near("nominal lost motion [arcmin] (regression)", nominal("lost_motion"), 0.065885,
                0.001)
    checks.near("corrected lost motion [arcmin] (regression)", corrected("lost_motion"), 23.7292,
                0.001)
else:
    sys.exit(f"cycloid_claims: unknown claim {claim}")
checks.done()
