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
The internal pair of the stiffness tests (planet 24 in ring 69, m 2.5 mm, ring tip d_a 170 mm, rim
3 modules: tests/stiffness/planet_ring.h), 16 positions, at its single-contact position 8:
457.8, 442.0, 434.3 MPa at h_c 0.015, 0.0075, 0.00375 mm against the fast 424.7 (limit 426.3 from
the first two, 426.5 from the last two). Its double-contact positions are not a claim here: the
exact peak there is not monotone in h_c (position 3: 443.3, 384.1, 385.6 MPa; the fast 373.7,
−3.1 % from the finest) and a first-order limit of the first two levels is meaningless.
Pressure at a relief's start (a kink of the flank) is outside this claim: the exact peak there
grows with refinement (docs/ltca.md §5), there is no converged value to compare with.

usage: influence_peak_pressure.py GEARSTIFF WORKDIR
"""
import os
import sys

from verify import Checks, column, run_json, value, work_folder

gearstiff, work = os.path.realpath(sys.argv[1]), work_folder(sys.argv[2])
common = ["Finite elements/Element degree=2", "Contact/Friction coefficient=0"]
# tests/stiffness/planet_ring.h as parameters: the ring's bore d_f2 + 2·3·m_n = 193.75 mm.
internal = ["Gear pair/Pinion/teeth=24", "Gear pair/Pinion/profile shift=0",
            "Gear pair/Pinion/tip diameter=0", "Gear pair/Wheel/teeth=69",
            "Gear pair/Wheel/internal=true", "Gear pair/Wheel/profile shift=0",
            "Gear pair/Wheel/tip diameter=170", "Gear pair/Wheel/bore diameter=193.75"]


def fast_sweep(pair, positions):
    summary = run_json(gearstiff, "stiffness", common + pair + [
        "Stiffness/mode=sweep", f"Stiffness/sweep positions={positions}",
        "Stiffness/contact model=influence coefficients"], cwd=work)
    return [column(summary, "stiffness_sweep", name)
            for name in ("roll_angle", "max_pressure", "loaded_pairs")]


def exact_peak(pair, angle, contact_size):
    summary = run_json(gearstiff, "stiffness", common + pair + [
        "Stiffness/mode=roll angle", f"Stiffness/pinion roll angle={angle!r}",
        f"Mesh/contact size={contact_size}"], cwd=work)
    return value(summary, "max_contact_pressure")


checks = Checks("influence_peak_pressure")
external = fast_sweep([], 32)
planet_ring = fast_sweep(internal, 16)
# (name, pair settings, the fast sweep, position index, loaded pairs there). Measured 2026-12-02,
# fast against the limit: −0.95 % (external single, 678.4 against 684.9 MPa), −1.16 % (external
# double, 524.4 against 530.6), −0.38 % (internal single, 424.7 against 426.3). The limit's own
# uncertainty is up to 1.7 % (from h_c 0.0075 and 0.00375 mm instead: 672.9, 519.3, 426.5 MPa, the
# fast model +0.8, +1.0, −0.4 %), so 3x the measured deviation (3.5 %) would sit inside the
# reference's spread: the 5 % is the bound.
cases = (("external, single contact", [], external, 19, 1),
         ("external, double contact", [], external, 9, 2),
         ("internal, single contact", internal, planet_ring, 7, 1))
for name, pair, (angles, pressures, pairs), index, loaded in cases:
    checks.holds(f"{name}: position {index + 1} has {pairs[index]} loaded pair(s), {loaded} "
                 f"expected", pairs[index] == loaded)
    coarse, fine = (exact_peak(pair, angles[index], h) for h in (0.015, 0.0075))
    limit = 2. * fine - coarse
    print(f"{name} (roll angle {angles[index]:.4f} deg): exact p_max {coarse:.2f} MPa at h_c "
          f"0.015 mm, {fine:.2f} at 0.0075, limit {limit:.2f}; fast {pressures[index]:.2f} MPa")
    # The exact peak approaches the fast model's as h_c falls (measured 2026-12-02: 723.2 -> 704.0,
    # 565.0 -> 547.8, 457.8 -> 442.0 MPa against 678.4, 524.4, 424.7).
    checks.holds(f"{name}: the exact peak approaches the fast one as h_c falls",
                 abs(fine - pressures[index]) < abs(coarse - pressures[index]))
    checks.near(f"{name}: fast peak pressure against the exact limit [MPa]", pressures[index],
                limit, 0.05)
checks.done()
