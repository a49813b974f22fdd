#!/usr/bin/env python3
"""The geometry and mesh of a `gearstiff mesh` scene (ASCII .msh 4.1) as a PNG.

    plot_mesh.py SCENE.msh OUT.png

Draws every quadrilateral (2D) or the bottom face of every hexahedron (3D, first four nodes),
filled by body (physical group of its surface or volume, named in the legend), with the cell
edges; a second panel zooms on the smallest cells (the contact zones). Matplotlib, Agg backend;
the PNG path is the last argument.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import chart_case  # noqa: E402,F401  (every figure names its case in a footer)
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402


def read_msh(path):
    """Nodes {tag: (x, y)}, cells [(body, [tags])], physical names {(dim, tag): name}."""
    with open(path) as f:
        lines = [l.strip() for l in f]
    names, entity_body, nodes, cells = {}, {}, {}, []
    i = 0
    while i < len(lines):
        section = lines[i]
        if section == "$PhysicalNames":
            for k in range(int(lines[i + 1])):
                parts = lines[i + 2 + k].split(maxsplit=2)
                names[(int(parts[0]), int(parts[1]))] = parts[2].strip('"')
        elif section == "$Entities":
            counts = [int(v) for v in lines[i + 1].split()]
            row = i + 2 + counts[0] + counts[1]  # points and curves skipped
            for dim, count in ((2, counts[2]), (3, counts[3])):
                for k in range(count):
                    parts = lines[row + k].split()
                    n_physical = int(parts[7])
                    if n_physical > 0:
                        entity_body[(dim, int(parts[0]))] = int(parts[8])
                row += count
        elif section == "$Nodes":
            blocks = int(lines[i + 1].split()[0])
            row = i + 2
            for _ in range(blocks):
                count = int(lines[row].split()[3])
                tags = [int(lines[row + 1 + k]) for k in range(count)]
                for k, tag in enumerate(tags):
                    x, y = (float(v) for v in lines[row + 1 + count + k].split()[:2])
                    nodes[tag] = (x, y)
                row += 1 + 2 * count
        elif section == "$Elements":
            blocks = int(lines[i + 1].split()[0])
            row = i + 2
            for _ in range(blocks):
                dim, entity, kind, count = (int(v) for v in lines[row].split())
                if kind in (3, 5):  # 4-node quadrilateral, 8-node hexahedron
                    body = entity_body.get((dim, entity), entity)
                    for k in range(count):
                        tags = [int(v) for v in lines[row + 1 + k].split()[1:5]]
                        cells.append(((dim, body), tags))
                row += 1 + count
        i += 1
    return nodes, cells, names


def main():
    mesh, png = sys.argv[1], sys.argv[-1]
    nodes, cells, names = read_msh(mesh)
    bodies = sorted({body for body, _ in cells})
    fig, axes = plt.subplots(1, 2, figsize=(12, 5.5))
    sizes = []
    for ax in axes:
        for n, body in enumerate(bodies):
            polygons = [[nodes[t] for t in tags] for b, tags in cells if b == body]
            ax.add_collection(PolyCollection(polygons, facecolor=f"C{n}", alpha=0.35,
                                             edgecolor="k", linewidth=0.15,
                                             label=names.get(body, f"body {body[1]}")))
        ax.set_aspect("equal")
        ax.autoscale_view()
    # Zoom on the smallest cells: the contact zones are graded down to h_c.
    for _, tags in cells:
        xs = [nodes[t][0] for t in tags]
        ys = [nodes[t][1] for t in tags]
        sizes.append((max(max(xs) - min(xs), max(ys) - min(ys)), sum(xs) / 4, sum(ys) / 4))
    sizes.sort()
    smallest = sizes[: max(1, len(sizes) // 50)]
    cx = sum(s[1] for s in smallest) / len(smallest)
    cy = sum(s[2] for s in smallest) / len(smallest)
    half = max(30 * smallest[0][0], max(max(abs(s[1] - cx), abs(s[2] - cy)) for s in smallest))
    axes[1].set_xlim(cx - half, cx + half)
    axes[1].set_ylim(cy - half, cy + half)
    axes[0].set_title(f"{len(cells)} cells, {len(nodes)} nodes", fontsize=10)
    axes[1].set_title("the finest cells (contact zones)", fontsize=10)
    for ax in axes:
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
    axes[0].legend(loc="best", fontsize=7)
    fig.tight_layout()
    fig.savefig(png, dpi=130)


if __name__ == "__main__":
    main()
