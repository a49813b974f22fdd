#!/usr/bin/env python3
"""The table Ê(Δz/h, i) of stiffness::end_face_layer_excess (stiffness/ltca_contact.cc), computed.

    python3 tools/end_face_layer.py            print the table (a few minutes on one core)
    python3 tools/end_face_layer.py --check    recompute two rows of the table and the kernel's
                                               row of a load on the end plane (Δz/h 4) and
                                               compare them with stiffness/ltca_contact.cc;
                                               exit 1 when off
    python3 tools/end_face_layer.py --kernel [--ratio R ...]
                                               the layer's coupling between node planes under
                                               a one-plane load, interior and from the free end
                                               (interior_kernel, end_kernel)
    python3 tools/end_face_layer.py --inclined S ... [--ratio R]
                                               the interior kernel along an inclined (helical)
                                               contact line: plane m read at m·S (inclined_kernel)
    python3 tools/end_face_layer.py --rows [--ratio R ...]
                                               the kernel's whole rows: per Δz/h the interior
                                               row and the rows of the planes loaded 0 … 4
                                               from the free end (docs/ltca.md §3 "End faces")

The fast contact model (docs/ltca.md §3) joins an FE body, read at a depth h under a load on a
flank, to an analytic layer 0 ≤ y ≤ h that assumes plane strain: a line load infinitely long
along the face. A 3D face ends at the gears' traction-free end planes, where the layer under a
line load that stops at the free face is softer (a quarter-space, not a half-space). The exact
path (Q1 hexahedra extruded in `Mesh/layers` uniform layers of Δz) sees that softening through
its own discretisation along the face: with Δz ≫ h it cannot follow the end's boundary layer
(width ~h), with Δz ≲ h it can. So this script measures the layer's compression at the node
planes z_i = i·Δz from the free end on the exact path's own discretisation along z: a 3D Q1
model of the quarter-space x ≥ 0 (symmetry), y ≥ 0 (depth), z ≥ 0 (the end plane z = 0 free),
graded in x and y down to the contact's half-width a, uniform layers of Δz along z, loaded by a
Hertzian line load of 1 N/m along the whole face; minus the same layer under plane strain (the
2D model of the same x–y mesh: the 3D model with z held at both ends reproduces it exactly). The
excess is tabulated in units of 2(1−ν²)/(πE) per N/m, as a function of Δz/h and the plane's
index i from the end, for a/h = 0.1 (the fast model's meshes put a/h at 0.05 … 0.2; the
dependence on a/h is stated by `--spread`).

Mesh: x from 0 to 30·h (the half-width in 8 cells, then geometric), y from 0 to 30·h (the depth
h a node, geometric from a/8), z uniform Δz to max(8·h, 4·Δz) beyond the end, then geometric to
30·h + that, held u_z = 0 there (the face continues by symmetry); x = 30·h and y = 30·h held.
ν 0.3. numpy and scipy only.
"""
import argparse
import sys

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl

from cc_table import table_rows

RATIO = [0.5, 0.75, 1., 1.5, 2., 3., 4., 6., 8., 12., 16.]  # Δz/h
PLANES = 3  # node planes i = 0, 1, 2 from the end
POISSON = 0.3
HALF_WIDTH = 0.1  # a/h
KERNEL_RATIO = [0.5, 1., 2., 4., 8., 16.]  # Δz/h of the kernel's rows
KERNEL_REACH = 7  # planes read beyond the loaded one
KERNEL_END = 5  # planes loaded from the free end


def graded(start, first, end, growth):
    """Nodes from `start`, the first step `first`, growing geometrically to `end`."""
    nodes, step = [start], first
    while nodes[-1] + step < end - 0.5 * step:
        nodes.append(nodes[-1] + step)
        step *= growth
    nodes.append(end)
    return np.array(nodes)


def section_nodes(a, h=1.0, far=30., growth=1.35, refine=1):
    growth = growth ** (1. / refine)
    x = np.concatenate([np.linspace(0., a, 8 * refine + 1)[:-1],
                        graded(a, a / (8 * refine), far, growth)])
    y = np.concatenate([graded(0., a / (8 * refine), h, growth)[:-1],
                        graded(h, (h - 0) / (8 * refine), far, growth)])
    # h a node: the reads are at depth h under the load
    return x, y


