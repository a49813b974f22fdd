#!/usr/bin/env python3
"""The counts docs/developers.md states about the tree, computed from the tree (issue 45).

    python3 tools/house_counts.py            print the generated block
    python3 tools/house_counts.py --check    exit 1 when docs/developers.md's block differs (CI:
                                             ctest docs.house_counts), printing the difference
    python3 tools/house_counts.py --write    rewrite the block in docs/developers.md

The block lies between the lines `<!-- house_counts: begin -->` and `<!-- house_counts: end -->`.
It holds: files and lines per module (production code, tests, bench); the module and app-wing
include graph with its upward arrows (an include of a module not below in the layer table); the
functions over 80 lines (from a column-0 `{` to its `}`, parameter declaration tables named
`declare_*` listed apart since they are allowed); files over the size limits; and runs of six or
more code lines repeated to the letter. Standard library only, so CI needs nothing but Python 3.

Files: what git tracks plus untracked files it does not ignore (so a new file counts before it is
committed); outside a git checkout, every file below the root except build folders.
"""
import argparse
import difflib
import hashlib
import os
import re
import subprocess
import sys
from collections import defaultdict

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
DOC = os.path.join("docs", "developers.md")
BEGIN = "<!-- house_counts: begin (tools/house_counts.py --write; do not edit by hand) -->"
END = "<!-- house_counts: end -->"

# The layers, lowest first: a module may include its own headers and those of the modules listed
# for it (the graph of the top-level CMakeLists.txt). Any other include is an upward arrow.
MODULES = ["errors", "kinematics", "dynamics", "geometry", "fem", "contact", "stiffness", "app",
           "python"]
ALLOWED = {
    "errors": set(),
    "kinematics": {"errors"},
    "dynamics": {"errors", "kinematics"},
    "geometry": {"errors", "kinematics"},
    "fem": {"errors"},
    "contact": {"errors", "fem"},
    "stiffness": {"errors", "kinematics", "dynamics", "geometry", "fem", "contact"},
    "app": {"errors", "kinematics", "dynamics", "geometry", "fem", "contact", "stiffness"},
    "python": {"errors", "kinematics", "dynamics", "geometry", "fem", "contact", "stiffness",
               "app"},
}
# The wings of app/, lowest first, and what each may include (app/CMakeLists.txt).
WINGS = ["core", "kinematics", "scenes", "stiffness", "dynamics", "cycloid"]
WINGS_ALLOWED = {
    "core": set(),
    "kinematics": {"core"},
    "scenes": {"core", "kinematics"},
    "stiffness": {"core", "kinematics", "scenes"},
    "dynamics": {"core", "kinematics"},
    "cycloid": {"core", "kinematics", "scenes"},
}
# Modules whose code must not include deal.II (they build without it).
PLAIN = {"errors", "kinematics", "dynamics", "geometry"}
# The naming contract (app/core/field_names.h): library code names its own fields, app/ maps them
# to the parameter paths users write. A string literal that is such a path ("Train/output",
# "Simulation/time step", or a section head "Train/" a key is appended to) in a library module
# is counted; in the modules listed here it fails --check, except in the files of NOT_YET_NAMED.
NAMED_BY_FIELD = ["kinematics", "dynamics", "geometry", "contact", "stiffness"]
# Files of those modules that still spell user paths, each with why (remove it once converted).
NOT_YET_NAMED: dict[str, str] = {}
LIBRARIES = ["kinematics", "dynamics", "geometry", "fem", "contact", "stiffness"]
USER_PATH = re.compile(r'"((?:[A-Z][a-z]+|ISO)(?: [A-Za-z0-9\']+)*)/([A-Za-z][A-Za-z0-9_\' ]*)?"')
# The field helpers of kinematics/fields.h and dynamics/fields.h and the member lists app/ maps
# (field_family over each list): a member a library names must be in its list.
FIELD_LISTS = {"gear": ["gear_members"], "train": ["train_fields"],
               "simulation": ["simulation_fields"], "iso6336": ["iso6336_fields"],
               "speed_sweep": ["speed_sweep_fields"], "train_mesh": ["train_mesh_fields"],
               "mesh": ["mesh_fields"], "deck": ["deck_fields"], "disc": ["disc_fields"],
               "correction": ["correction_fields"], "cycloid_scene": ["cycloid_scene_fields"],
               "cylinders": ["cylinders_fields"], "contact": ["contact_fields"],
               "train_gear": ["train_gear_fields"], "gear_mesh": ["gear_mesh_fields"],
               "cycloid_loads": ["cycloid_loads_fields"]}
