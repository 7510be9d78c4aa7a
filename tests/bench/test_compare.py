"""`make bench`'s last step, compare.py, on the files the bench writes (run by `make test`).

The beamrotor side is real (`beamrotor bench` on small planar models, static and modal); the
SciPy side and the cold wall times are written here, so that every figure of the summary has
a value known beforehand: SciPy's times are set multiples of beamrotor's, its midspan deflection
is the closed form q s^4 / (384 E I) that the bench reports beside its own, and its frequencies
are beamrotor's less a set relative shift. A summary that fails to be written, or any ratio or
agreement that is not the quotient of the figures read, fails here (an earlier compare.py
stopped with UnboundLocalError before writing anything, and nothing noticed).
"""
import json
import os
import pathlib
import subprocess
import sys

import pytest

HERE = pathlib.Path(__file__).resolve().parent
EXE = os.environ.get("BEAMROTOR_EXE", str(HERE.parents[1] / "build" / "beamrotor"))
SIZES = (1000, 10000)
SCIPY_FACTOR = {1000: 7.0, 10000: 9.0}  # SciPy's static time over beamrotor's model + solve
COLD = {"planar_static_1000": 0.05, "scipy_static_1000": 0.30, "planar_static_10000": 0.08,
        "scipy_static_10000": 0.40, "planar_modal_10000": 0.2, "scipy_modal_10000": 20.0}
FREQUENCY_SHIFT = 3e-9


def write(path, data):
    path.write_text(json.dumps(data))


def bench(directory, elements, modes):
    out = directory / f"planar_{'modal' if modes else 'static'}_{elements}.json"
    subprocess.run([EXE, "bench", "--kind", "planar", "--elements", str(elements), "--modes",
                    str(modes), "--repeat", "1", "--json", str(out)], check=True,
                   stdout=subprocess.DEVNULL)
    return json.loads(out.read_text())


@pytest.fixture(scope="module")
def summary(tmp_path_factory):
    # ctest names the binary; a missing one is a failure, never a silent skip.
    assert os.path.exists(EXE), f"no beamrotor binary at {EXE} (set BEAMROTOR_EXE)"
    directory = tmp_path_factory.mktemp("bench")
    ours = {n: bench(directory, n, 0) for n in SIZES}
    modal = bench(directory, 10000, 10)
    for n, a in ours.items():
        total = a["build_s"] + a["static"]["total_s"]
        write(directory / f"scipy_static_{n}.json",
              {"elements": n, "static": {"total_s": SCIPY_FACTOR[n] * total},
               "midspan_w": a["exact_midspan_w"]})
    write(directory / "scipy_modal_10000.json",
          {"elements": 10000, "static": {"total_s": 1.0},
           "modal": {"total_s": 50 * modal["modal"]["total_s"],
                     "frequencies_hz": [f * (1 - FREQUENCY_SHIFT)
                                        for f in modal["modal"]["frequencies_hz"]]}})
    for name, seconds in COLD.items():
        write(directory / f"cold_{name}.json", {"wall_s": seconds, "runs_s": [seconds]})
    run = subprocess.run([sys.executable, str(HERE / "compare.py"), str(directory)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return {"ours": ours, "modal": modal, "directory": directory,
            "summary": json.loads((directory / "summary.json").read_text()), "text": run.stdout}


def test_static_rows_are_the_quotients_of_the_figures_read(summary):
    rows = {r["elements"]: r for r in summary["summary"]["planar_static"]}
    assert sorted(rows) == list(SIZES)
    for n, a in summary["ours"].items():
        r = rows[n]
        assert r["beamrotor_s"] == pytest.approx(a["build_s"] + a["static"]["total_s"], rel=1e-15)
        assert r["ratio"] == pytest.approx(SCIPY_FACTOR[n], rel=1e-14)
        assert r["cold_ratio"] == pytest.approx(
            COLD[f"scipy_static_{n}"] / COLD[f"planar_static_{n}"], rel=1e-14)
        # SciPy's deflection here is the closed form, so the agreement with it is the bench's
        # own error against the closed form, computed by the bench (7e-15 at these sizes).
        assert r["w_agreement"] == pytest.approx(a["rel_error_static"], rel=1e-6, abs=1e-16)
    assert "planar_static_slope" in summary["summary"]
    assert (summary["directory"] / "planar_static_scaling.png").stat().st_size > 0


def test_modal_ratio_and_frequency_agreement(summary):
    m = summary["summary"]["planar_modal"]
    assert m["ratio"] == pytest.approx(50.0, rel=1e-14)
    # f (1 - d) against f: |1 / (1 - d) - 1| = d / (1 - d).
    assert m["frequency_agreement"] == pytest.approx(FREQUENCY_SHIFT / (1 - FREQUENCY_SHIFT),
                                                     rel=1e-6)
    assert m["beamrotor_cold_s"] == COLD["planar_modal_10000"]
    assert m["scipy_cold_s"] == COLD["scipy_modal_10000"]
    assert f"{COLD['scipy_modal_10000'] / COLD['planar_modal_10000']:.1f}x" in summary["text"]