def elasticity(nu, dim):
    lam, mu = nu / ((1 + nu) * (1 - 2 * nu)), 0.5 / (1 + nu)  # E = 1
    n = 3 if dim == 2 else 6
    d = np.zeros((n, n))
    d[:dim, :dim] = lam
    d[range(dim), range(dim)] += 2 * mu
    d[range(dim, n), range(dim, n)] = mu
    return d


def box_stiffness(sizes, nu):
    """Q1 stiffness of axis-aligned boxes (2D rectangles or 3D bricks), 2^dim Gauss points.
    sizes: (cells, dim). Corner order: lexicographic in (x, y[, z]), x fastest."""
    cells, dim = sizes.shape
    corners = np.array([[(c >> k) & 1 for k in range(dim)] for c in range(2 ** dim)])
    n = 2 ** dim
    d = elasticity(nu, dim)
    ke = np.zeros((cells, dim * n, dim * n))
    g = (1 + np.array([-1., 1.]) / np.sqrt(3.)) / 2  # on [0, 1]
    for point in np.array(np.meshgrid(*[g] * dim, indexing="ij")).reshape(dim, -1).T:
        # dN/dξ on the unit box
        values = np.where(corners == 1, point, 1 - point)  # (n, dim)
        dn = np.zeros((dim, n))
        for k in range(dim):
            others = np.prod(np.delete(values, k, axis=1), axis=1)
            dn[k] = np.where(corners[:, k] == 1, 1., -1.) * others
        grad = dn[None, :, :] / sizes[:, :, None]  # (cells, dim, n)
        rows = 3 if dim == 2 else 6
        b = np.zeros((cells, rows, dim * n))
        for k in range(dim):
            b[:, k, k::dim] = grad[:, k]
        pairs = [(0, 1)] if dim == 2 else [(1, 2), (0, 2), (0, 1)]
        for r, (p, q) in enumerate(pairs):
            b[:, dim + r, p::dim] = grad[:, q]
            b[:, dim + r, q::dim] = grad[:, p]
        volume = np.prod(sizes, axis=1)
        ke += np.einsum("eai,ab,ebj->eij", b, d, b) * (volume / n)[:, None, None]
    return ke, corners


def solve(axes, held, load, nu):
    """Assemble Q1 on the tensor grid `axes`, hold the DoFs `held`, solve for `load`."""
    dim = len(axes)
    shape = [len(a) for a in axes]
    nodes = int(np.prod(shape))
    index = np.arange(nodes).reshape(shape[::-1]).T  # index[i, j(, k)], x fastest
    starts = np.array(np.meshgrid(*[np.arange(s - 1) for s in shape], indexing="ij")).reshape(
        dim, -1).T
    sizes = np.stack([np.diff(axes[k])[starts[:, k]] for k in range(dim)], 1)
    ke, corners = box_stiffness(sizes, nu)
    cell_nodes = index[tuple((starts[:, None, :] + corners[None, :, :]).transpose(2, 0, 1))]
    dofs = (dim * cell_nodes[:, :, None] + np.arange(dim)[None, None, :]).reshape(len(starts), -1)
    k = sp.csr_matrix((ke.ravel(), (np.repeat(dofs, dim * 2 ** dim, 1).ravel(),
                                    np.tile(dofs, (1, dim * 2 ** dim)).ravel())),
                      shape=(dim * nodes,) * 2)
    free = np.setdiff1d(np.arange(dim * nodes), held)
    u = np.zeros(dim * nodes)
    u[free] = spl.spsolve(k[free][:, free].tocsc(), load[free])
    return u, index


def line_load(x, a):
    """Consistent nodal forces (per unit length along z) of the Hertzian pressure of 1 N/m
    total (half of it on x ≥ 0), p = (2/(πa))·√(1 − x²/a²), on the x nodes."""
    f = np.zeros(len(x))
    t, w = np.polynomial.legendre.leggauss(24)
    for e in range(len(x) - 1):
        lo, hi = x[e], min(x[e + 1], a)
        if hi <= lo:
            break
        s = lo + (hi - lo) * (t + 1) / 2
        p = 2 / (np.pi * a) * np.sqrt(np.clip(1 - (s / a) ** 2, 0, None)) * w * (hi - lo) / 2
        share = (s - x[e]) / (x[e + 1] - x[e])
        f[e] += np.sum(p * (1 - share))
        f[e + 1] += np.sum(p * share)
    return f


