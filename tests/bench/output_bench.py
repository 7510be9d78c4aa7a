#!/usr/bin/env python3
"""What writing the results costs beside the solve, per shipped deck (part of make bench;
never part of make test).

Each deck of problems/ is solved --repeat times with `beamrotor solve` into a scratch
directory; the summary's cost line `time: T s (solve S s, write W s)` gives the solve and the
write, and the kernel's accounting of the finished children gives the CPU time of the whole
run (beamrotor and the gnuplot processes it started); each run's wall time is the whole run
as a user types it, taken again with --charts none, and results.json's time_s gives each
analysis's own solve (the compressor's 580-speed unbalance sweep, the internally damped
Jeffcott rotor's instability onset). Medians per deck. Then the two ways a
sweep or study writes a result per point: a sweep of the pump rod over 200 values with
--point-files, and a study of 1000 points with --point-files (its `point files:` line).

With --baseline, a second executable (built before a change) runs in turn with the first
on every deck, so that both see the same load.

The issues' targets: writing at most 0.3 s beyond the solve for every shipped deck on two
cores, and at least 100 points per second for per-point files (issue 43); every shipped deck
end to end in at most 0.5 s (issue 45). The JSON holds every
figure and whether each target is met; the machine may be shared, so the CPU seconds are
given beside the wall seconds.
"""
import argparse
import glob
import json
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from bench_io import solve_costs, write_json

WRITE_TARGET_S = 0.3
WHOLE_TARGET_S = 0.5   # issue 45: every shipped deck end to end
POINTS_TARGET = 100.0


def children_cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run(command):
    """Runs a command; returns (stdout, CPU seconds of it and its children)."""
    before = children_cpu_seconds()
    done = subprocess.run(command, capture_output=True, text=True)
    cpu = children_cpu_seconds() - before
    if done.returncode != 0:
        sys.exit("failed: " + " ".join(command) + "\n" + done.stdout + done.stderr)
    return done.stdout, cpu


def analysis_seconds(out):
    """{analysis name: its solve seconds} from results.json's time_s ({} for a deck whose
    output names no results.json)."""
    path = os.path.join(out, "results.json")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        analyses = json.load(f).get("analyses", [])
    return {a["name"]: a["time_s"] for a in analyses if "time_s" in a}


