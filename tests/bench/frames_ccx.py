#!/usr/bin/python3
"""3D frames against CalculiX, whole runs as a user types them (part of make bench; never part
of make test).

Each frame of frame_grid.py is written as a beamrotor deck and as a ccx input by the writers
of `make verify-frames` (tests/verify/frames: Timoshenko elements with the properties of the
rectangle ccx's B31 beam expands into, B31 beams with RECT sections), the same nodes and 5
elements per member in both. Then, in turn, --repeat times each: `beamrotor solve DECK` and
`ccx -i JOB` (OMP_NUM_THREADS=2: ccx's matrix set-up, stresses and SPOOLES factorisation on
both cores, as beamrotor's passes), each under GNU time for its peak resident memory. Per
frame: medians of the whole runs' wall times and their ratio, beamrotor's solve alone (its
summary's cost line) and per member, both peaks, and the answers' agreement: the largest
difference of a joint displacement component over the largest |ccx| displacement, beside
ccx's own mesh change from 5 to 10 elements per member on the small frames (its mesh-convergence
tolerance) and against Richardson's extrapolation of those two meshes (B31 converges at second
order), and the balance of beamrotor's reactions against the loads. A frame marked
beamrotor-only (10^5 members: ccx would need about 25 GB at its measured 52 kB an element) runs
beamrotor alone. Writes JSON (--json) and prints a table.

Usage: frames_ccx.py --exe build/beamrotor --json out/bench/frames_ccx.json [--large]
"""
import argparse
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "verify", "frames"))
sys.path.insert(0, HERE)
import beamrotor_deck  # noqa: E402
from bench_io import solve_costs, write_json  # noqa: E402
import ccx_input  # noqa: E402
import ccx_results  # noqa: E402
import frame_grid  # noqa: E402
import frame_model  # noqa: E402

ELEMENTS = 5          # per member, in both programs
FINE = 10             # ccx's second mesh, for its own discretisation change
# name: (model maker, ccx runs it, ccx's mesh change measured, large)
CASES = {
    "building_6x6x8": (lambda: frame_grid.building(6, 6, 8), True, True, False),
    "tower_64": (lambda: frame_grid.tower(64), True, True, False),
    "building_13x13x17": (lambda: frame_grid.building(13, 13, 17), True, False, False),
    "building_16x16x24": (lambda: frame_grid.building(16, 16, 24), True, False, True),
    "building_30x30x36": (lambda: frame_grid.building(30, 30, 36), False, False, True),
}


