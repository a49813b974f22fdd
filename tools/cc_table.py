"""The rows of a constant table in a C++ source, for the scripts that computed it to check it
(tools/wedge_layer.py, tools/end_face_layer.py): `name = {{ {{a, b, ...}}, ... }};`."""
import os
import re

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def table_rows(name, source=os.path.join("stiffness", "ltca_contact.cc")):
    """[[float, ...], ...]: each inner {{...}} of the table `name` in `source` (from the root)."""
    with open(os.path.join(ROOT, source), encoding="utf-8") as f:
        text = f.read()
    block = text[text.index(f"{name} = {{{{"):]
    block = block[:block.index("}};")]
    return [[float(v) for v in row.split(",")] for row in re.findall(r"\{\{([^{}]*)\}\}", block)]
