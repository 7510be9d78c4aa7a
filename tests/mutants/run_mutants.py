#!/usr/bin/env python3
"""Mutation testing for beamrotor: `make mutants` (never part of `make test`).

Plants the single-line mutants of tests/mutants/mutants.txt one at a time in the source tree
itself, rebuilds a one-object-per-source build directory incrementally, runs the test suite
with a time limit and puts the file back, whatever happens (an exception, Ctrl-C, SIGTERM; a
copy of the original sits in OUT/backup/ until it is restored, and a later run puts back any
copy a killed run left there). A mutant is killed when tests fail (or time out) in the full run
and again when the failed ones are rerun alone: the suite has wall-clock budgets (a sweep's
outputs, a Campbell diagram) that a loaded machine can miss, and a failure the quiet rerun does
not repeat is reported as flaky, not as a kill. A mutant survives when the suite passes, and is
invalid when it does not compile. Prints one line per mutant and the kill rate, and writes
OUT/summary.json.

Usage: run_mutants.py [--build DIR] [--out DIR] [--list FILE] [--jobs N] [--timeout S]
                      [--only ID,ID,...] [--check]
"""

import argparse
import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
KEYS = ("id", "file", "find", "replace", "why", "equivalent")


def parse_list(path):
    """Blocks of `key: value` lines separated by blank lines; # starts a comment line."""
    mutants, block = [], {}
    lines = path.read_text().splitlines() + [""]
    for number, line in enumerate(lines, 1):
        if line.startswith("#"):
            continue
        if not line.strip():
            if block:
                mutants.append(block)
                block = {}
            continue
        key, sep, value = line.partition(": ")
        if not sep or key not in KEYS or key in block:
            sys.exit(f"{path}:{number}: expected one of {', '.join(KEYS)} once per block: {line}")
        block[key] = value
        block.setdefault("line", number)
    return mutants


def validate(mutants):
    """Every block complete, ids unique, each find text once in its file and on one line."""
    seen, problems = set(), []
    for m in mutants:
        where = f"mutant at line {m['line']}"
        missing = [k for k in ("id", "file", "find", "replace", "why") if k not in m]
        if missing:
            problems.append(f"{where}: missing {', '.join(missing)}")
            continue
        if m["id"] in seen:
            problems.append(f"{where}: duplicate id {m['id']}")
        seen.add(m["id"])
        source = ROOT / m["file"]
        if not source.is_file():
            problems.append(f"{m['id']}: no file {m['file']}")
            continue
        count = source.read_text().count(m["find"])
        if count != 1:
            problems.append(f"{m['id']}: the find text occurs {count} times in {m['file']}")
        if m["find"] == m["replace"]:
            problems.append(f"{m['id']}: replace equals find")
    return problems


class Planted:
    """Context manager: the mutant is in the file inside the block, the original after it."""

    def __init__(self, mutant, backup_dir):
        self.path = ROOT / mutant["file"]
        self.backup = backup_dir / mutant["file"]
        self.mutant = mutant

    def __enter__(self):
        self.original = self.path.read_text()
        self.backup.parent.mkdir(parents=True, exist_ok=True)
        self.backup.write_text(self.original)
        self.path.write_text(self.original.replace(self.mutant["find"], self.mutant["replace"], 1))
        return self

    def __exit__(self, *exc):
        self.path.write_text(self.original)
        self.backup.unlink()
        return False


def restore_leftovers(backup_dir):
    """Puts back originals an earlier run could not (it was killed with SIGKILL)."""
    if not backup_dir.is_dir():
        return
    for copy in sorted(p for p in backup_dir.rglob("*") if p.is_file()):
        target = ROOT / copy.relative_to(backup_dir)
        print(f"restoring {target.relative_to(ROOT)} left mutated by an earlier run")
        target.write_text(copy.read_text())
        copy.unlink()


def run(command, timeout, log):
    """Runs command, appending its output to log; returns (exit code or None on timeout, s)."""
    start = time.monotonic()
    with open(log, "a") as out:
        out.write(f"$ {' '.join(command)}\n")
        out.flush()
        process = subprocess.Popen(command, cwd=ROOT, stdout=out, stderr=subprocess.STDOUT,
                                   start_new_session=True)
        try:
            code = process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)  # its own session: the whole process group
            process.wait()
            code = None
        except BaseException:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
            raise
    return code, time.monotonic() - start


def ctest_regex(names):
    """An anchored CTest regular expression matching exactly these test names."""
    special = set(".^$*+?()[]{}|\\")
    return "^(" + "|".join("".join("\\" + c if c in special else c for c in n)
                           for n in names) + ")$"


def run_suite(build_dir, jobs, timeout, log):
    """The whole suite, then the failed tests again one at a time. Returns (failed in both
    runs, failed only in the first, seconds); a hang of the whole run counts as a failure."""
    test = ["ctest", "--test-dir", build_dir, "--timeout", str(timeout), "--output-on-failure"]
    code, seconds = run(test + ["-j", str(jobs)], timeout * 2, log)
    if code == 0:
        return [], [], seconds
    if code is None:
        return ["(suite timed out)"], [], seconds
    first = failed_tests(log)
    if not first:  # ctest failed without naming a test (e.g. it could not start)
        return ["(ctest failed)"], [], seconds
    code, again = run(test + ["-R", ctest_regex(first)], timeout * 2, log)
    confirmed = first if code is None else failed_tests(log) if code != 0 else []
    return confirmed, [n for n in first if n not in confirmed], seconds + again


