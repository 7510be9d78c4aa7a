#!/usr/bin/python3
"""A building frame with load cases and many combinations as a deck, to time and compare
`beamrotor solve` on it (what writing combinations costs; never part of make test).

The building of `beamrotor bench --kind frame3d` (n x n bays of 4 m x 5 m, n storeys of 3.5 m,
tube columns, rectangular beams, 5 elements per member, clamped bases) with three load cases
(dead: self-weight and a uniform load on every beam; wind along x and along z: 10 kN at
every top joint) and C combinations whose factors step through dead 1..1.35 and the winds
-1.5..1.5, as the bench's.

Usage: combinations_deck.py --bays N --combinations C > deck.yaml
"""
import argparse
import sys


def joint(i, j, k, prefix="n"):
    return f"{prefix}{i}_{j}_{k}"


def factors(k):
    return 1 + 0.35 * (k % 8) / 7, 1.5 * ((k % 7) - 3) / 3, 1.5 * ((k % 5) - 2) / 2


def deck(n, combinations):
    out = [f"title: combinations bench, {n} bays each way, {n} storeys",
           "model: {dimension: 3d}",
           "materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]",
           "sections:",
           "  - {name: column, shape: tube, D: 0.3, t: 0.012}",
           "  - {name: beam, shape: rectangle, b: 0.2, h: 0.4}",
           "nodes:"]
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                out.append(f"  - {{name: {joint(i, j, k)}, at: [{4 * i}, {3.5 * k}, {5 * j}]}}")
    out.append("members:")
    beams = []
    for k in range(n):
        for j in range(n + 1):
            for i in range(n + 1):
                out.append(f"  - {{name: {joint(i, j, k, 'c')}, from: {joint(i, j, k)}, "
                           f"to: {joint(i, j, k + 1)}, section: column, elements: 5}}")
    for k in range(1, n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                for name, end in ((joint(i, j, k, "x"), (i + 1, j, k)),
                                  (joint(i, j, k, "z"), (i, j + 1, k))):
                    if end[0] > n or end[1] > n:
                        continue
                    beams.append(name)
                    out.append(f"  - {{name: {name}, from: {joint(i, j, k)}, to: {joint(*end)}, "
                               "section: beam, elements: 5}")
    out.append("supports:")
    for j in range(n + 1):
        for i in range(n + 1):
            out.append(f"  - {{name: {joint(i, j, 0, 's')}, at: {joint(i, j, 0)}, fix: clamped}}")
    top = [joint(i, j, n) for j in range(n + 1) for i in range(n + 1)]
    out.append("loads: []")
    out.append("load_cases:")
    dead = ["{type: self-weight, g: 9.81}"] + [
        f"{{type: distributed, member: {b}, qy: -5000}}" for b in beams]
    out.append("  - {name: dead, loads: [" + ", ".join(dead) + "]}")
    for name, component in (("wind_x", "fx"), ("wind_z", "fz")):
        loads = ", ".join(f"{{type: point, at: {t}, {component}: 10000}}" for t in top)
        out.append(f"  - {{name: {name}, loads: [{loads}]}}")
    out.append("combinations:")
    for k in range(combinations):
        d, x, z = factors(k)
        out.append(f"  - {{name: C{k + 1}, factors: {{dead: {d!r}, wind_x: {x!r}, wind_z: {z!r}}}}}")
    out.append("analyses: [{type: static}]")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bays", type=int, required=True)
    parser.add_argument("--combinations", type=int, required=True)
    args = parser.parse_args()
    sys.stdout.write(deck(args.bays, args.combinations))


if __name__ == "__main__":
    main()
