#!/usr/bin/env python3
"""Compares a command's summary.json with the stored one (tests/regression/<case>.json).

Usage: compare.py STORED ACTUAL            exit 0 when they agree, 1 with one line per difference
       compare.py --bless STORED ACTUAL    copy ACTUAL over STORED (after an intended change)

Agreement, field by field (the ASPECT way: the whole output, numeric tolerances):
- numbers: |a - b| <= rtol*max(|a|, |b|) + atol with rtol = 1e-6. The floor atol comes from the
  case's own scale, never from a fixed number: 1e-9 of the largest magnitude the stored output
  holds of the same physical kind (forces with forces, the load for a reaction; stresses with
  stresses; moments with moments and with force x length; a unit of no known kind with itself),
  and at least 1e-9 of the largest entry of the same table column. Round-off of a result whose
  true value is zero (a reaction of 1e-11 N beside a 129 N load) is far below that floor, and a
  real change of any result at the case's scale is far above it. A field listed in TOLERANCES
  below documents a larger scatter;
- wall-clock fields (and where they ran) are ignored by an explicit list of names (WALL_CLOCK,
  WALL_CLOCK_COLUMNS), not by a pattern: `decay_time`, `time_step`, `..._times_width` are
  results and are compared; a new timing field fails here until it is named in the list. Texts
  that only carry timings or paths are ignored (IGNORED_TEXT);
- everything else (keys, units, column names, the names a categorical column allows and holds,
  row counts, texts, file names) must be identical.
"""
import json
import math
import re
import shutil
import sys

RTOL = 1e-6
FLOOR = 1e-9  # of the case's own scale of the same kind (see above)

# Wall-clock measurements and where they ran: never a result (values and table columns).
WALL_CLOCK = {
    "cost", "cost_single", "cost_double", "cost_sweep", "cost_total",
    "time_total", "time_setup", "time_assembly", "time_solve", "time_per_iteration",
    "time_scene", "time_geometry", "time_meshing", "time_checking", "time_writing",
    "integration_time", "integration_cpu_time", "sweep_time", "sweep_wall_time",
    "sweep_cpu_time", "sweep_once_time", "sweep_per_position_time",
    "scene_time", "meshing_time", "read_time", "setup_time", "factorization_time",
    "iteration_time", "evaluate_time", "solve_wall_time",
    "corrected_scene_time", "corrected_meshing_time", "corrected_read_time",
    "corrected_setup_time", "corrected_factorization_time", "corrected_iteration_time",
    "corrected_evaluate_time", "corrected_solve_wall_time",
    "sweep_ranks", "mpi_ranks",
}
WALL_CLOCK_COLUMNS = {
    "time",        # active_set_history: wall time of each iteration
    "solve_time",  # cycloid_correction
    "rank",        # run_sweep: which rank solved a position (whichever was free)
    "wall_time", "cpu_time", "total_time", "setup_time", "scene_time", "factorization_time",
}
IGNORED_TEXT = re.compile(r"(^|_)(time|timing|timings|path|directory|file|host|date)(_|$)")

# Units by physical kind and factor to SI: the floor of a value is FLOOR times the largest
# magnitude of its kind in the stored output. Units of no listed kind form a kind of their own.
UNIT_KIND = {
    "N": ("force", 1.), "kN": ("force", 1e3),
    "m": ("length", 1.), "mm": ("length", 1e-3), "µm": ("length", 1e-6), "um": ("length", 1e-6),
    "N·m": ("moment", 1.), "N·mm": ("moment", 1e-3), "Nm": ("moment", 1.), "N*m": ("moment", 1.),
    "Pa": ("stress", 1.), "MPa": ("stress", 1e6), "GPa": ("stress", 1e9),
    "N/m": ("stiffness", 1.), "N/µm": ("stiffness", 1e6), "N/um": ("stiffness", 1e6),
    "N/mm": ("line load", 1e3), "N/(mm·µm)": ("stiffness per length", 1e9),
    "rad": ("angle", 1.), "deg": ("angle", math.pi / 180), "arcmin": ("angle", math.pi / 10800),
    "µrad": ("angle", 1e-6), "urad": ("angle", 1e-6), "1e-4 rad": ("angle", 1e-4),
    "s": ("duration", 1.), "ms": ("duration", 1e-3), "µs": ("duration", 1e-6),
    "us": ("duration", 1e-6),
}


def kind(unit):
    return UNIT_KIND.get(unit, (f"unit {unit}", 1.))


def numbers(document):
    """(unit, value) of every finite number the output holds (values and table entries)."""
    for v in document.get("values", {}).values():
        for field in ("value", "published"):
            x = v.get(field)
            if isinstance(x, (int, float)) and math.isfinite(x):
                yield v.get("unit"), x
    for t in document.get("tables", {}).values():
        for row in t["rows"]:
            for unit, x in zip(t["units"], row):
                if isinstance(x, (int, float)) and math.isfinite(x):
                    yield unit, x


def kind_scales(document):
    """The largest magnitude (SI) of each kind in `document`; a moment's scale is at least the
    largest force times the largest length (a reaction moment of a zero-moment case is round-off
    of force x arm)."""
    scales = {}
    for unit, x in numbers(document):
        name, factor = kind(unit)
        scales[name] = max(scales.get(name, 0.), abs(x) * factor)
    scales["moment"] = max(scales.get("moment", 0.),
                           scales.get("force", 0.) * scales.get("length", 0.))
    return scales


