#!/usr/bin/env python3
"""Throughput of `beamrotor study` (make bench-study; never part of make test).

The pump rod's stroke-and-wear grid (eta x w0, every point giving all five reactions and the
largest stress, each reaction checked against the deck's closed form at every point) run
serially, with --threads 2 and under mpirun -n 2; prints points per second, parallel
efficiency against the serial run and memory per point (peak resident memory of the full grid
less that of 10^3 points, per extra point), the lean path against the full path (--full-path) on a
2000-point grid, and the per-point cost split the study prints (reading the deck, building the
model, assembly, factorisation, the rest of the solve, checks and outputs, the table row), and
writes them as JSON. Points per second come from wall time and from CPU time (the machine may be
shared; CPU time is what one core spends).
"""
import argparse
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile


def children_cpu_seconds():
    """User plus system time of the finished children so far (s)."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run(command, out_dir):
    """Runs the study; returns (points/s, wall s, CPU s, summary, its printed summary).

    The CPU time (all threads and ranks, from the kernel's accounting of the children) gives
    points per CPU second, the one-core figure that other work on a shared machine leaves
    alone; wall time is what a user waits.
    """
    cpu_before = children_cpu_seconds()
    process = subprocess.Popen(command + ["--out", out_dir], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    stdout, stderr = process.communicate()
    cpu = children_cpu_seconds() - cpu_before
    if process.returncode != 0:
        sys.exit("failed: " + " ".join(command) + "\n" + stdout + stderr)
    match = re.search(r"time: ([0-9.]+) s, ([0-9]+) points/s", stdout)
    with open(os.path.join(out_dir, "summary.json")) as f:
        summary = json.load(f)
    return float(match.group(2)), float(match.group(1)), cpu, summary, stdout


COST_PHASES = ("read deck", "model", "assemble", "factorise", "solve and recover",
               "checks and outputs", "table row")


def cost_split(stdout):
    """The study's `per point (us): ...` line as {phase: microseconds per point}."""
    line = re.search(r"per point \(us\): (.*)", stdout)
    if not line:
        sys.exit("the study printed no per-point cost split")
    split = {}
    for phase in COST_PHASES:
        match = re.search(re.escape(phase) + r" ([0-9.]+)", line.group(1))
        if not match:
            sys.exit("the cost split has no '%s'" % phase)
        split[phase] = float(match.group(1))
    return split


def peak_rss_mb(command, out_dir):
    """Peak resident memory of one run (MB), as GNU time reports it (%M, kB). Not from
    wait4's accounting after a fork of this script: the child's peak would then include the
    memory this script holds (the tables it keeps), which exec does not reset."""
    process = subprocess.run(["/usr/bin/time", "-f", "%M"] + command + ["--out", out_dir],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if process.returncode != 0:
        sys.exit("failed: " + " ".join(command))
    return float(process.stderr.strip().splitlines()[-1]) / 1024.0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", default="build/beamrotor")
    parser.add_argument("--deck", default="problems/pump_rod.yaml")
    parser.add_argument("--eta-steps", type=int, default=399)  # 400 x 250 = 100000 points
    parser.add_argument("--w0-steps", type=int, default=249)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--json", default="out/bench/study.json")
    args = parser.parse_args()
    # Every reaction and the largest stress recorded at each point (the checks come anyway).
    outputs = []
    for quantity in ("reaction left uy", "reaction left rz", "reaction middle uy",
                     "reaction right uy", "reaction right rz", "stress max"):
        outputs += ["--output", quantity]
    grid = ["study", args.deck, "--sweep", "eta=0:0.4:%d" % args.eta_steps,
            "--sweep", "w0=0.5e-3:1.5e-3:%d" % args.w0_steps] + outputs
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
        rates, cpu_rates, splits = [], [], []
        for r in range(args.repeat):
            out = os.path.join(scratch, "%s_%d" % (name, r))
            rate, seconds, cpu, summary, stdout = run(command, out)
            rates.append(rate)
            splits.append(cost_split(stdout))
            cpu_rates.append(points / cpu)
            if summary.get("path") != "lean":
                sys.exit("the study did not take the lean path: %s" % summary.get("path"))
            with open(os.path.join(out, "study.csv"), "rb") as f:
                tables[name] = f.read()
            checks = {c["name"]: (c["passed"], c["applicable"]) for c in summary["checks"]}
            closed = {k: v for k, v in checks.items() if "closed form" in k}
            if any(p != a or a != points for p, a in closed.values()):
                sys.exit("a closed-form check failed or was skipped: %s" % closed)
            shutil.rmtree(out)
        rates.sort()
        cpu_rates.sort()
        results["runs"][name] = {"points_per_s_median": rates[len(rates) // 2],
                                 "points_per_s_all": rates,
                                 "points_per_cpu_s_median": cpu_rates[len(cpu_rates) // 2],
                                 "points_per_cpu_s_all": cpu_rates}
        print("%-10s %8.0f points/s, %8.0f points per CPU second (medians of %d)"
              % (name, rates[len(rates) // 2], cpu_rates[len(cpu_rates) // 2], args.repeat))
        # Where a point's time goes, on the core that solved it: each phase's median.
        split = {phase: sorted(s[phase] for s in splits)[len(splits) // 2]
                 for phase in COST_PHASES}
        results["runs"][name]["cost_per_point_us"] = split
        print("           per point (us, medians): " +
              ", ".join("%s %.1f" % (phase, us) for phase, us in split.items()) +
              "; sum %.1f" % sum(split.values()))
    serial = results["runs"]["serial"]["points_per_s_median"]
    for name in results["runs"]:
        if name != "serial":
            speedup = results["runs"][name]["points_per_s_median"] / serial
            results["runs"][name]["speedup"] = speedup
            results["runs"][name]["parallel_efficiency"] = speedup / 2
            print("%-10s speed-up %.2f, parallel efficiency %.2f" % (name, speedup, speedup / 2))
    results["tables_identical"] = all(t == tables["serial"] for t in tables.values())
    print("tables identical across serial, threads and MPI:", results["tables_identical"])
    def grid_of(eta_steps, w0_steps):
        return [args.exe, "study", args.deck, "--sweep", "eta=0:0.4:%d" % eta_steps,
                "--sweep", "w0=0.5e-3:1.5e-3:%d" % w0_steps] + outputs
    # Peak memory of 10^3 and 10^4 points (and the full grid): the growth per point.
    rss = {n: peak_rss_mb(grid_of(*steps), os.path.join(scratch, "rss_%d" % n))
           for n, steps in ((1000, (39, 24)), (10000, (99, 99)))}
    rss[points] = peak_rss_mb(variants["serial"], os.path.join(scratch, "rss_large"))
    # Growth from 10^3 points to the full grid: between 10^3 and 10^4 points the kept outputs
    # (48 bytes a point) stay inside the allocator's granularity.
    per_point = (rss[points] - rss[1000]) * 1024 * 1024 / (points - 1000)
    results["peak_rss_mb"] = {"%d_points" % n: v for n, v in rss.items()}
    results["memory_bytes_per_point"] = per_point
    print("peak memory %.1f MB at 1000 points, %.1f MB at 10000, %.1f MB at %d: "
          "%.0f bytes per point" % (rss[1000], rss[10000], rss[points], points, per_point))
    # The lean path against the full path (every point's deck parsed in full), serially on a
    # 2000-point grid: the same table, and the speed-up.
    lean_full = {}
    for path in ("lean", "full"):
        command = grid_of(39, 49) + (["--full-path"] if path == "full" else [])
        out = os.path.join(scratch, "path_" + path)
        rate, _, cpu, summary, _ = run(command, out)
        with open(os.path.join(out, "study.csv"), "rb") as f:
            lean_full[path] = (rate, 2000 / cpu, f.read())
    results["lean_vs_full_2000_points"] = {
        path: {"points_per_s": v[0], "points_per_cpu_s": v[1]} for path, v in lean_full.items()}
    results["lean_vs_full_2000_points"]["tables_identical"] = (
        lean_full["lean"][2] == lean_full["full"][2])
    print("2000 points: lean %.0f, full %.0f points per CPU second; tables identical: %s"
          % (lean_full["lean"][1], lean_full["full"][1],
             lean_full["lean"][2] == lean_full["full"][2]))
    shutil.rmtree(scratch)
    os.makedirs(os.path.dirname(args.json) or ".", exist_ok=True)
    with open(args.json, "w") as f:
        json.dump(results, f, indent=2)
    print("json:", args.json)
    if not results["tables_identical"] or not results["lean_vs_full_2000_points"]["tables_identical"]:
        sys.exit("the tables differ")


if __name__ == "__main__":
    main()
