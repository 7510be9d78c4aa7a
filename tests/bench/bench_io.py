"""What the bench scripts share: the summary's cost line and writing a JSON report."""
import json
import os
import re
import sys


def solve_costs(stdout):
    """(solve s, write s) from the summary's cost line `time: T s (solve S s, write W s)`."""
    match = re.search(r"time: [0-9.]+ s \(solve ([0-9.]+) s, write ([0-9.]+) s\)", stdout)
    if not match:
        sys.exit("the summary has no cost line:\n" + stdout[-2000:])
    return float(match.group(1)), float(match.group(2))


def write_json(path, report):
    """Writes the report (indented, a final newline), making its directory; prints its path."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as fh:
        json.dump(report, fh, indent=2)
        fh.write("\n")
    print("json:", path)