def floor(scales, unit):
    """The absolute floor of a number in `unit`, in that unit."""
    name, factor = kind(unit)
    return FLOOR * scales.get(name, 0.) / factor


# Fields whose scatter is larger than round-off, with the reason. Key: "values/<key>" or
# "tables/<table>/<column>"; value: (rtol, atol).
TOLERANCES = {
    # Active-set iterations of a sweep position on 2 ranks depend on which position the rank
    # solved before it (warm start; positions go to whichever rank is free, fem::distribute_items):
    # the count differs by one between runs, the converged k does not (to 1e-6).
    "tables/stiffness_sweep/iterations": (math.inf, math.inf),
}


def close(a, b, rtol, atol):
    if a is None or b is None:
        return a is None and b is None
    if isinstance(a, str) or isinstance(b, str):
        return a == b
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return abs(a - b) <= rtol * max(abs(a), abs(b)) + atol


def compare(stored, actual):
    diffs = []
    scales = kind_scales(stored)

    def differ(where, message):
        diffs.append(f"{where}: {message}")

    if stored.get("command") != actual.get("command"):
        differ("command", f"{stored.get('command')!r} != {actual.get('command')!r}")
    st, at = stored.get("text", {}), actual.get("text", {})
    for key in sorted(set(st) | set(at)):
        if IGNORED_TEXT.search(key):
            continue
        if key not in st or key not in at:
            differ(f"text/{key}", "only in " + ("stored" if key in st else "actual"))
        elif st[key] != at[key]:
            differ(f"text/{key}", f"{st[key]!r} != {at[key]!r}")
    sv, av = stored.get("values", {}), actual.get("values", {})
    for key in sorted(set(sv) | set(av)):
        if key in WALL_CLOCK:
            continue
        where = f"values/{key}"
        if key not in sv or key not in av:
            differ(where, "only in " + ("stored" if key in sv else "actual"))
            continue
        s, a = sv[key], av[key]
        if s.get("unit") != a.get("unit"):
            differ(where, f"unit {s.get('unit')!r} != {a.get('unit')!r}")
        rtol, atol = TOLERANCES.get(where, (RTOL, floor(scales, s.get("unit"))))
        for field in ("value", "published"):
            if (field in s) != (field in a):
                differ(where, f"{field} only in " + ("stored" if field in s else "actual"))
            elif field in s and not close(s[field], a[field], rtol, atol):
                differ(where, f"{field} {s[field]!r} != {a[field]!r}")
    stab, atab = stored.get("tables", {}), actual.get("tables", {})
    for name in sorted(set(stab) | set(atab)):
        where = f"tables/{name}"
        if name not in stab or name not in atab:
            differ(where, "only in " + ("stored" if name in stab else "actual"))
            continue
        s, a = stab[name], atab[name]
        if s["columns"] != a["columns"] or s["units"] != a["units"]:
            differ(where, f"columns {list(zip(s['columns'], s['units']))} != "
                          f"{list(zip(a['columns'], a['units']))}")
            continue
        if s.get("categories", {}) != a.get("categories", {}):
            differ(where, f"categories {s.get('categories', {})} != {a.get('categories', {})}")
            continue
        if len(s["rows"]) != len(a["rows"]):
            differ(where, f"{len(s['rows'])} rows != {len(a['rows'])}")
            continue
        for c, column in enumerate(s["columns"]):
            if column in WALL_CLOCK_COLUMNS:
                continue
            values = [row[c] for row in s["rows"] + a["rows"]
                      if isinstance(row[c], (int, float)) and math.isfinite(row[c])]
            scale = max((abs(v) for v in values), default=0.)
            unit = s["units"][c]
            rtol, atol = TOLERANCES.get(f"{where}/{column}",
                                        (RTOL, max(FLOOR * scale, floor(scales, unit))))
            for r, (srow, arow) in enumerate(zip(s["rows"], a["rows"])):
                if not close(srow[c], arow[c], rtol, atol):
                    differ(f"{where}/{column}[{r}]", f"{srow[c]!r} != {arow[c]!r}")
    if sorted(stored.get("files", [])) != sorted(actual.get("files", [])):
        differ("files", f"{sorted(stored.get('files', []))} != {sorted(actual.get('files', []))}")
    return diffs


def main(argv):
    bless = "--bless" in argv
    args = [a for a in argv if a != "--bless"]
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    stored_path, actual_path = args
    with open(actual_path) as f:
        actual = json.load(f)
    if bless:
        shutil.copyfile(actual_path, stored_path)
        print(f"blessed {stored_path}")
        return 0
    with open(stored_path) as f:
        stored = json.load(f)
    diffs = compare(stored, actual)
    for d in diffs[:60]:
        print(d)
    if len(diffs) > 60:
        print(f"... and {len(diffs) - 60} more differences")
    if diffs:
        print(f"{len(diffs)} difference(s) from {stored_path}; if the change is intended, "
              "re-bless with tools/bless_regression.sh")
    return 1 if diffs else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