def plane_strain(x, y, a, nu, h):
    load = np.zeros(2 * len(x) * len(y))
    index = np.arange(len(x) * len(y)).reshape(len(y), len(x)).T
    load[2 * index[:, 0] + 1] = line_load(x, a)
    held = np.concatenate([2 * index[0, :],  # x = 0: symmetry
                           2 * index[-1, :], 2 * index[-1, :] + 1,
                           2 * index[:, -1], 2 * index[:, -1] + 1])
    u, index = solve([x, y], np.unique(held), load, nu)
    j = int(np.argmin(abs(y - h)))
    return u[2 * index[0, 0] + 1] - u[2 * index[0, j] + 1]


def face_nodes(ratio, h=1.0, planes=4):
    dz = ratio * h
    near = max(8 * h, planes * dz)
    z = np.arange(0., near + 0.5 * dz, dz)
    return np.concatenate([z[:-1], graded(z[-1], dz, z[-1] + 30 * h, 1.35)])


def quarter_space(x, y, z, a, nu, h):
    nx, ny, nz = len(x), len(y), len(z)
    index = np.arange(nx * ny * nz).reshape(nz, ny, nx).T
    load = np.zeros(3 * nx * ny * nz)
    weights = np.zeros(nz)  # consistent nodal weights of a uniform load along z
    weights[:-1] += 0.5 * np.diff(z)
    weights[1:] += 0.5 * np.diff(z)
    load[3 * index[:, 0, :] + 1] = np.outer(line_load(x, a), weights)
    held = np.concatenate([(3 * index[0, :, :]).ravel(),  # x = 0: symmetry
                           (3 * index[:, :, -1] + 2).ravel(),  # z far: the face continues
                           *[(3 * index[-1, :, :] + c).ravel() for c in range(3)],
                           *[(3 * index[:, -1, :] + c).ravel() for c in range(3)]])
    u, index = solve([x, y, z], np.unique(held), load, nu)
    j = int(np.argmin(abs(y - h)))
    return np.array([u[3 * index[0, 0, i] + 1] - u[3 * index[0, j, i] + 1]
                     for i in range(PLANES)])


def one_plane_load(ratio, near, a=HALF_WIDTH, nu=POISSON, h=1.0):
    """The interior model of interior_kernel and inclined_kernel, solved: a line load of 1 N/m on
    the node plane z = 0 alone (its nodal force w·Δz), uniform layers of Δz = ratio·h out to
    `near` each side, then graded 30·h further, z held at both far ends. Returns the section's
    nodes x, y, the displacements u, the node index [i, j, k] and the loaded plane's k."""
    x, y = section_nodes(a)
    dz = ratio * h
    uniform = np.arange(0., near + 0.5 * dz, dz)
    far = graded(uniform[-1], dz, uniform[-1] + 30 * h, 1.35)
    z = np.unique(np.round(np.concatenate([-far[::-1], -uniform[::-1], uniform, far]), 12))
    plane = int(np.argmin(abs(z)))
    nx, ny, nz = len(x), len(y), len(z)
    index = np.arange(nx * ny * nz).reshape(nz, ny, nx).T
    load = np.zeros(3 * nx * ny * nz)
    load[3 * index[:, 0, plane] + 1] = line_load(x, a) * dz
    held = np.concatenate([(3 * index[0, :, :]).ravel(),  # x = 0: symmetry
                           (3 * index[:, :, 0] + 2).ravel(), (3 * index[:, :, -1] + 2).ravel(),
                           *[(3 * index[-1, :, :] + c).ravel() for c in range(3)],
                           *[(3 * index[:, -1, :] + c).ravel() for c in range(3)]])
    u, index = solve([x, y, z], np.unique(held), load, nu)
    return x, y, u, index, plane


def interior_kernel(ratio, a=HALF_WIDTH, nu=POISSON, h=1.0, reach=5):
    """The layer's coupling between node planes away from the ends (docs/ltca.md §3 "End
    faces", session 50): a line load w on one node plane alone, as the exact path's dual mortar
    applies it (the plane's nodal force w·Δz, nothing on its neighbours), on uniform layers of Δz
    (z held at both far ends, the plane in the middle); the compression (surface minus depth h)
    at that plane and the next `reach` over the plane-strain compression of w. Their sum over
    all planes is 1 (a uniform load is plane strain); the fast model takes 1, 0, 0, ..."""
    dz = ratio * h
    x, y, u, index, plane = one_plane_load(ratio, max(8 * h, (reach + 3) * dz), a, nu, h)
    reference = plane_strain(x, y, a, nu, h)
    j = int(np.argmin(abs(y - h)))
    return np.array([(u[3 * index[0, 0, plane + m] + 1] - u[3 * index[0, j, plane + m] + 1])
                     / reference for m in range(reach + 1)])


