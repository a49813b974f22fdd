#!/usr/bin/env bash
# A helical pair with lead crowning (issue 46; docs/helical.md "Lead crowning"): its loaded TE
# over a mesh cycle at several torques, its contact pattern and its Harris map beside the
# unmodified pair.
#
#     examples/helical_lead_crowning.sh [path/to/gearstiff] [OUT_FOLDER]
#
# The pair: z 19/29, m_n 2 mm, β ±20° (ISO 21771 hands: external pair, opposite hands), b 9.19 mm
# so that ε_β = b·sin β/(π·m_n) = 0.5, 8 layers (16 per unit ε_β: the twist rule's 8 per unit
# leave this pair's contact lines a mortar gap beyond the overlap tolerance, docs/helical.md
# "Face width and ε_β"), Q1, frictionless, the small pair's coarse cell sizes (tests/helical). Lead crowning C_β = 10 µm on the pinion (removed at
# both face ends, parabolic, 0 in the middle; the amount normal to the flank, ISO 21771).
# One `stiffness` sweep of POSITIONS positions over a transverse base pitch at every torque of
# TORQUES (one scene and factorization per position for all of them), and the same for the
# unmodified teeth as a variant. OUT_FOLDER receives the report (report.json, tables as CSV) and
# the charts `gearstiff` draws:
#   contact_pattern.png  line load over the face width at every position (the crowned pinion at
#                        the first torque): the load gathers at the middle of the face
#   harris_map.png       TE peak-to-peak against torque, crowned and unmodified
#   transmission_error.png, stiffness.png   TE and k over the cycle
set -euo pipefail
gearstiff=${1:-$(dirname "$0")/../build/app/gearstiff}
out=${2:-helical_lead_crowning}
POSITIONS=${POSITIONS:-6}
TORQUES=${TORQUES:-"11.5, 23, 46, 92"} # N·m: 1.25, 2.5, 5, 10 N·m per mm of face
"$gearstiff" stiffness -o "$out" \
  --set "Mesh/dimension=3" --set "Finite elements/Element degree=1" \
  --set "Contact/Friction coefficient=0" --set "Stiffness/published reference=false" \
  --set "Gear pair/Pinion/teeth=19" --set "Gear pair/Wheel/teeth=29" \
  --set "Gear pair/Pinion/module=2" --set "Gear pair/Wheel/module=2" \
  --set "Gear pair/Pinion/profile shift=0" --set "Gear pair/Wheel/profile shift=0" \
  --set "Gear pair/Pinion/helix angle=20" --set "Gear pair/Wheel/helix angle=-20" \
  --set "Gear pair/Pinion/face width=9.19" --set "Gear pair/Wheel/face width=9.19" \
  --set "Mesh/layers=8" --set "Mesh/contact size=0.15" --set "Mesh/fine radius=0.4" \
  --set "Mesh/body size=0.75" --set "Mesh/rim size=2.5" \
  --set "Gear pair/Pinion/lead crowning=10" \
  --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=$POSITIONS" \
  --set "Stiffness/torques=$TORQUES" \
  --set "Stiffness/variants=Pinion/lead crowning = 0"
echo "written: $out (contact_pattern.png, harris_map.png, report.json)"
