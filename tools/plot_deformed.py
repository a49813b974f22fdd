#!/usr/bin/env python3
"""Deformed shape and contact pressure of one solved position, from its VTU, as a PNG.

    plot_deformed.py POSITION.vtu [POSITION_2.vtu ...] OUT.png

The VTU files are what `gearstiff stiffness` writes for a position (one per rank, deal.II
DataOut: points, cells, point data `displacement`, `von_mises_stress`, `contact_pressure`; ASCII or
zlib-compressed base64 binary), coordinates in mm. Left: the teeth about the loaded contact (a
quarter of the scene across), displacement magnified so that the largest there shows as 2 % of
the view, coloured by von Mises stress. Right: a zoom on the
contact with the largest pressure, the contact pressure at the closed nodes as coloured dots
over the deformed cells (true scale there). Plane (2D) scenes; for 3D the z = 0 face is drawn.
Matplotlib, Agg backend; the PNG path is the last argument. Standard library otherwise.
"""
import base64
import struct
import sys
import xml.etree.ElementTree as ElementTree
import zlib

import matplotlib

matplotlib.use("Agg")
import chart_case  # noqa: E402,F401  (every figure names its case in a footer)
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

FORMATS = {"Float32": "f", "Float64": "d", "Int32": "i", "Int64": "q", "UInt8": "B",
           "UInt32": "I", "UInt64": "Q", "Int8": "b"}