FIELD_HEADERS = ["kinematics/fields.h", "dynamics/fields.h", "geometry/fields.h",
                 "contact/fields.h", "stiffness/cycloid_loads.h"]
FIELD_CALL = re.compile(r'field::(\w+)\((?:[^,()]+, )?"(\w+)"\)')
FUNCTION_LIMIT = 80  # lines
FILE_LIMIT = 900  # lines
FILE_LIMITS = {"contact": 600}  # lines, stricter per module
REPEAT_LINES = 6  # code lines a repeated run has at least
SOURCE = re.compile(r"\.(cc|h)$")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/(?:([a-z_]+)/)?[^"]*"')


def tree_files():
    try:
        out = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"],
                             cwd=ROOT, capture_output=True, text=True, check=True).stdout
        files = [f for f in out.splitlines() if os.path.isfile(os.path.join(ROOT, f))]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for folder, dirs, names in os.walk(ROOT):
            dirs[:] = [d for d in dirs if not d.startswith(("build", "."))]
            files += [os.path.relpath(os.path.join(folder, n), ROOT) for n in names]
    return sorted(f for f in files if SOURCE.search(f))


def read_lines(path):
    with open(os.path.join(ROOT, path), encoding="utf-8", errors="replace") as f:
        return f.read().split("\n")[:-1]


def family(path):
    top = path.split("/")[0]
    if top in MODULES:
        return "production", top
    if top in ("tests", "bench", "examples"):
        return top, top
    return "other", top


CONTROL = re.compile(r"(if|for|while|switch|else|do|try|catch|return)\b")


def long_functions(path, lines):
    """(name, first line, length) of every function body longer than the limit: a `{` alone on
    its line after a signature (at any indent: methods defined in a class count too), to the `}`
    at the same indent; lengths from the signature's first line. Lambdas and control blocks are
    not functions of their own."""
    found = []
    i = 0
    while i < len(lines):
        if lines[i].strip() != "{":
            i += 1
            continue
        indent = len(lines[i]) - len(lines[i].lstrip())
        j = i
        while j > 0 and lines[j - 1].strip() and not lines[j - 1].rstrip().endswith(
                (";", "}", "{", ":")) and not lines[j - 1].lstrip().startswith(("//", "#")):
            j -= 1
        # "public:" ends a run; an initializer list's ": a(b)" line does not end in ':'
        head = " ".join(l.strip() for l in lines[j:i])
        is_function = ("(" in head and not CONTROL.match(head) and "[" not in head.split("(")[0]
                       and "](" not in head and not re.match(r"(namespace|struct|class|enum|union)\b", head)
                       and not head.endswith((",", "=")))
        if not is_function:
            i += 1
            continue
        end = i + 1
        while end < len(lines) and not (lines[end].startswith(" " * indent + "}") and (
                len(lines[end]) - len(lines[end].lstrip()) == indent)):
            end += 1
        length = end - j + 1
        if length > FUNCTION_LIMIT:
            name = re.search(r"([A-Za-z_][A-Za-z_0-9:~]*)\s*\(", head)
            found.append((name.group(1) if name else head[:40], j + 1, length))
        i = end + 1
    return found


def code_line(line):
    text = " ".join(line.split())
    if not text or text.startswith(("//", "#include", "*", "/*")):
        return None
    if re.fullmatch(r"[{}();,\s]*", text) or text in ("} // namespace", "public:", "private:"):
        return None
    return text


