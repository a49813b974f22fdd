#!/usr/bin/env python3
"""Claim (issue 47, docs/ltca.md "Peak pressure"): the influence-coefficient model's peak pressure
(the Hertz p0 of each pair's force, from its analytic near field) is within 5 % of the exact FE
path's converged peak, although it lies 6-18 % below the exact path's nodal peak at the default
h_c = 0.03 mm. The exact nodal peak falls towards Hertz's as h_c is refined (measured 2026-12-02,
Q2, single-contact position 20 of the 32: 755.7, 723.2, 704.0, 688.5 MPa at h_c 0.03, 0.015,
0.0075, 0.00375 mm, the fast model 678.4 MPa): it is not converged at the default contact size,
so the comparison is with its limit h_c -> 0, extrapolated from h_c 0.015 and 0.0075 mm.

The built-in pair (T1 = 49.4 N·m, Q2, plane strain, frictionless: the fast model applies no
friction), the fast model's default 32-position sweep, and the exact path at one single-contact
position (20 of 32, ℓ in the single-tooth zone) and one double-contact position (10 of 32) at
those positions' roll angles, each meshed for that position (`Stiffness/mode = roll angle`).
The limit: first-order Richardson, p* = 2·p(h/2) − p(h): the nodal peak's error halves with h_c
over the last three levels (differences 32.5, 19.2, 15.6 MPa at the single position; 34.6, 17.2,
14.3 at the double one), the first-order rate of a nodal value at the edge-of-zone square root.
Pressure at a relief's start (a kink of the flank) is outside this claim: the exact peak there
grows with refinement (docs/ltca.md §5), there is no converged value to compare with.

usage: influence_peak_pressure.py GEARSTIFF WORKDIR
"""
import os
import sys

from verify import Checks, column, run_json, value, work_folder

gearstiff, work = os.path.realpath(sys.argv[1]), work_folder(sys.argv[2])
common = ["Finite elements/Element degree=2", "Contact/Friction coefficient=0"]
fast = run_json(gearstiff, "stiffness", common + [
    "Stiffness/mode=sweep", "Stiffness/contact model=influence coefficients"], cwd=work)
angles = column(fast, "stiffness_sweep", "roll_angle")
pressures = column(fast, "stiffness_sweep", "max_pressure")
pairs = column(fast, "stiffness_sweep", "loaded_pairs")


def exact_peak(angle, contact_size):
    summary = run_json(gearstiff, "stiffness", common + [
        "Stiffness/mode=roll angle", f"Stiffness/pinion roll angle={angle!r}",
        f"Mesh/contact size={contact_size}"], cwd=work)
    return value(summary, "max_contact_pressure")


checks = Checks("influence_peak_pressure")
for name, index, loaded in (("single contact", 19, 1), ("double contact", 9, 2)):
    checks.holds(f"{name}: position {index + 1} has {pairs[index]} loaded pair(s), {loaded} "
                 f"expected", pairs[index] == loaded)
    coarse, fine = exact_peak(angles[index], 0.015), exact_peak(angles[index], 0.0075)
    limit = 2. * fine - coarse
    print(f"{name} (roll angle {angles[index]:.4f} deg): exact p_max {coarse:.2f} MPa at h_c "
          f"0.015 mm, {fine:.2f} at 0.0075, limit {limit:.2f}; fast {pressures[index]:.2f} MPa")
    # The exact peak approaches the fast model's as h_c falls (measured 2026-12-02: single
    # 723.2 -> 704.0, double 565.0 -> 547.8 MPa against 678.4 and 524.4).
    checks.holds(f"{name}: the exact peak approaches the fast one as h_c falls",
                 abs(fine - pressures[index]) < abs(coarse - pressures[index]))
    # The 5 %. Measured 2026-12-02: −0.95 % (single, 678.4 against 684.9 MPa) and −1.16 %
    # (double, 524.4 against 530.6); the limit's own uncertainty is about 1.7 % (from h_c 0.0075
    # and 0.00375 mm instead: 672.9 and 519.3 MPa, the fast model +0.8 % and +1.0 %), so 3x the
    # measured deviation (3.5 %) would sit inside the reference's spread: the bound holds.
    checks.near(f"{name}: fast peak pressure against the exact limit [MPa]", pressures[index],
                limit, 0.05)
checks.done()