def timed(command, cwd=None, env=None):
    """(wall s, peak resident MB, stdout) of one run under GNU time."""
    start = time.perf_counter()
    done = subprocess.run(["/usr/bin/time", "-f", "peak %M"] + command, cwd=cwd, env=env,
                          capture_output=True, text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0 or "*ERROR" in done.stdout:
        sys.exit("failed: " + " ".join(command) + "\n" + done.stdout[-2000:] + done.stderr)
    peak = re.findall(r"peak ([0-9]+)", done.stderr)
    return wall, float(peak[-1]) / 1024, done.stdout


def run_ccx(directory, stem):
    env = dict(os.environ, OMP_NUM_THREADS="2")
    return timed(["ccx", "-i", stem], cwd=directory, env=env)


def ccx_joints(model, mesh, stem):
    """{joint: (ux, uy, uz)} from ccx's .dat file."""
    rows = ccx_results.dat_table(stem + ".dat", "displacements", "JOINTS")
    return {name: rows[n] for name, n in mesh["joints"].items()}


def difference(a, b):
    """Largest difference of a joint displacement component over the largest |b|."""
    scale = max(abs(v) for row in b.values() for v in row)
    return max(abs(x - y) for j in b for x, y in zip(a[j], b[j])) / scale


def beamrotor_answers(model, directory):
    """Joint displacements and the reactions' balance against the loads (relative to the
    total load), from results.json."""
    with open(os.path.join(directory, "results.json")) as fh:
        analysis = json.load(fh)["analyses"][0]
    joints = {name: tuple(analysis["displacements"][name][c] for c in ("ux", "uy", "uz"))
              for name in model["nodes"]}
    loads = [0.0, 0.0, 0.0]
    for p in model["point_loads"]:
        loads = [a + f for a, f in zip(loads, p["f"])]
    lengths = {m["name"]: m["length"] for m in model["members"]}
    for q in model["distributed_loads"]:
        loads = [a + f * lengths[q["member"]] for a, f in zip(loads, q["q"])]
    reactions = [sum(r[c] for r in analysis["reactions"].values()) for c in ("fx", "fy", "fz")]
    balance = max(abs(a + r) for a, r in zip(loads, reactions)) / max(abs(a) for a in loads)
    return joints, balance, analysis.get("solver")


def measure(name, maker, with_ccx, mesh_change, repeat, scratch, exe):
    model = frame_model.prepare(maker())
    directory = os.path.join(scratch, name)
    os.makedirs(directory)
    deck = os.path.join(directory, "deck.yaml")
    beamrotor_deck.write(model, deck, ELEMENTS)
    mesh = ccx_input.write(model, os.path.join(directory, "job.inp"), ELEMENTS)
    results = os.path.join(directory, "beamrotor")
    ours = {"wall": [], "peak": [], "solve": [], "write": []}
    theirs = {"wall": [], "peak": []}
    for _ in range(repeat):
        shutil.rmtree(results, ignore_errors=True)
        wall, peak, stdout = timed([exe, "solve", deck, "--out", results])
        solve, write = solve_costs(stdout)
        for key, value in zip(("wall", "peak", "solve", "write"), (wall, peak, solve, write)):
            ours[key].append(value)
        if with_ccx:
            wall, peak, _ = run_ccx(directory, "job")
            theirs["wall"].append(wall)
            theirs["peak"].append(peak)
    members = len(model["members"])
    row = {"members": members, "elements": members * ELEMENTS, "joints": len(model["nodes"]),
           "repeat": repeat,
           "beamrotor_whole_s": statistics.median(ours["wall"]),
           "beamrotor_whole_all_s": ours["wall"],
           "beamrotor_solve_s": statistics.median(ours["solve"]),
           "beamrotor_write_s": statistics.median(ours["write"]),
           "beamrotor_peak_mb": max(ours["peak"])}
    row["beamrotor_whole_per_member_us"] = row["beamrotor_whole_s"] / members * 1e6
    row["beamrotor_solve_per_member_us"] = row["beamrotor_solve_s"] / members * 1e6
    joints, balance, solver = beamrotor_answers(model, results)
    row["beamrotor_solver"] = solver
    row["beamrotor_equilibrium"] = balance
    if with_ccx:
        row.update(ccx_whole_s=statistics.median(theirs["wall"]), ccx_whole_all_s=theirs["wall"],
                   ccx_peak_mb=max(theirs["peak"]))
        row["whole_run_ratio"] = row["ccx_whole_s"] / row["beamrotor_whole_s"]
        coarse = ccx_joints(model, mesh, os.path.join(directory, "job"))
        row["displacement_difference"] = difference(joints, coarse)
        row["largest_ccx_displacement_m"] = max(abs(v) for r in coarse.values() for v in r)
        if mesh_change:
            fine_mesh = ccx_input.write(model, os.path.join(directory, "fine.inp"), FINE)
            run_ccx(directory, "fine")
            fine = ccx_joints(model, fine_mesh, os.path.join(directory, "fine"))
            row["ccx_mesh_change_5_to_10"] = difference(coarse, fine)
            row["displacement_difference_ccx_10"] = difference(joints, fine)
            # B31's error goes with h^2: Richardson's extrapolation of the two meshes.
            limit = {j: tuple(f + (f - c) / 3 for c, f in zip(coarse[j], fine[j])) for j in fine}
            row["displacement_difference_ccx_extrapolated"] = difference(joints, limit)
    shutil.rmtree(directory, ignore_errors=True)
    return row


def slope(rows):
    """Least-squares slope of log(beamrotor's solve and whole run) against log(members) over
    the buildings."""
    out = {}
    buildings = [r for n, r in rows.items() if n.startswith("building")]
    if len(buildings) < 2:
        return out
    lx = [math.log(r["members"]) for r in buildings]
    for key in ("beamrotor_solve_s", "beamrotor_whole_s"):
        ly = [math.log(r[key]) for r in buildings]
        mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
        out[key] = (sum((a - mx) * (b - my) for a, b in zip(lx, ly))
                    / sum((a - mx) ** 2 for a in lx))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exe", default="./build/beamrotor")
    parser.add_argument("--json", required=True)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--large", action="store_true",
                        help="also the 10^5-element building (ccx once: about 5 GB and a minute) "
                             "and the 10^5-member one (beamrotor only)")
    parser.add_argument("--large-repeat", type=int, default=1)
    parser.add_argument("--only", help="comma-separated case names")
    args = parser.parse_args()
    if not shutil.which("ccx"):
        sys.exit("ccx is not installed (make deps PACKAGES=calculix-ccx)")
    exe = os.path.abspath(args.exe)
    scratch = tempfile.mkdtemp(prefix="beamrotor-frames-ccx-")
    rows = {}
    print(f"{'frame':20} {'members':>8} {'beamrotor s':>12} {'solve s':>8} {'ccx s':>8} "
          f"{'ratio':>6} {'peak MB':>8} {'ccx MB':>7} {'u diff':>8} {'ccx 5->10':>9}")
    try:
        for name, (maker, with_ccx, mesh_change, large) in CASES.items():
            if (args.only and name not in args.only.split(",")) or (large and not args.large):
                continue
            repeat = args.large_repeat if large else args.repeat
            r = measure(name, maker, with_ccx, mesh_change, repeat, scratch, exe)
            rows[name] = r

            def cell(key, fmt, r=r):
                return format(r[key], fmt) if key in r else "-"
            print(f"{name:20} {r['members']:>8} {r['beamrotor_whole_s']:>12.3f} "
                  f"{r['beamrotor_solve_s']:>8.3f} {cell('ccx_whole_s', '8.2f'):>8} "
                  f"{cell('whole_run_ratio', '6.1f'):>6} {r['beamrotor_peak_mb']:>8.0f} "
                  f"{cell('ccx_peak_mb', '7.0f'):>7} {cell('displacement_difference', '8.1e'):>8} "
                  f"{cell('ccx_mesh_change_5_to_10', '9.1e'):>9}", flush=True)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    report = {"elements_per_member": ELEMENTS, "machine_shared": True, "frames": rows,
              "log_log_slope_vs_members": slope(rows)}
    for key, value in report["log_log_slope_vs_members"].items():
        print(f"log-log slope of {key} against members (buildings): {value:.2f}")
    write_json(args.json, report)


if __name__ == "__main__":
    main()
