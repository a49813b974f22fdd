#!/usr/bin/env python3
"""Claim (docs/internal-gears.md, "ISO 6336-1 reference" and StifferThanExternalPairOfTheSamePlanet):
ISO 6336-1:2006 9.3.2 method B evaluates an internal pair's single stiffness with z_n2 = ∞ (the
ring enters like a rack), which makes it stiffer than the external pair of the same planet; the
FE finds the same relation (internal 6.2 % stiffer) and lies near ISO's c'·b.

Planet 24 / ring 69 (docs/references.md §2's inner set; m 2.5 mm, x = 0, ring tip 170 mm, rim 5·m,
the planet as the split-path pinion) and the external 24/69 pair of the same planet (standard
tips, wheel bore 150 mm), single-pair position, frictionless, default scene (Q2).

usage: internal_iso.py GEARSTIFF WORKDIR
"""
import os
import sys

from verify import Checks, run_json, value, work_folder

gearstiff, work = os.path.realpath(sys.argv[1]), work_folder(sys.argv[2])
common = ["Gear pair/Pinion/teeth=24", "Gear pair/Wheel/teeth=69",
          "Gear pair/Pinion/profile shift=0", "Gear pair/Wheel/profile shift=0",
          "Gear pair/Pinion/tip diameter=0", "Gear pair/Pinion/bore diameter=20"]
internal = common + ["Gear pair/Wheel/internal=true", "Gear pair/Wheel/tip diameter=170",
                     "Gear pair/Wheel/bore diameter=0"]
external = common + ["Gear pair/Wheel/tip diameter=0", "Gear pair/Wheel/bore diameter=150"]
fe = ["Contact/Friction coefficient=0"]
k_int = value(run_json(gearstiff, "stiffness",
                       internal + fe + ["Gear pair scene/wheel rim thickness=12.5"], cwd=work),
              "mesh_stiffness")
k_ext = value(run_json(gearstiff, "stiffness", external + fe, cwd=work), "mesh_stiffness")
iso_int = value(run_json(gearstiff, "gear-pair", internal, cwd=work),
                "iso_single_stiffness_times_width")
iso_ext = value(run_json(gearstiff, "gear-pair", external, cwd=work),
                "iso_single_stiffness_times_width")
print(f"FE k internal {k_int:.2f}, external {k_ext:.2f} N/um (ratio {k_int / k_ext:.4f}); "
      f"ISO c'b internal {iso_int:.2f}, external {iso_ext:.2f} N/um (ratio {iso_int / iso_ext:.4f})")

checks = Checks("internal_iso")
checks.holds("ISO 6336-1: internal (z_n2 = inf) stiffer than external", iso_int > iso_ext)
checks.holds("FE: internal stiffer than external", k_int > k_ext)
# Measured 2026-11-26: +6.6 % (371.60 against 348.54 N/µm); ISO's c' is an empirical fit for
# solid gears (C_M = 0.8 of the theoretical value), so the FE is not expected to equal it;
# tolerance 20 %, three times the measured deviation.
checks.near("FE internal k / ISO c'b internal", k_int, iso_int, 0.20)
# The relation itself: FE ratio internal/external (1.0624) against ISO's (1.0696), measured
# 2026-11-26: −0.67 %; tolerance 2 %, three times that.
checks.near("FE ratio internal/external / ISO ratio", k_int / k_ext, iso_int / iso_ext, 0.02)
checks.done()
