#!/usr/bin/env python3
"""The table Ĝ(s, α) of stiffness::corner_layer_excess (stiffness/ltca_contact.cc), computed.

    python3 tools/wedge_layer.py            print the table (about 3 minutes on one core)
    python3 tools/wedge_layer.py --check    recompute two entries and compare them with the table
                                            in stiffness/ltca_contact.cc (ctest
                                            verification.wedge_layer, about 25 s); exit 1 when off

The fast contact model (docs/ltca.md §3) joins an FE body, read at a depth h under a load on a
flank, to an analytic layer 0 ≤ z ≤ h that assumes a half-plane. Near a tooth's sharp tip corner
the body is a wedge of interior angle π/2 + α (α the flank's pressure angle at the tip), which
is softer: its layer compresses more. This script measures how much, for a line load at distance
d from the apex, by two plane-strain FE models with the same polar mesh — the wedge θ ∈ [0, π/2 +
α] and the half-plane θ ∈ [0, π] — loaded by the same narrow uniform pressure (width 0.1·d, 1 N/m)
on the face θ = 0, the arc r = R = 1000·h held: the excess is the difference of the two
(surface under the load − the point at depth h under it), in units of (f − 1)·2(1−ν²)/(πE) with
f the Flamant wedge factor (stiffness::tip_edge_wedge_factor), as a function of s = d/h.

Mesh: bilinear quadrilaterals on a polar grid, 260 radii geometric from 1e-5·h to R plus the
load's edges, 1° in θ. Halving both (400 radii, 0.5°) moved the entry at α 17.5°, s 0.05 from
1.3437 to 1.3444 (measured 2026-12-05). ν 0.3; at ν 0.25 and 0.35 the entry at α 25° is 4 % lower
and higher at s 0.05, 12 % at s 0.2 (the table is for steel). numpy and scipy only.
"""
import argparse
import sys

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl

from cc_table import table_rows

S = [0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 0.8, 1.6]  # d/h
ALPHA = [10., 17.5, 25., 32., 40.]  # degrees, the tip's pressure angle
POISSON = 0.3


def wedge_factor(alpha):
    """Flamant's wedge over the half-plane (stiffness::tip_edge_wedge_factor)."""
    half = 0.5 * (0.5 * np.pi + alpha)
    off = 0.5 * np.pi - half
    return 0.5 * np.pi * (np.cos(off) ** 2 / (half + 0.5 * np.sin(2 * half)) +
                          np.sin(off) ** 2 / (half - 0.5 * np.sin(2 * half)))