def deck_figures(executables, deck, repeat, scratch):
    """Medians per executable; the executables take turns run by run, so that a machine whose
    load changes weighs on each alike. Each run as a user types it, then the same without
    charts (--charts none): wall seconds of the whole process beside the summary's costs."""
    keys = ("solve", "write", "cpu", "wall", "wall_no_charts")
    samples = {exe: {k: [] for k in keys} for exe in executables}
    analyses = {exe: {} for exe in executables}
    for _ in range(repeat):
        for exe in executables:
            out = os.path.join(scratch, "deck")
            start = time.perf_counter()
            stdout, cpu = run([exe, "solve", deck, "--out", out])
            wall = time.perf_counter() - start
            solve, write = solve_costs(stdout)
            for name, seconds in analysis_seconds(out).items():
                analyses[exe].setdefault(name, []).append(seconds)
            shutil.rmtree(out, ignore_errors=True)
            start = time.perf_counter()
            run([exe, "solve", deck, "--out", out, "--charts", "none"])
            no_charts = time.perf_counter() - start
            shutil.rmtree(out, ignore_errors=True)
            for k, value in zip(keys, (solve, write, cpu, wall, no_charts)):
                samples[exe][k].append(value)
    figures = {}
    for exe, s in samples.items():
        write = statistics.median(s["write"])
        whole = statistics.median(s["wall"])
        figures[exe] = {"solve_s": statistics.median(s["solve"]), "write_s": write,
                        "run_cpu_s": statistics.median(s["cpu"]), "whole_s": whole,
                        "whole_no_charts_s": statistics.median(s["wall_no_charts"]),
                        "analyses_s": {name: statistics.median(v)
                                       for name, v in analyses[exe].items()},
                        "within_target": write <= WRITE_TARGET_S,
                        "whole_within_target": whole <= WHOLE_TARGET_S}
    return figures


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exe", default="./build/beamrotor")
    parser.add_argument("--decks", default="problems")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--json", required=True)
    parser.add_argument("--baseline",
                        help="another executable (e.g. one built before a change) run in turn "
                             "with --exe on every deck; its figures go to the JSON as baseline")
    parser.add_argument("--scratch", default=None,
                        help="where the results are written (default: the system's temporary "
                             "directory; /dev/shm leaves the disk's file creation out)")
    args = parser.parse_args()
    scratch = tempfile.mkdtemp(prefix="beamrotor-output-bench-", dir=args.scratch)
    report = {"repeat": args.repeat, "write_target_s": WRITE_TARGET_S, "decks": {}}
    if args.baseline:
        report["baseline"] = {}
    executables = [args.exe] + ([args.baseline] if args.baseline else [])
    try:
        print(f"{'deck':28} {'solve s':>9} {'write s':>9} {'run CPU s':>10} {'whole s':>8} "
              f"{'no charts':>9}" +
              (f" {'baseline write s':>17} {'CPU s':>7}" if args.baseline else ""))
        for deck in sorted(glob.glob(os.path.join(args.decks, "*.yaml"))):
            name = os.path.splitext(os.path.basename(deck))[0]
            figures = deck_figures(executables, deck, args.repeat, scratch)
            ours = figures[args.exe]
            report["decks"][name] = ours
            line = (f"{name:28} {ours['solve_s']:9.3f} {ours['write_s']:9.3f} "
                    f"{ours['run_cpu_s']:10.3f} {ours['whole_s']:8.3f} "
                    f"{ours['whole_no_charts_s']:9.3f}")
            if args.baseline:
                base = figures[args.baseline]
                report["baseline"][name] = base
                line += f" {base['write_s']:17.3f} {base['run_cpu_s']:7.3f}"
            print(line + ("" if ours["within_target"] else "  over"))
        writes = [d["write_s"] for d in report["decks"].values()]
        report["largest_write_s"] = max(writes)
        report["all_within_target"] = all(d["within_target"] for d in report["decks"].values())
        report["whole_target_s"] = WHOLE_TARGET_S
        report["largest_whole_s"] = max(d["whole_s"] for d in report["decks"].values())
        report["all_whole_within_target"] = all(d["whole_within_target"]
                                                for d in report["decks"].values())
        pump_rod = os.path.join(args.decks, "pump_rod.yaml")
        out = os.path.join(scratch, "sweep")
        stdout, _ = run([args.exe, "solve", pump_rod, "--out", out, "--point-files",
                         "--sweep", "eta=0:0.4:199"])
        solve, write = solve_costs(stdout)
        report["sweep_point_files"] = {"values": 200, "write_s": write,
                                       "points_per_s": 200 / write}
        out = os.path.join(scratch, "study")
        stdout, _ = run([args.exe, "study", pump_rod, "--out", out, "--point-files",
                         "--sweep", "eta=0:0.4:39", "--sweep", "w0=0.5e-3:1.5e-3:24"])
        match = re.search(r"point files: ([0-9.]+) us per point .*, ([0-9]+) points/s", stdout)
        if not match:
            sys.exit("the study printed no point-files line:\n" + stdout)
        report["study_point_files"] = {"points": 1000, "us_per_point": float(match.group(1)),
                                       "points_per_s": float(match.group(2))}
        for kind in ("sweep_point_files", "study_point_files"):
            figures = report[kind]
            figures["within_target"] = figures["points_per_s"] >= POINTS_TARGET
            print(f"{kind}: {figures['points_per_s']:.0f} points/s")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    write_json(args.json, report)


if __name__ == "__main__":
    main()
