#!/usr/bin/python3
"""Side-by-side figures of `make bench`: beamrotor against SciPy on the planar model, and the
gathering of every other figure of out/bench into summary.json.

Reads DIR/planar_static_N.json, DIR/scipy_static_N.json (N = 1e3 .. 1e6),
DIR/planar_modal_10000.json and DIR/scipy_modal_10000.json, DIR/planar_modal_1000000.json
(modes against statics in one run); prints the table and ratios,
and adds, when their files are there: rotor_800.json, frames_ccx*.json (3D frames against
CalculiX), frame3d_combinations_{1,20,200}.json, frame3d_100000.json,
output.json (shipped decks end to end) and study.json (points per second);
checks that both give the same answers, fits the log-log slope of beamrotor's static cost
against N, and writes DIR/summary.json and the chart DIR/planar_static_scaling.{svg,png}.
Usage: compare.py DIR
"""
import glob
import json
import math
import os
import subprocess
import sys


def load(path):
    with open(path) as fh:
        return json.load(fh)


def cold(directory, name):
    """Median wall seconds of the fresh processes in DIR/cold_NAME.json (cold.py), or None."""
    path = os.path.join(directory, f"cold_{name}.json")
    return load(path)["wall_s"] if os.path.exists(path) else None


def ratio(a, b):
    return b / a if a and b else None


def text(x, width, digits):
    return f"{x:>{width}.{digits}f}" if x is not None else f"{'-':>{width}}"


def slope(xs, ys):
    """Least-squares slope of log y against log x."""
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def chart(directory, rows):
    data = os.path.join(directory, "planar_static_scaling.dat")
    with open(data, "w") as fh:
        fh.write("# elements beamrotor_s scipy_s\n")
        for r in rows:
            fh.write(f"{r['elements']} {r['beamrotor_s']} {r['scipy_s']}\n")
    n0, t0 = rows[0]["elements"], rows[0]["beamrotor_s"]
    for terminal, ext in (("svg size 800,560", "svg"), ("pngcairo size 800,560", "png")):
        script = f"""
set terminal {terminal}
set output '{os.path.join(directory, 'planar_static_scaling.' + ext)}'
set logscale xy
set grid
set key top left
set xlabel 'elements (planar continuous beam, 3 dofs per node)'
set ylabel 'model + static solve, s (median)'
set title 'Static cost against size: beamrotor and SciPy (spsolve)'
plot '{data}' using 1:2 with linespoints lw 2 title 'beamrotor', \\
     '{data}' using 1:3 with linespoints lw 2 title 'SciPy', \\
     {t0}*(x/{n0}) with lines dt 2 lc rgb 'gray' title 'linear cost'
"""
        subprocess.run(["gnuplot"], input=script, text=True, check=True)


def frames(directory):
    """3D frames: against CalculiX (frames_ccx*.json), load combinations and the 10^5-member
    frame3d bench."""
    out = {}
    for path in sorted(glob.glob(os.path.join(directory, "frames_ccx*.json"))):
        for frame, r in load(path)["frames"].items():
            out.setdefault("frames_ccx", {})[frame] = r
            line = (f"{frame}, {r['members']} members: beamrotor whole run "
                    f"{r['beamrotor_whole_s']:.2f} s (solve {r['beamrotor_solve_s']:.3f} s, "
                    f"peak {r['beamrotor_peak_mb']:.0f} MB)")
            if "ccx_whole_s" in r:
                line += (f", ccx {r['ccx_whole_s']:.2f} s (peak {r['ccx_peak_mb']:.0f} MB): "
                         f"{r['ccx_whole_s'] / r['beamrotor_whole_s']:.1f}x; joint displacements "
                         f"differ by {r['displacement_difference']:.1e}")
            print(line)
    combinations = {}
    for c in (1, 20, 200):
        path = os.path.join(directory, f"frame3d_combinations_{c}.json")
        if os.path.exists(path):
            f = load(path)["frame"]
            combinations[c] = {k: f[k] for k in ("members", "cases_s", "cases_to_static",
                                                  "write_s", "whole_s")}
            print(f"{c} combinations on {f['members']:.0f} members: cases solved in "
                  f"{f['cases_s']:.3f} s ({f['cases_to_static']:.2f} x one static solve; "
                  f"target 3), whole run {f['whole_s']:.1f} s")
    if combinations:
        out["frame3d_combinations"] = combinations
    if 1 in combinations and 200 in combinations:
        # Issue 41 item 6 and issue 45: 200 combinations cost <= 3x one, whole run against
        # whole run (read, solve, write) on the same frame.
        ratio = combinations[200]["whole_s"] / combinations[1]["whole_s"]
        out["frame3d_combinations"]["whole_200_over_1"] = ratio
        print(f"200 combinations over 1, whole runs: {ratio:.2f} (target 3)")
    path = os.path.join(directory, "frame3d_100000.json")
    if os.path.exists(path):
        g = load(path)
        out["frame3d_100000"] = {"members": g["frame"]["members"], "free_dofs": g["free_dofs"],
                                 "solver": g["solver"], "factor_entries": g["factor_entries"],
                                 "static_s": g["static"]["total_s"],
                                 "factor_s": g["static"]["factor_s"],
                                 "whole_s": g["frame"]["whole_s"],
                                 "peak_rss_mb": g["peak_rss_mb"]}
        print(f"frame3d, {g['frame']['members']:.0f} members: static {g['static']['total_s']:.2f}"
              f" s (target 4 s; {g['solver']}), whole run {g['frame']['whole_s']:.1f} s")
    return out