def layer_compression(opening, d, h=1.0, radius=1000., inner=1e-5, radii=260,
                      step=np.radians(1.0), nu=POISSON):
    """Surface under the load minus the point at depth h under it (normal displacement, E = 1,
    load 1 N/m over [0.95·d, 1.05·d]) of the body θ ∈ [0, opening]."""
    e = 0.05 * d
    r = np.unique(np.concatenate([np.geomspace(inner, radius, radii),
                                  np.linspace(d - e, d + e, 9)]))
    t = np.linspace(0., opening, max(8, int(round(opening / step))) + 1)
    nr, nt = len(r), len(t)
    x = (r[:, None] * np.cos(t)[None, :]).ravel()
    y = (r[:, None] * np.sin(t)[None, :]).ravel()
    node = lambda i, j: i * nt + j
    elastic = 1. / ((1 + nu) * (1 - 2 * nu)) * np.array(
        [[1 - nu, nu, 0], [nu, 1 - nu, 0], [0, 0, (1 - 2 * nu) / 2]])
    i, j = (a.ravel() for a in np.meshgrid(np.arange(nr - 1), np.arange(nt - 1), indexing="ij"))
    cells = np.stack([node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)], 1)
    xe, ye = x[cells], y[cells]
    ke = np.zeros((len(cells), 8, 8))
    gauss = np.array([-1., 1.]) / np.sqrt(3.)
    for a in gauss:
        for b in gauss:
            dn = 0.25 * np.array([[-(1 - b), 1 - b, 1 + b, -(1 + b)],
                                  [-(1 - a), -(1 + a), 1 + a, 1 - a]])
            j11, j12, j21, j22 = xe @ dn[0], ye @ dn[0], xe @ dn[1], ye @ dn[1]
            det = j11 * j22 - j12 * j21
            dnx = (j22[:, None] * dn[0] - j12[:, None] * dn[1]) / det[:, None]
            dny = (-j21[:, None] * dn[0] + j11[:, None] * dn[1]) / det[:, None]
            bm = np.zeros((len(cells), 3, 8))
            bm[:, 0, 0::2], bm[:, 1, 1::2] = dnx, dny
            bm[:, 2, 0::2], bm[:, 2, 1::2] = dny, dnx
            ke += np.einsum("eai,ab,ebj->eij", bm, elastic, bm) * det[:, None, None]
    dofs = np.stack([2 * cells, 2 * cells + 1], 2).reshape(len(cells), 8)
    stiffness = sp.csr_matrix((ke.ravel(), (np.repeat(dofs, 8, 1).ravel(),
                                            np.tile(dofs, (1, 8)).ravel())),
                              shape=(2 * nr * nt,) * 2)
    load = np.zeros(2 * nr * nt)
    for k in range(nr - 1):  # the pressure on θ = 0, into the body (+y), lumped per cell
        lo, hi = max(r[k], d - e), min(r[k + 1], d + e)
        if hi > lo:
            share = (0.5 * (lo + hi) - r[k]) / (r[k + 1] - r[k])
            load[2 * node(k, 0) + 1] += (hi - lo) / (2 * e) * (1 - share)
            load[2 * node(k + 1, 0) + 1] += (hi - lo) / (2 * e) * share
    held = np.array([[2 * node(nr - 1, m), 2 * node(nr - 1, m) + 1] for m in range(nt)]).ravel()
    free = np.setdiff1d(np.arange(2 * nr * nt), held)
    u = np.zeros(2 * nr * nt)
    u[free] = spl.spsolve(stiffness[free][:, free].tocsc(), load[free])

    def normal(px, py):
        # bilinear in (r, θ) on the cell holding the point
        rr, tt = np.hypot(px, py), np.arctan2(py, px)
        k = np.searchsorted(r, rr) - 1
        m = min(max(np.searchsorted(t, tt) - 1, 0), nt - 2)
        p = (rr - r[k]) / (r[k + 1] - r[k])
        q = (tt - t[m]) / (t[m + 1] - t[m])
        corners = [node(k, m), node(k + 1, m), node(k + 1, m + 1), node(k, m + 1)]
        weights = [(1 - p) * (1 - q), p * (1 - q), p * q, (1 - p) * q]
        return sum(w * u[2 * c + 1] for w, c in zip(weights, corners))

    return normal(d, 0.) - normal(d, h)


def entry(alpha_degrees, s):
    """Ĝ(s, α): the wedge's layer excess over (f − 1)·2(1−ν²)/(πE)."""
    alpha = np.radians(alpha_degrees)
    excess = layer_compression(0.5 * np.pi + alpha, s) - layer_compression(np.pi, s)
    return excess / (2 * (1 - POISSON ** 2) / np.pi) / (wedge_factor(alpha) - 1.)


def source_table():
    """The table as stiffness/ltca_contact.cc holds it: {α: [Ĝ over S]}."""
    return dict(zip(ALPHA, table_rows("corner_g")))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    if args.check:
        table = source_table()
        worst = 0.
        for alpha, s in [(17.5, 0.05), (32., 0.2)]:
            value = entry(alpha, s)
            stored = table[alpha][S.index(s)]
            print(f"alpha {alpha} deg, s {s}: computed {value:.4f}, table {stored:.4f}")
            worst = max(worst, abs(value - stored))
        # 5e-4: the table's printed digits (1e-4) and the solver's round-off across machines.
        sys.exit(0 if worst < 5e-4 else 1)
    for alpha in ALPHA:
        row = ", ".join(f"{entry(alpha, s):.4f}" for s in S)
        print(f"    {{{{{row}}}}},  // alpha {alpha} deg, f {wedge_factor(np.radians(alpha)):.4f}",
              flush=True)


if __name__ == "__main__":
    main()