def failed_tests(log):
    """The CTest names listed after 'The following tests FAILED:' in the last ctest output."""
    text = Path(log).read_text()
    names = []
    for line in text.split("The following tests FAILED:")[-1].splitlines()[1:]:
        if " - " not in line:
            break
        names.append(line.split(" - ", 1)[1].rsplit(" (", 1)[0].strip())
    return names


def interrupt(signum, frame):
    """SIGTERM unwinds like Ctrl-C, so every planted file is put back."""
    raise KeyboardInterrupt()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default="build-mutants", help="build directory (non-unity)")
    parser.add_argument("--out", default="out/mutants", help="summary.json, logs, backups")
    parser.add_argument("--list", default="tests/mutants/mutants.txt")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--timeout", type=float, default=900,
                        help="seconds for one run of the whole suite (a hang counts as killed)")
    parser.add_argument("--build-timeout", type=float, default=1800)
    parser.add_argument("--only", default="", help="comma-separated ids to run")
    parser.add_argument("--check", action="store_true", help="only validate the list")
    args = parser.parse_args()

    signal.signal(signal.SIGTERM, interrupt)

    mutants = parse_list(ROOT / args.list)
    problems = validate(mutants)
    if problems:
        sys.exit("mutant list:\n  " + "\n  ".join(problems))
    if args.only:
        wanted = set(args.only.split(","))
        unknown = wanted - {m["id"] for m in mutants}
        if unknown:
            sys.exit(f"unknown mutant ids: {', '.join(sorted(unknown))}")
        mutants = [m for m in mutants if m["id"] in wanted]
    print(f"{len(mutants)} mutants in {args.list}, all well-formed")
    if args.check:
        return 0

    out = ROOT / args.out
    backup_dir = out / "backup"
    logs = out / "logs"
    restore_leftovers(backup_dir)
    logs.mkdir(parents=True, exist_ok=True)
    build = ["cmake", "--build", args.build, "-j", str(args.jobs)]

    # 1. The unmutated suite must pass, or no kill means anything.
    log = logs / "baseline.log"
    log.write_text("")
    code, build_s = run(build, args.build_timeout, log)
    if code != 0:
        sys.exit(f"the unmutated tree does not build (see {log})")
    failed, flaky, suite_s = run_suite(args.build, args.jobs, args.timeout, log)
    if failed:
        sys.exit(f"the unmutated suite fails: {', '.join(failed)} (see {log})")
    print(f"baseline: built in {build_s:.0f} s, suite passes in {suite_s:.0f} s"
          + (f" (flaky under load: {', '.join(flaky)})" if flaky else ""))

    # 2. One mutant at a time.
    results = []
    started = time.monotonic()
    interrupted = False
    try:
        for k, m in enumerate(mutants, 1):
            log = logs / f"{m['id']}.log"
            log.write_text(f"{m['file']}: {m['find']}\n  -> {m['replace']}\n")
            result = {key: m[key] for key in ("id", "file", "find", "replace", "why")}
            if "equivalent" in m:
                result["equivalent"] = m["equivalent"]
            with Planted(m, backup_dir):
                code, build_s = run(build, args.build_timeout, log)
                result["build_s"] = round(build_s, 1)
                if code != 0:
                    result["status"] = "invalid"
                    result["reason"] = "does not build" if code is not None else "build timed out"
                else:
                    failed, flaky, test_s = run_suite(args.build, args.jobs, args.timeout, log)
                    result["test_s"] = round(test_s, 1)
                    result["status"] = "killed" if failed else "survived"
                    if failed:
                        result["killed_by"] = failed
                    if flaky:
                        result["flaky"] = flaky
            results.append(result)
            note = ", ".join(result.get("killed_by", [])) or result.get("reason", "")
            if "flaky" in result:
                note += (", " if note else "") + "flaky: " + ", ".join(result["flaky"])
            if result["status"] == "survived" and "equivalent" in m:
                note = "equivalent: " + m["equivalent"]
            print(f"[{k}/{len(mutants)}] {result['status']:8s} {m['id']}"
                  + (f"  ({note})" if note else ""), flush=True)
    except KeyboardInterrupt:
        interrupted = True
        print("interrupted: the planted file is restored; partial results follow")
    if not interrupted:
        # Leave the build directory matching the restored tree (an interrupted run leaves that
        # to the next one's baseline build).
        run(build, args.build_timeout, logs / "restore.log")

    # 3. Summary.
    def count(status, equivalent=None):
        return sum(1 for r in results if r["status"] == status
                   and (equivalent is None or ("equivalent" in r) == equivalent))

    killed = count("killed")
    survived = count("survived", equivalent=False)
    equivalent = count("survived", equivalent=True)
    invalid = count("invalid")
    judged = killed + survived
    rate = killed / judged if judged else 0.0
    summary = {
        "list": args.list,
        "mutants": len(results),
        "killed": killed,
        "survived": survived,
        "equivalent": equivalent,
        "invalid": invalid,
        "kill_rate": rate,
        "kill_rate_definition": "killed / (killed + survived), equivalent and invalid left out",
        "elapsed_s": round(time.monotonic() - started),
        "results": results,
    }
    (out / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
    print(f"\n{killed} killed, {survived} survived, {equivalent} equivalent (survived, shown "
          f"harmless in the list), {invalid} invalid; kill rate {killed}/{judged} = "
          f"{100 * rate:.1f} %")
    for r in results:
        if r["status"] == "survived" and "equivalent" not in r:
            print(f"  SURVIVED {r['id']}: {r['why']} ({r['file']})")
    print(f"summary: {out / 'summary.json'}")
    return 1 if survived else 0


if __name__ == "__main__":
    sys.exit(main())