def decode(array, header_type):
    kind = FORMATS[array.get("type")]
    text = "".join((array.text or "").split())
    if array.get("format", "ascii") == "ascii":
        return [float(v) for v in text.split()] if text else []
    header_char = "Q" if header_type == "UInt64" else "I"
    size = struct.calcsize(header_char)
    # zlib (deal.II with zlib): header [blocks, block size, last block size, sizes...]
    first = base64.b64decode(text[: ((3 * size + 2) // 3) * 4])
    blocks = struct.unpack("<" + header_char, first[:size])[0]
    header_bytes = (3 + blocks) * size
    header_chars = ((header_bytes + 2) // 3) * 4
    header = struct.unpack("<" + header_char * (3 + blocks),
                           base64.b64decode(text[:header_chars])[:header_bytes])
    data = base64.b64decode(text[header_chars:])
    raw, offset = b"", 0
    for length in header[3:]:
        raw += zlib.decompress(data[offset:offset + length])
        offset += length
    return list(struct.unpack("<" + kind * (len(raw) // struct.calcsize(kind)), raw))


def decode_uncompressed(array, header_type):
    kind = FORMATS[array.get("type")]
    header_char = "Q" if header_type == "UInt64" else "I"
    raw = base64.b64decode("".join(array.text.split()))
    size = struct.calcsize(header_char)
    length = struct.unpack("<" + header_char, raw[:size])[0]
    body = raw[size:size + length]
    return list(struct.unpack("<" + kind * (len(body) // struct.calcsize(kind)), body))


def read_vtu(path):
    root = ElementTree.parse(path).getroot()
    header_type = root.get("header_type", "UInt32")
    compressed = root.get("compressor") is not None

    def values(array):
        if array.get("format", "ascii") == "ascii":
            return decode(array, header_type)
        return decode(array, header_type) if compressed else decode_uncompressed(array,
                                                                                 header_type)

    pieces = []
    for piece in root.iter("Piece"):
        points = values(piece.find("Points/DataArray"))
        cells = {a.get("Name"): values(a) for a in piece.find("Cells").iter("DataArray")}
        data = {}
        for a in piece.find("PointData").iter("DataArray"):
            data[a.get("Name")] = (int(a.get("NumberOfComponents", "1")), values(a))
        pieces.append((points, cells, data))
    return pieces


def main():
    files, png = sys.argv[1:-1], sys.argv[-1]
    polygons, stress, contact, base = [], [], [], []
    for path in files:
        for points, cells, data in read_vtu(path):
            xyz = [points[3 * i:3 * i + 3] for i in range(len(points) // 3)]
            ncomp, u = data["displacement"]
            disp = [u[ncomp * i:ncomp * i + 2] for i in range(len(xyz))]
            mises = data.get("von_mises_stress", data.get("von_mises", (1, [0.] * len(xyz))))[1]
            pressure = data.get("contact_pressure", (1, [0.] * len(xyz)))[1]
            start = 0
            for end in cells["offsets"]:
                ids = cells["connectivity"][int(start):int(end)][:4]
                start = end
                if len(ids) < 3 or any(abs(xyz[i][2]) > 1e-12 for i in ids):
                    continue
                base.append([(xyz[i][0], xyz[i][1], disp[i][0], disp[i][1]) for i in ids])
                stress.append(sum(mises[i] for i in ids) / len(ids) / 1e6)
            for i, p in enumerate(pressure):
                if p > 0. and abs(xyz[i][2]) < 1e-12:
                    contact.append((xyz[i][0] + disp[i][0], xyz[i][1] + disp[i][1], p / 1e6))
    # Millimetres: a gear's teeth are millimetres wide; metres made them specks on the axes.
    base = [[(1e3 * x, 1e3 * y, 1e3 * dx, 1e3 * dy) for x, y, dx, dy in cell] for cell in base]
    contact = [(1e3 * x, 1e3 * y, p) for x, y, p in contact]
    xs = [x for cell in base for x, _, _, _ in cell]
    ys = [y for cell in base for _, y, _, _ in cell]
    extent = max(max(xs) - min(xs), max(ys) - min(ys))
    peak = max(contact, key=lambda c: c[2]) if contact else None
    # Left: the teeth about the loaded contact (a quarter of the scene across), not whole gears.
    centre = (peak[0], peak[1]) if peak else (0.5 * (max(xs) + min(xs)), 0.5 * (max(ys) + min(ys)))
    window = 0.125 * extent
    near = [cell for cell in base
            if any(abs(x - centre[0]) <= window and abs(y - centre[1]) <= window
                   for x, y, _, _ in cell)] or base
    largest = max(max(abs(dx), abs(dy)) for cell in near for _, _, dx, dy in cell) or 1.
    scale = 0.02 * 2 * window / largest
    fig, (whole, zoom) = plt.subplots(1, 2, figsize=(13, 5.5))
    for ax, factor in ((whole, scale), (zoom, 1.)):
        shapes = [[(x + factor * dx, y + factor * dy) for x, y, dx, dy in cell] for cell in base]
        # Cell edges only where the cells are large enough on the page to be seen.
        collection = PolyCollection(shapes, array=stress, cmap="viridis",
                                    edgecolor="face" if ax is whole else "0.3",
                                    linewidth=0.2 if ax is whole else 0.1)
        ax.add_collection(collection)
        ax.set_aspect("equal")
        ax.autoscale_view()
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
    whole.set_xlim(centre[0] - window, centre[0] + window)
    whole.set_ylim(centre[1] - window, centre[1] + window)
    fig.colorbar(whole.collections[0], ax=whole, label="von Mises stress [MPa]")
    whole.set_title(f"teeth about the contact, displacement ×{scale:.3g}\n"
                    f"(largest {largest * 1e3:.3g} µm)", fontsize=10)
    if contact:
        # A few tenths of a millimetre: the loaded zone of a tooth contact and its cells.
        half = 0.004 * extent
        zoom.set_xlim(peak[0] - half, peak[0] + half)
        zoom.set_ylim(peak[1] - half, peak[1] + half)
        dots = zoom.scatter([c[0] for c in contact], [c[1] for c in contact],
                            c=[c[2] for c in contact], cmap="inferno", s=14, zorder=3)
        fig.colorbar(dots, ax=zoom, label="contact pressure [MPa]")
        zoom.set_title(f"contact pressure at the closed nodes (peak {peak[2]:.4g} MPa), true "
                       "scale", fontsize=10)
    else:
        zoom.set_title("no closed contact node", fontsize=10)
    fig.suptitle("Deformed teeth and contact pressure of the solved position", fontsize=11)
    fig.tight_layout()
    fig.savefig(png, dpi=130)


if __name__ == "__main__":
    main()