def repeats(sources):
    """Pairs of places (file a lines, file b lines) sharing a run of REPEAT_LINES code lines."""
    windows = defaultdict(list)
    for path, lines in sources.items():
        code = [(n + 1, c) for n, c in ((n, code_line(l)) for n, l in enumerate(lines)) if c]
        for k in range(len(code) - REPEAT_LINES + 1):
            digest = hashlib.sha1("\n".join(c for _, c in code[k:k + REPEAT_LINES]).encode())
            windows[digest.hexdigest()].append((path, code[k][0], code[k + REPEAT_LINES - 1][0]))
    pairs = {}
    for places in windows.values():
        if len(places) < 2 or len(places) > 8:  # more than 8: a common idiom, not a copy
            continue
        for a in range(len(places)):
            for b in range(a + 1, len(places)):
                (fa, sa, ea), (fb, sb, eb) = sorted((places[a], places[b]))
                if fa == fb and sb <= ea:
                    continue  # overlapping windows of one run
                key = (fa, fb)
                runs = pairs.setdefault(key, [])
                for run in runs:  # extend a run of consecutive windows
                    if run[1] >= sa - 1 and run[3] >= sb - 1 and run[0] <= sa and run[2] <= sb:
                        run[1], run[3] = max(run[1], ea), max(run[3], eb)
                        break
                else:
                    runs.append([sa, ea, sb, eb])
    rows = []
    for (fa, fb), runs in pairs.items():
        for sa, ea, sb, eb in runs:
            rows.append((fa, sa, ea, fb, sb, eb))
    return sorted(rows, key=lambda r: (-(r[2] - r[1]), r))


def include_graph(sources):
    modules, wings, plain_dealii = defaultdict(set), defaultdict(set), []
    for path, lines in sources.items():
        kind, module = family(path)
        if kind != "production":
            continue
        wing = path.split("/")[1] if module == "app" and path.count("/") >= 2 else None
        for line in lines:
            if module in PLAIN and re.match(r"\s*#\s*include\s*<deal\.II/", line):
                plain_dealii.append(path)
            m = INCLUDE.match(line)
            if not m or m.group(1) not in MODULES:
                continue
            if m.group(1) != module:
                modules[module].add(m.group(1))
            elif wing and m.group(2) and m.group(2) != wing:
                wings[wing].add(m.group(2))
    return modules, wings, sorted(set(plain_dealii))


def mutual_includes(sources):
    """Pairs of components (x.h, x.cc and a private x_internal.h as one) that include each
    other."""
    edges = defaultdict(set)
    for path, lines in sources.items():
        if family(path)[0] != "production":
            continue
        component = re.sub(r"_internal$", "", os.path.splitext(path)[0])
        for line in lines:
            m = re.match(r'\s*#\s*include\s+"([^"]+)\.h"', line)
            # a private header of one component (x_internal.h) is part of it
            if m and m.group(1) != component and m.group(1) != component + "_internal":
                edges[component].add(m.group(1))
    return sorted((a, b) for a in edges for b in edges[a] if a < b and a in edges.get(b, ()))


def upward(graph, allowed):
    return sorted((a, b) for a, targets in graph.items() for b in targets
                  if b not in allowed.get(a, set()))


def count_sizes(sources):
    """Files and lines per family (production, tests, ...), per module and per app wing."""
    sizes = {"family": defaultdict(lambda: [0, 0]), "module": defaultdict(lambda: [0, 0]),
             "wing": defaultdict(lambda: [0, 0])}
    for path, lines in sources.items():
        kind, module = family(path)
        parts = path.split("/")
        keys = [("family", kind)]
        if kind == "production":
            keys.append(("module", module))
        if parts[0] == "app" and len(parts) >= 3:
            keys.append(("wing", parts[1]))
        for table, key in keys:
            sizes[table][key][0] += 1
            sizes[table][key][1] += len(lines)
    return sizes


def size_lines(sizes):
    out = ["C++ files (`.cc`, `.h`) and their lines:", "", "| module | files | lines |",
           "|---|---:|---:|"]
    rows = [(m + "/", sizes["module"][m]) for m in MODULES if m in sizes["module"]]
    rows += [("**all production code**" if k == "production" else k + "/", sizes["family"][k])
             for k in ("production", "tests", "bench", "examples", "other")
             if k in sizes["family"]]
    out += [f"| {label} | {files} | {lines} |" for label, (files, lines) in rows]
    wings = sizes["wing"]
    if wings:
        out += ["", "app/ wings: " + ", ".join(f"{w}/ {wings[w][0]} files {wings[w][1]} lines"
                                               for w in WINGS if w in wings) + "."]
    return out


