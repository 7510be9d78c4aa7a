#!/usr/bin/python3
"""Cold one-shot figures of `make bench`: a command run R times, each in a fresh process.

What a user meets: the wall time from starting the process to its exit, so dynamic loading,
library start-up, first-touch page faults and writing the results all count (the warm
figures of `beamrotor bench` and planar_scipy.py are medians of repeats inside one process).
Writes FILE: {"command", "repeat", "wall_s" (median), "runs_s", "peak_rss_mb" (largest over
the runs)}. The command's standard output is discarded; a failing run fails this script.

Usage: cold.py --repeat R --json FILE -- COMMAND [ARG ...]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time


def run_once(command):
    """Wall seconds and peak resident MB of one fresh process running command."""
    start = time.perf_counter()
    child = subprocess.Popen(command, stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != 0:
        sys.exit(f"cold.py: {' '.join(command)} failed with exit {child.returncode}")
    return wall, usage.ru_maxrss / 1024.0  # Linux reports kilobytes


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--json", required=True)
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command:
        parser.error("no command given")
    runs = [run_once(command) for _ in range(max(1, args.repeat))]
    out = {"command": command, "repeat": len(runs),
           "wall_s": statistics.median(w for w, _ in runs),
           "runs_s": [w for w, _ in runs],
           "peak_rss_mb": max(m for _, m in runs)}
    with open(args.json, "w") as fh:
        json.dump(out, fh, indent=2)
    print(f"cold {os.path.basename(command[0])}: median {out['wall_s']:.3f} s wall over "
          f"{out['repeat']} fresh processes")


if __name__ == "__main__":
    main()