def decks_and_studies(directory):
    """Shipped decks end to end (output.json) and studies' points per second (study.json)."""
    out = {}
    path = os.path.join(directory, "output.json")
    if os.path.exists(path):
        o = load(path)
        decks = o["decks"]
        out["decks"] = {name: {k: d.get(k) for k in ("whole_s", "whole_no_charts_s", "solve_s",
                                                      "write_s")}
                        for name, d in decks.items()}
        if decks and all("whole_s" in d for d in decks.values()):
            slowest = max(decks, key=lambda n: decks[n]["whole_s"])
            print(f"shipped decks end to end: slowest {slowest} {decks[slowest]['whole_s']:.2f} s"
                  f" ({decks[slowest]['whole_no_charts_s']:.2f} s without charts; target 0.5 s)")
        rotor = {}
        for deck, analysis, key in (("compressor_rotor", "response", "unbalance_sweep_s"),
                                    ("compressor_rotor", "campbell", "campbell_s"),
                                    ("jeffcott_internal_damping", "campbell",
                                     "stability_onset_s")):
            seconds = decks.get(deck, {}).get("analyses_s", {}).get(analysis)
            if seconds is not None:
                rotor[key] = {"deck": deck, "analysis": analysis, "solve_s": seconds}
                print(f"{deck} '{analysis}': {seconds:.3f} s")
        if rotor:
            out["rotor_decks"] = rotor
    path = os.path.join(directory, "study.json")
    if os.path.exists(path):
        runs = load(path)["runs"]
        out["study_points_per_s"] = {name: r["points_per_s_median"] for name, r in runs.items()}
        print("study points/s: " + ", ".join(f"{name} {r['points_per_s_median']:.0f}"
                                              for name, r in runs.items()))
    return out