def listed(items):
    items = list(items)
    return "" if not items else " — " + ", ".join(items)


def house_lines(sources, sizes):
    modules, wings, plain_dealii = include_graph(sources)
    up = upward(modules, ALLOWED) + [("app/" + a, "app/" + b) for a, b in upward(wings,
                                                                              WINGS_ALLOWED)]
    mutual = mutual_includes(sources)
    out = ["", "The house (each module and the modules it includes; app/'s wings apart):", ""]
    rows = [(m, sorted(modules.get(m, []))) for m in MODULES if m in sizes["module"]]
    rows += [("app/" + w, ["app/" + t for t in sorted(wings.get(w, []))]) for w in WINGS
             if w in sizes["wing"]]
    out += [f"    {name:<15}-> {', '.join(targets) or '-'}" for name, targets in rows]
    out += ["", "Upward arrows (an include the layer table of tools/house_counts.py does not "
                f"allow): {len(up)}" + listed(f"{a} -> {b}" for a, b in up) + ".",
            f"Components (x.h with x.cc) that include each other: {len(mutual)}"
            + listed(f"{a} <-> {b}" for a, b in mutual) + ".",
            f"deal.II included by a deal.II-free module: {len(plain_dealii)}"
            + listed(plain_dealii) + "."]
    return out


def size_limit_lines(sources):
    functions = sorted(((length, path, line, name) for path, lines in sources.items()
                        for name, line, length in long_functions(path, lines)),
                       key=lambda f: (-f[0], f[1]))
    tables = [f for f in functions if f[3].split("::")[-1].startswith("declare_")]
    others = [f for f in functions if f not in tables]
    big = sorted(f"{path} ({len(lines)} > {FILE_LIMITS.get(family(path)[1], FILE_LIMIT)})"
                 for path, lines in sources.items() if family(path)[0] == "production"
                 and len(lines) > FILE_LIMITS.get(family(path)[1], FILE_LIMIT))
    largest = max(((len(l), p) for p, l in sources.items() if family(p)[0] == "production"),
                  default=(0, "-"))
    return ["", f"Functions over {FUNCTION_LIMIT} lines outside parameter declaration tables: "
                f"{len(others)}" + listed(f"`{n}` {p}:{l} ({k})" for k, p, l, n in others) + ".",
            f"Parameter declaration tables over {FUNCTION_LIMIT} lines (allowed): {len(tables)}"
            + listed(f"`{n}` {p}:{l} ({k})" for k, p, l, n in tables) + ".",
            f"Production files over their limit ({FILE_LIMIT} lines; contact/ "
            f"{FILE_LIMITS['contact']}): {len(big)}" + listed(big)
            + f". Largest: {largest[1]} ({largest[0]} lines)."]


def repeat_lines(sources):
    rows = repeats(sources)
    production = [r for r in rows if "production" in (family(r[0])[0], family(r[3])[0])]
    out = ["", f"Runs of {REPEAT_LINES} or more code lines repeated to the letter (comments, "
               f"includes and lone braces skipped; runs in more than 8 places are idioms): "
               f"{len(rows)} pairs of places, {len(production)} touching production code."]
    out += [f"- {fa}:{sa}-{ea} ~ {fb}:{sb}-{eb}" for fa, sa, ea, fb, sb, eb in production[:12]]
    if len(production) > 12:
        out.append(f"- (+{len(production) - 12} more)")
    return out


def user_paths(sources):
    """module -> [(path, line, literal)] of the user parameter paths its code spells."""
    found = defaultdict(list)
    for path, lines in sources.items():
        kind, module = family(path)
        if kind != "production" or module not in LIBRARIES:
            continue
        for number, line in enumerate(lines, 1):
            code = line.split("//")[0] if not line.lstrip().startswith("//") else ""
            for match in USER_PATH.finditer(code):
                found[module].append((path, number, match.group(0)))
    return found


