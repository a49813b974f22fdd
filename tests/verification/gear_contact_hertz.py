#!/usr/bin/env python3
"""Claim (docs/accuracy.md, "Contact pressure"): at the gear contact the FE pressure is Hertz's
line contact with the local radii of the involutes (docs/references.md §6): Q1's nodal peak lies a
few per cent above the Hertz estimate (689 MPa at h_c = 0.03 mm against ≈ 0.66 GPa); with the
local radii Hertz's peak is 683.5 MPa, which the Q1 nodal peak at h_c = 0.021 mm matches, and
the closed zone spans Hertz's 2a to within the node spacing.

The split-path pair (docs/references.md §1) at the single-pair position (pitch point), Q1,
frictionless (Hertz's theory), plane strain, the default scene with h_c = 0.021 mm (the finer
of the two Q1 levels docs/accuracy.md quotes). Hertz (Johnson 1985 eq. 4.43, 4.45) at the pair's
own FE normal force per face width, with the local radii of curvature of the two involutes at
the pinion's contact roll angle ξ: ρ1 = r_b1·ξ, ρ2 = a_w·sin α_wt − ρ1, E* = E/(2(1 − ν²)).

usage: gear_contact_hertz.py GEARSTIFF WORKDIR
"""
import os
import math
import sys

from verify import Checks, run_json, value, work_folder

gearstiff, work = os.path.realpath(sys.argv[1]), work_folder(sys.argv[2])
contact_size = 0.021  # mm
settings = ["Finite elements/Element degree=1", "Contact/Friction coefficient=0",
            f"Mesh/contact size={contact_size}"]
summary = run_json(gearstiff, "stiffness", settings, cwd=work)
pair = run_json(gearstiff, "gear-pair", cwd=work)
r_b1 = value(pair, "pinion_base_radius") * 1e-3
a_w = value(pair, "centre_distance") * 1e-3
alpha_wt = math.radians(value(pair, "working_pressure_angle"))
xi = math.radians(value(summary, "pinion_roll_angle"))
width = 24e-3  # m, the common face width, the plane-strain thickness (docs/references.md §1)
e, nu = 210e9, 0.3  # Pa, -: the stiffness command's defaults
rho1 = r_b1 * xi
rho2 = a_w * math.sin(alpha_wt) - rho1
r_star = rho1 * rho2 / (rho1 + rho2)
e_star = e / (2. * (1. - nu * nu))
force = value(summary, "contact_normal_force")
line_load = force / width
a = math.sqrt(4. * line_load * r_star / (math.pi * e_star))
p0 = 2. * line_load / (math.pi * a)
p_max = value(summary, "max_contact_pressure") * 1e6
span = value(summary, "contact_width") * 1e-3
print(f"roll angle {math.degrees(xi):.4f} deg, rho1 {rho1 * 1e3:.4f} mm, rho2 {rho2 * 1e3:.4f} mm, "
      f"F {force:.2f} N (T1/r_b1 = {49.4 / r_b1:.2f} N); Hertz a {a * 1e3:.5f} mm, "
      f"p0 {p0 / 1e6:.1f} MPa; FE nodal p_max {p_max / 1e6:.1f} MPa, closed span "
      f"{span * 1e3:.5f} mm, h_c {value(summary, 'contact_size'):.4f} mm")

checks = Checks("gear_contact_hertz")
# One pair carries T1: its normal force is T1/r_b1 (frictionless: the forces act along the flank
# normals, whose moment arm about the pinion is r_b1 exactly; docs/internal-gears.md).
# Measured 2026-11-26: −3e-7; tolerance 1e-5, the contact solver's convergence tolerance.
checks.near("FE normal force / (T1/r_b1)", force, 49.4 / r_b1, 1e-5)
# Measured 2026-11-26: −0.028 % (683.3 against 683.5 MPa; the "≈ 0.66 GPa" docs/references.md §6
# quotes is a rounded estimate with R ≈ 6.6 mm, the local radii give R* = 6.56 mm and 683.5 MPa);
# tolerance 0.1 %, about three times the measured deviation.
checks.near("FE nodal peak pressure / Hertz p0", p_max, p0, 0.001)
# The closed zone ends between a closed and an open node at each edge: its span lies within
# one contact cell of 2a at each end, 2a − 2h_c ≤ span ≤ 2a (+ round-off). Measured 2026-11-26:
# −5.7 µm = −0.27 h_c (0.14971 against 0.15545 mm).
h = value(summary, "contact_size") * 1e-3
checks.near("FE closed span / Hertz 2a (bound: two contact cells)", span, 2. * a, 2. * h, False)
checks.done()