def main():
    directory = sys.argv[1] if len(sys.argv) > 1 else "out/bench"
    rows = []
    for n in (1000, 10000, 100000, 1000000):
        ours = os.path.join(directory, f"planar_static_{n}.json")
        theirs = os.path.join(directory, f"scipy_static_{n}.json")
        if not (os.path.exists(ours) and os.path.exists(theirs)):
            continue
        a, b = load(ours), load(theirs)
        total = a["build_s"] + a["static"]["total_s"]
        rows.append({"elements": a["elements"], "beamrotor_s": total,
                     "beamrotor_static_s": a["static"]["total_s"],
                     "scipy_s": b["static"]["total_s"],
                     "ratio": b["static"]["total_s"] / total,
                     "beamrotor_cold_s": cold(directory, f"planar_static_{n}"),
                     "scipy_cold_s": cold(directory, f"scipy_static_{n}"),
                     "rel_error_static": a["rel_error_static"],
                     "w_agreement": abs(a["midspan_w"] / b["midspan_w"] - 1)})
    for r in rows:
        r["cold_ratio"] = ratio(r["beamrotor_cold_s"], r["scipy_cold_s"])
    print("planar static: warm (model + static solve, medians in one process) and cold (wall "
          "time of a fresh process, medians)")
    print(f"  {'elements':>9} {'beamrotor s':>12} {'SciPy s':>9} {'ratio':>7}"
          f" {'cold beamrotor s':>17} {'cold SciPy s':>13} {'ratio':>7}"
          f" {'error vs exact':>15} {'vs SciPy':>9}")
    for r in rows:
        print(f"  {r['elements']:>9} {r['beamrotor_s']:>12.4f} {r['scipy_s']:>9.3f}"
              f" {r['ratio']:>6.1f}x {text(r['beamrotor_cold_s'], 17, 3)}"
              f" {text(r['scipy_cold_s'], 13, 3)} {text(r['cold_ratio'], 6, 1)}x"
              f" {r['rel_error_static']:>15.1e} {r['w_agreement']:>9.1e}")
    summary = {"planar_static": rows}
    if len(rows) >= 2:
        s = slope([r["elements"] for r in rows], [r["beamrotor_s"] for r in rows])
        summary["planar_static_slope"] = s
        print(f"  log-log slope of beamrotor's cost, {rows[0]['elements']} to "
              f"{rows[-1]['elements']} elements: {s:.2f} (linear: 1)")
        chart(directory, rows)
    modal_ours = os.path.join(directory, "planar_modal_10000.json")
    modal_theirs = os.path.join(directory, "scipy_modal_10000.json")
    if os.path.exists(modal_ours) and os.path.exists(modal_theirs):
        a, b = load(modal_ours), load(modal_theirs)
        fa, fb = a["modal"]["frequencies_hz"], b["modal"]["frequencies_hz"]
        agreement = max(abs(x / y - 1) for x, y in zip(fa, fb))
        speedup = ratio(a["modal"]["total_s"], b["modal"]["total_s"])
        summary["planar_modal"] = {"elements": a["elements"], "modes": len(fa),
                                   "beamrotor_s": a["modal"]["total_s"],
                                   "scipy_s": b["modal"]["total_s"], "ratio": speedup,
                                   "frequency_agreement": agreement,
                                   "beamrotor_cold_s": cold(directory, "planar_modal_10000"),
                                   "scipy_cold_s": cold(directory, "scipy_modal_10000")}
        print(f"planar modal, {a['elements']} elements, {len(fa)} modes: beamrotor "
              f"{a['modal']['total_s']:.3f} s, SciPy eigsh {b['modal']['total_s']:.2f} s, "
              f"{speedup:.1f}x; frequencies agree to {agreement:.1e}")
        m = summary["planar_modal"]
        if m["beamrotor_cold_s"] and m["scipy_cold_s"]:
            print(f"  cold (fresh process: model, statics and modes): beamrotor "
                  f"{m['beamrotor_cold_s']:.3f} s, SciPy {m['scipy_cold_s']:.2f} s, "
                  f"{m['scipy_cold_s'] / m['beamrotor_cold_s']:.1f}x")
    large = os.path.join(directory, "planar_modal_1000000.json")
    if os.path.exists(large):
        g = load(large)
        modal_s, static_s = g["modal"]["total_s"], g["static"]["total_s"]
        summary["planar_modal_large"] = {"elements": g["elements"], "modal_s": modal_s,
                                         "static_s": static_s, "ratio": modal_s / static_s}
        print(f"planar modal, {g['elements']} elements, {len(g['modal']['frequencies_hz'])} "
              f"modes: {modal_s:.2f} s, {modal_s / static_s:.1f}x its statics "
              f"({static_s:.2f} s; target 10x)")
    grid = os.path.join(directory, "grid3d_1000000.json")
    if os.path.exists(grid):
        g = load(grid)
        summary["grid3d"] = {k: g[k] for k in ("free_dofs", "factor_entries", "solver",
                                               "peak_rss_mb", "symmetry_error")}
        summary["grid3d"].update(static_s=g["static"]["total_s"],
                                 modal_s=g.get("modal", {}).get("total_s"))
        print(f"grid3d, {g['free_dofs']} free dofs: static {g['static']['total_s']:.2f} s "
              f"(factor {g['static']['factor_s']:.2f} s, {g['solver']}, "
              f"{g['factor_entries']:.3g} factor entries), 10 modes "
              f"{g.get('modal', {}).get('total_s', float('nan')):.1f} s, "
              f"peak {g['peak_rss_mb']:.0f} MB")
    rotor = os.path.join(directory, "rotor_200.json")
    if os.path.exists(rotor):
        r = load(rotor)
        summary["rotor"] = {"elements": r["elements"], "campbell_s": r["modal"]["total_s"],
                            "cold_s": cold(directory, "rotor_200"),
                            "rel_error_planar_twin": r["modal"]["rel_error_planar_twin"]}
        print(f"rotor, {r['elements']} elements: Campbell of {r['campbell']['speeds']:.0f} "
              f"speeds x {r['campbell']['modes']:.0f} modes in {r['modal']['total_s']:.2f} s "
              f"(target 0.3 s); at rest vs planar model {r['modal']['rel_error_planar_twin']:.1e}")
        if summary["rotor"]["cold_s"]:
            print(f"  cold (fresh process: model, statics and Campbell): "
                  f"{summary['rotor']['cold_s']:.2f} s")
    rotor800 = os.path.join(directory, "rotor_800.json")
    if os.path.exists(rotor800):
        r = load(rotor800)
        summary["rotor_800"] = {"elements": r["elements"], "campbell_s": r["modal"]["total_s"],
                                "rel_error_planar_twin": r["modal"]["rel_error_planar_twin"]}
        print(f"rotor, {r['elements']} elements: Campbell in {r['modal']['total_s']:.2f} s "
              f"(target 1 s)")
    summary.update(frames(directory))
    summary.update(decks_and_studies(directory))
    with open(os.path.join(directory, "summary.json"), "w") as fh:
        json.dump(summary, fh, indent=2)
    print(f"figures: {directory}/summary.json, {directory}/planar_static_scaling.svg")


if __name__ == "__main__":
    main()
