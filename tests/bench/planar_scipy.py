#!/usr/bin/python3
"""The bench's `planar` standard model built and solved with SciPy, for side-by-side figures.

Same model as problems/bench/StandardModels.cpp: a continuous planar Euler-Bernoulli beam
(E = 210e9 Pa, rho = 7850 kg/m^3, 20 mm square section), spans of 0.6 m with 10 elements
each, ux = uy = 0 at every span end, 1000 N/m downwards as consistent nodal loads; dofs
(ux, uy, rz) per node. Assembly is vectorised COO, the way a SciPy user would write it; the
static solve is scipy.sparse.linalg.spsolve, the modes eigsh(K, k, M, sigma=0).

Usage: planar_scipy.py --elements N [--modes K] [--repeat R] --json FILE
"""
import argparse
import json
import statistics
import time

import numpy as np
import scipy
import scipy.sparse as sp
import scipy.sparse.linalg as spla

E, RHO, SIDE, SPAN, PER_SPAN, Q = 210e9, 7850.0, 0.02, 0.6, 10, -1000.0


def element_matrices(h):
    """6x6 stiffness and consistent mass of one element on (ux1, uy1, rz1, ux2, uy2, rz2)."""
    A, I = SIDE * SIDE, SIDE**4 / 12
    EA, EI, m = E * A, E * I, RHO * A
    k = np.zeros((6, 6))
    k[np.ix_([0, 3], [0, 3])] = EA / h * np.array([[1, -1], [-1, 1]])
    b = [1, 2, 4, 5]
    k[np.ix_(b, b)] = EI / h**3 * np.array(
        [[12, 6 * h, -12, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
         [-12, -6 * h, 12, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]])
    mm = np.zeros((6, 6))
    mm[np.ix_([0, 3], [0, 3])] = m * h / 6 * np.array([[2, 1], [1, 2]])
    mm[np.ix_(b, b)] = m * h / 420 * np.array(
        [[156, 22 * h, 54, -13 * h], [22 * h, 4 * h * h, 13 * h, -3 * h * h],
         [54, 13 * h, 156, -22 * h], [-13 * h, -3 * h * h, -22 * h, 4 * h * h]])
    f = np.array([0, Q * h / 2, Q * h * h / 12, 0, Q * h / 2, -Q * h * h / 12])
    return k, mm, f


def build(elements):
    spans = max(1, -(-elements // PER_SPAN))
    n = spans * PER_SPAN
    h = SPAN / PER_SPAN
    ke, me, fe = element_matrices(h)
    dofs = (3 * np.arange(n)[:, None] + np.arange(6)[None, :])  # element dof numbers
    rows = np.repeat(dofs, 6, axis=1).ravel()
    cols = np.tile(dofs, (1, 6)).ravel()
    size = 3 * (n + 1)
    K = sp.coo_matrix((np.tile(ke.ravel(), n), (rows, cols)), shape=(size, size)).tocsc()
    M = sp.coo_matrix((np.tile(me.ravel(), n), (rows, cols)), shape=(size, size)).tocsc()
    f = np.bincount(dofs.ravel(), weights=np.tile(fe, n), minlength=size)
    support_nodes = np.arange(0, n + 1, PER_SPAN)
    fixed = np.concatenate([3 * support_nodes, 3 * support_nodes + 1])
    free = np.setdiff1d(np.arange(size), fixed)
    midspan = (spans // 2) * PER_SPAN + PER_SPAN // 2
    return K[free][:, free], M[free][:, free], f[free], free, midspan


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--elements", type=int, required=True)
    parser.add_argument("--modes", type=int, default=0)
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--json", required=True)
    args = parser.parse_args()

    static_s, modal_s = [], []
    for _ in range(max(1, args.repeat)):
        start = time.perf_counter()
        K, M, f, free, midspan = build(args.elements)
        u = spla.spsolve(K, f)
        static_s.append(time.perf_counter() - start)
        w = u[np.searchsorted(free, 3 * midspan + 1)]
        if args.modes > 0:
            start = time.perf_counter()
            values = spla.eigsh(K, k=args.modes, M=M, sigma=0, which="LM",
                                return_eigenvectors=False)
            modal_s.append(time.perf_counter() - start)
            frequencies = sorted(np.sqrt(values) / (2 * np.pi))
    EI = E * SIDE**4 / 12
    out = {
        "scipy_version": scipy.__version__,
        "elements": -(-args.elements // PER_SPAN) * PER_SPAN,
        "dofs": int(K.shape[0]),
        "static": {"total_s": statistics.median(static_s)},
        "midspan_w": float(w),
        "rel_error_static": abs(w / (Q * SPAN**4 / (384 * EI)) - 1),
    }
    if modal_s:
        out["modal"] = {"total_s": statistics.median(modal_s),
                        "frequencies_hz": [float(x) for x in frequencies]}
    with open(args.json, "w") as fh:
        json.dump(out, fh, indent=2)
    print(f"scipy {scipy.__version__} planar {out['elements']} elements: static "
          f"{out['static']['total_s']:.3f} s" +
          (f", {args.modes} modes {out['modal']['total_s']:.3f} s" if modal_s else ""))


if __name__ == "__main__":
    main()
