#!/usr/bin/env python3
"""Compares a command's summary.json with the stored one (tests/regression/<case>.json).

Usage: compare.py STORED ACTUAL            exit 0 when they agree, 1 with one line per difference
       compare.py --bless STORED ACTUAL    copy ACTUAL over STORED (after an intended change)

Agreement, field by field (the ASPECT way: the whole output, numeric tolerances):
- numbers: |a - b| <= rtol*max(|a|, |b|) + atol with rtol = 1e-6; atol = 1e-9 of the largest
  magnitude in the same table column (a column's near-zero entries are round-off of its scale)
  and 1e-12 for scalar values; a field listed in TOLERANCES below documents a larger scatter;
- timings, ranks and wall-clock fields are ignored (IGNORED_KEYS / IGNORED_COLUMNS), and so are
  texts that only carry timings or paths (IGNORED_TEXT);
- everything else (keys, units, column names, the names a categorical column allows and holds,
  row counts, texts, file names) must be identical.
"""
import json
import math
import re
import shutil
import sys

RTOL = 1e-6
SCALAR_ATOL = 1e-12
COLUMN_ATOL = 1e-9

# Wall-clock measurements and where they ran: never a result.
TIMING = re.compile(r"(^|_)(time|times|seconds|elapsed|wall|rank|ranks|memory|speed_up|"
                    r"throughput|cost)(_|$)")
IGNORED_TEXT = re.compile(r"(^|_)(time|timing|timings|path|directory|file|host|date)(_|$)")

# Fields whose scatter is larger than round-off, with the reason. Key: "values/<key>" or
# "tables/<table>/<column>"; value: (rtol, atol).
TOLERANCES = {
    # Active-set iterations of a sweep position on 2 ranks depend on which position the rank
    # solved before it (warm start; positions go to whichever rank is free, fem::distribute_items):
    # the count differs by one between runs, the converged k does not (to 1e-6).
    "tables/stiffness_sweep/iterations": (math.inf, math.inf),
}


def ignored(name):
    return bool(TIMING.search(name))


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

    def differ(where, message):
        diffs.append(f"{where}: {message}")

    if stored.get("command") != actual.get("command"):
        differ("command", f"{stored.get('command')!r} != {actual.get('command')!r}")
    st, at = stored.get("text", {}), actual.get("text", {})
    for key in sorted(set(st) | set(at)):
        if IGNORED_TEXT.search(key) or ignored(key):
            continue
        if key not in st or key not in at:
            differ(f"text/{key}", "only in " + ("stored" if key in st else "actual"))
        elif st[key] != at[key]:
            differ(f"text/{key}", f"{st[key]!r} != {at[key]!r}")
    sv, av = stored.get("values", {}), actual.get("values", {})
    for key in sorted(set(sv) | set(av)):
        if ignored(key):
            continue
        where = f"values/{key}"
        if key not in sv or key not in av:
            differ(where, "only in " + ("stored" if key in sv else "actual"))
            continue
        s, a = sv[key], av[key]
        if s.get("unit") != a.get("unit"):
            differ(where, f"unit {s.get('unit')!r} != {a.get('unit')!r}")
        rtol, atol = TOLERANCES.get(where, (RTOL, SCALAR_ATOL))
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
            if ignored(column):
                continue
            values = [row[c] for row in s["rows"] + a["rows"]
                      if isinstance(row[c], (int, float)) and math.isfinite(row[c])]
            scale = max((abs(v) for v in values), default=0.)
            rtol, atol = TOLERANCES.get(f"{where}/{column}", (RTOL, COLUMN_ATOL * scale))
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