def end_kernel(ratio, loaded, a=HALF_WIDTH, nu=POISSON, h=1.0, reach=5):
    """As interior_kernel, with the line load w on node plane `loaded` counted from the free end
    plane z = 0 (its force w·t, t the plane's tributary width; quarter_space's mesh and
    supports): the compression at planes 0 … reach over the plane-strain compression of w."""
    x, y = section_nodes(a)
    reference = plane_strain(x, y, a, nu, h)
    z = face_nodes(ratio, h, planes=max(4, reach + 3))
    nx, ny, nz = len(x), len(y), len(z)
    index = np.arange(nx * ny * nz).reshape(nz, ny, nx).T
    load = np.zeros(3 * nx * ny * nz)
    # The plane's force w·t: its tributary width t is Δz/2 on the end plane, Δz beyond.
    load[3 * index[:, 0, loaded] + 1] = line_load(x, a) * ratio * h * (0.5 if loaded == 0 else 1.)
    held = np.concatenate([(3 * index[0, :, :]).ravel(),  # x = 0: symmetry
                           (3 * index[:, :, -1] + 2).ravel(),  # z far: the face continues
                           *[(3 * index[-1, :, :] + c).ravel() for c in range(3)],
                           *[(3 * index[:, -1, :] + c).ravel() for c in range(3)]])
    u, index = solve([x, y, z], np.unique(held), load, nu)
    j = int(np.argmin(abs(y - h)))
    return np.array([(u[3 * index[0, 0, i] + 1] - u[3 * index[0, j, i] + 1]) / reference
                     for i in range(reach + 1)])


def inclined_kernel(ratio, shifts, a=HALF_WIDTH, nu=POISSON, depths=(1.0, 3.0), reach=None):
    """The interior kernel under an inclined (helical) contact line (docs/ltca.md §3 "End
    faces", session 53): one solve of interior_kernel's model, the compression of plane m read at
    x = m·s along the profile (s = tan β_b·Δz, in units of h), for each s of `shifts` and each
    read depth (the mesh's node nearest it). Yields (s, depth, row over planes 0 … reach, the sum
    over all planes, the sum's excess over plane strain in units of 2(1−ν²)/(πE) per N/m). The
    excess is what lumping a uniform inclined line on node planes adds to the continuous line
    (plane strain in its own frame). Δz/h 2 with reach 12: 111k DoFs, 7.3 GB, 7.5 min of one
    core."""
    reach = reach or int(np.ceil(24. / ratio))
    x, y, u, index, plane = one_plane_load(ratio, (reach + 3) * ratio, a, nu)
    unit = 2 * (1 - nu ** 2) / np.pi
    for depth in depths:
        j = int(np.argmin(abs(y - depth)))
        reference = plane_strain(x, y, a, nu, y[j])
        for s in shifts:
            row = np.array([np.interp(m * s, x, u[3 * index[:, 0, plane + m] + 1]
                                      - u[3 * index[:, j, plane + m] + 1]) / reference
                            for m in range(reach + 1)])
            total = row[0] + 2 * row[1:].sum()
            yield s, y[j], row, total, (total - 1) * reference / unit


def entries(ratio, a=HALF_WIDTH, nu=POISSON, refine=1):
    """Ê(Δz/h, i) for i = 0 … PLANES − 1."""
    x, y = section_nodes(a, refine=refine)
    reference = plane_strain(x, y, a, nu, 1.)
    layer = quarter_space(x, y, face_nodes(ratio), a, nu, 1.)
    return (layer - reference) / (2 * (1 - nu ** 2) / np.pi)


def source_table():
    """The table as stiffness/ltca_contact.cc holds it: {Δz/h: [Ê over i]}."""
    return dict(zip(RATIO, table_rows("end_face_e")))


