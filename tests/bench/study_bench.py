#!/usr/bin/env python3
"""Throughput of `beamrotor study` (make bench-study; never part of make test).

The pump rod's stroke-and-wear grid (eta x w0, every point giving all five reactions and the
largest stress, each reaction checked against the deck's closed form at every point) run
serially, with --threads 2 and under mpirun -n 2; prints points per second, parallel
efficiency against the serial run and memory per point (peak resident memory of a large study
less that of a small one, per extra point), and writes them as JSON.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile


def run(command, out_dir):
    """Runs the study; returns (points/s, wall s, summary, its printed summary)."""
    process = subprocess.Popen(command + ["--out", out_dir], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    stdout, stderr = process.communicate()
    if process.returncode != 0:
        sys.exit("failed: " + " ".join(command) + "\n" + stdout + stderr)
    match = re.search(r"time: ([0-9.]+) s, ([0-9]+) points/s", stdout)
    with open(os.path.join(out_dir, "summary.json")) as f:
        summary = json.load(f)
    return float(match.group(2)), float(match.group(1)), summary, stdout


def peak_rss_mb(command, out_dir):
    """Peak resident memory of one run (MB), from the kernel's accounting of the child."""
    pid = os.fork()
    if pid == 0:
        with open(os.devnull, "w") as null:
            os.dup2(null.fileno(), 1)
            os.dup2(null.fileno(), 2)
        os.execv(command[0], command + ["--out", out_dir])
    _, status, usage = os.wait4(pid, 0)
    if status != 0:
        sys.exit("failed: " + " ".join(command))
    return usage.ru_maxrss / 1024.0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", default="build/beamrotor")
    parser.add_argument("--deck", default="problems/pump_rod.yaml")
    parser.add_argument("--eta-steps", type=int, default=399)  # 400 x 250 = 100000 points
    parser.add_argument("--w0-steps", type=int, default=249)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--json", default="out/bench/study.json")
    args = parser.parse_args()
    grid = ["study", args.deck, "--sweep", "eta=0:0.4:%d" % args.eta_steps,
            "--sweep", "w0=0.5e-3:1.5e-3:%d" % args.w0_steps]
    points = (args.eta_steps + 1) * (args.w0_steps + 1)
    scratch = tempfile.mkdtemp(prefix="beamrotor-bench-study-")
    results = {"deck": args.deck, "points": points, "machine_shared": True, "runs": {}}
    variants = {"serial": [args.exe] + grid,
                "threads_2": [args.exe] + grid + ["--threads", "2"]}
    if shutil.which("mpirun"):
        variants["mpirun_2"] = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-n", "2",
                                args.exe] + grid
    tables = {}
    for name, command in variants.items():
        rates = []
        for r in range(args.repeat):
            out = os.path.join(scratch, "%s_%d" % (name, r))
            rate, seconds, summary, stdout = run(command, out)
            rates.append(rate)
            with open(os.path.join(out, "study.csv"), "rb") as f:
                tables[name] = f.read()
            checks = {c["name"]: (c["passed"], c["applicable"]) for c in summary["checks"]}
            closed = {k: v for k, v in checks.items() if "closed form" in k}
            if any(p != a or a != points for p, a in closed.values()):
                sys.exit("a closed-form check failed or was skipped: %s" % closed)
            shutil.rmtree(out)
        rates.sort()
        results["runs"][name] = {"points_per_s_median": rates[len(rates) // 2],
                                 "points_per_s_all": rates}
        print("%-10s %8.0f points/s (median of %d)" % (name, rates[len(rates) // 2],
                                                         args.repeat))
    serial = results["runs"]["serial"]["points_per_s_median"]
    for name in results["runs"]:
        if name != "serial":
            speedup = results["runs"][name]["points_per_s_median"] / serial
            results["runs"][name]["speedup"] = speedup
            results["runs"][name]["parallel_efficiency"] = speedup / 2
            print("%-10s speed-up %.2f, parallel efficiency %.2f" % (name, speedup, speedup / 2))
    results["tables_identical"] = all(t == tables["serial"] for t in tables.values())
    print("tables identical across serial, threads and MPI:", results["tables_identical"])
    small = grid[:3] + ["eta=0:0.4:9"] + grid[4:6]
    small[-1] = "w0=0.5e-3:1.5e-3:9"
    rss_small = peak_rss_mb([args.exe] + small, os.path.join(scratch, "small"))
    rss_large = peak_rss_mb(variants["serial"], os.path.join(scratch, "large"))
    per_point = (rss_large - rss_small) * 1024 * 1024 / (points - 100)
    results["peak_rss_mb"] = {"100_points": rss_small, "%d_points" % points: rss_large}
    results["memory_bytes_per_point"] = per_point
    print("peak memory %.1f MB at 100 points, %.1f MB at %d: %.0f bytes per point"
          % (rss_small, rss_large, points, per_point))
    shutil.rmtree(scratch)
    os.makedirs(os.path.dirname(args.json) or ".", exist_ok=True)
    with open(args.json, "w") as f:
        json.dump(results, f, indent=2)
    print("json:", args.json)
    if not results["tables_identical"]:
        sys.exit("the tables differ")


if __name__ == "__main__":
    main()