def unlisted_fields(sources):
    """(path, line, helper, member) of each field a library names that its list lacks."""
    lists = defaultdict(set)
    for header in FIELD_HEADERS:
        text = "\n".join(sources.get(header, []))
        for name, body in re.findall(r"(\w+)\(\)\s*\{\s*static const std::vector<std::string> "
                                     r"members = \{([^}]*)\}", text):
            lists[name] |= set(re.findall(r'"(\w+)"', body))
    missing = []
    for path, lines in sources.items():
        if family(path)[1] not in NAMED_BY_FIELD:
            continue
        for number, line in enumerate(lines, 1):
            for helper, member in FIELD_CALL.findall(line):
                allowed = set().union(*(lists[n] for n in FIELD_LISTS.get(helper, [])))
                if helper in FIELD_LISTS and member not in allowed:
                    missing.append((path, number, helper, member))
    return missing


def naming_lines(sources):
    found = user_paths(sources)
    counts = ", ".join(f"{m} {len(found.get(m, []))}" for m in LIBRARIES)
    out = ["", "User parameter paths spelt in library code (string literals such as "
               f'`"Train/output"`; app/ maps library fields to them): {counts}. Modules that name '
               f"fields only (the check fails otherwise): {', '.join(NAMED_BY_FIELD)}; files of "
               f"those not converted yet: {len(NOT_YET_NAMED)}"
               + listed(f"{path} ({why})" for path, why in sorted(NOT_YET_NAMED.items())) + "."]
    return out


def naming_failures(sources):
    found = user_paths(sources)
    failures = [f"{p}:{n}: {lit} (library code names its field; app/ maps it)"
                for m in NAMED_BY_FIELD for p, n, lit in found.get(m, []) if p not in NOT_YET_NAMED]
    failures += [f"{p}: listed in NOT_YET_NAMED but spells no user path: remove it"
                 for p in NOT_YET_NAMED if not any(f == p for m in NAMED_BY_FIELD
                                                   for f, _, _ in found.get(m, []))]
    failures += [f"{p}:{n}: field::{h}(\"{m}\") is in no member list of the fields headers, so "
                 f"app/ does not map it" for p, n, h, m in unlisted_fields(sources)]
    return failures


def block():
    sources = {f: read_lines(f) for f in tree_files()}
    sizes = count_sizes(sources)
    out = (size_lines(sizes) + house_lines(sources, sizes) + size_limit_lines(sources)
           + repeat_lines(sources) + naming_lines(sources))
    return "\n".join(out) + "\n"


def split_doc(text):
    if BEGIN not in text or END not in text:
        raise SystemExit(f"{DOC}: no block between '{BEGIN}' and '{END}'")
    head, rest = text.split(BEGIN, 1)
    body, tail = rest.split(END, 1)
    return head, body, tail


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--check", action="store_true", help="fail when the doc's block is stale")
    group.add_argument("--write", action="store_true", help="rewrite the doc's block")
    args = parser.parse_args()
    generated = block()
    if args.check:
        failures = naming_failures({f: read_lines(f) for f in tree_files()})
        for failure in failures:
            print(failure)
        if failures:
            return 1
    if not (args.check or args.write):
        sys.stdout.write(generated)
        return 0
    path = os.path.join(ROOT, DOC)
    with open(path, encoding="utf-8") as f:
        text = f.read()
    head, body, tail = split_doc(text)
    wanted = "\n" + generated
    if args.write:
        with open(path, "w", encoding="utf-8") as f:
            f.write(head + BEGIN + wanted + END + tail)
        return 0
    if body != wanted:
        sys.stdout.writelines(difflib.unified_diff(body.splitlines(True), wanted.splitlines(True),
                                                   DOC + " (stated)", "the tree (generated)"))
        print(f"{DOC}: the counts differ from the tree; run: python3 tools/house_counts.py --write")
        return 1
    print(f"{DOC}: counts match the tree")
    return 0


if __name__ == "__main__":
    sys.exit(main())