def source_kernel():
    """The kernel as stiffness/ltca_contact.cc holds it: {Δz/h: [interior row, rows of the
    planes loaded 0 … KERNEL_END − 1]}."""
    rows = table_rows("kernel_rows")
    per = 1 + KERNEL_END
    assert len(rows) == per * len(KERNEL_RATIO), "kernel_rows and KERNEL_RATIO disagree"
    return {r: rows[per * k:per * (k + 1)] for k, r in enumerate(KERNEL_RATIO)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--spread", action="store_true",
                        help="the entries at Δz/h 1 and 4 for a/h 0.05, 0.1, 0.2, ν 0.25, 0.35 "
                        "and the x–y mesh refined")
    parser.add_argument("--ratio", type=float, nargs="*", help="only these Δz/h")
    parser.add_argument("--kernel", action="store_true",
                        help="the layer's coupling between interior node planes instead "
                        "(interior_kernel; about a minute a Δz/h)")
    parser.add_argument("--rows", action="store_true",
                        help="the kernel's whole rows: per Δz/h the interior row and the rows "
                        "of the planes loaded 0 … 4 from the free end (a few minutes a row on one "
                        "core; docs/ltca.md §3 \"End faces\")")
    parser.add_argument("--inclined", type=float, nargs="*", metavar="S",
                        help="the interior kernel read along an inclined contact line, plane m "
                        "at m·S along the profile (S/h; with --ratio, one Δz/h; docs/ltca.md §3 "
                        "\"End faces\")")
    args = parser.parse_args()
    if args.inclined is not None:
        for ratio in args.ratio or [2.]:
            for s, depth, row, total, excess in inclined_kernel(ratio, [0.] + args.inclined):
                print(f"dz/h {ratio} s/h {s} depth {depth:.3f}: planes 0..7 "
                      + ", ".join(f"{v:+.4f}" for v in row[:8])
                      + f"; sum {total:.4f}; excess {excess:.4f} units", flush=True)
        return
    if args.rows:
        for ratio in args.ratio or KERNEL_RATIO:
            rows = [interior_kernel(ratio, reach=KERNEL_REACH)]
            rows += [end_kernel(ratio, loaded, reach=loaded + KERNEL_REACH)
                     for loaded in range(KERNEL_END)]
            print(f"    {{{{  // dz/h {ratio}: interior, then loaded on plane 0 … {KERNEL_END - 1}",
                  flush=True)
            for row in rows:
                print("      {{" + ", ".join(f"{v:.4f}" for v in row) + "}},")
            print("    }},", flush=True)
        return
    if args.kernel:
        for ratio in args.ratio or [1., 2., 4., 8.]:
            c = interior_kernel(ratio)
            print(f"dz/h {ratio}: planes 0..{len(c) - 1}: " + ", ".join(f"{v:+.4f}" for v in c)
                  + f"; sum over all {c[0] + 2 * c[1:].sum():.4f}", flush=True)
            for loaded in range(3):
                e = end_kernel(ratio, loaded)
                print(f"  loaded on end plane {loaded}: planes 0..{len(e) - 1}: "
                      + ", ".join(f"{v:+.4f}" for v in e), flush=True)
        return
    if args.check:
        table = source_table()
        worst = 0.
        for ratio in [1., 4.]:
            value = entries(ratio)
            stored = table[ratio]
            print(f"dz/h {ratio}: computed {np.round(value, 4)}, table {stored}")
            worst = max(worst, np.max(abs(value - np.array(stored))))
        # The kernel's row of a load on the end plane (about 30 s; the interior row's two-sided
        # face takes 140 s).
        value = end_kernel(4., 0, reach=KERNEL_REACH)
        stored = source_kernel()[4.][1]
        print(f"dz/h 4 kernel, end plane loaded: computed {np.round(value, 4)}, table {stored}")
        worst = max(worst, np.max(abs(value - np.array(stored))))
        sys.exit(0 if worst < 5e-4 else 1)
    if args.spread:
        for ratio in [1., 4.]:
            print(f"dz/h {ratio}: a/h 0.1 {np.round(entries(ratio), 4)}", flush=True)
            for a in [0.05, 0.2]:
                print(f"  a/h {a}: {np.round(entries(ratio, a=a), 4)}", flush=True)
            for nu in [0.25, 0.35]:
                print(f"  nu {nu}: {np.round(entries(ratio, nu=nu), 4)}", flush=True)
            print(f"  x-y refined: {np.round(entries(ratio, refine=2), 4)}", flush=True)
        return
    for ratio in args.ratio or RATIO:
        row = ", ".join(f"{v:.4f}" for v in entries(ratio))
        print(f"    {{{{{row}}}}},  // dz/h {ratio}", flush=True)


if __name__ == "__main__":
    main()
