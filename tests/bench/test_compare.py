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


def test_frames_decks_and_studies_gathered(tmp_path):
    """The figures of the frame, deck and study scripts reach summary.json as written, and
    the rotor workloads are read from the analyses of their decks."""
    frame = {"members": 1064, "beamrotor_whole_s": 2.0, "beamrotor_solve_s": 0.5,
             "beamrotor_peak_mb": 86.0, "ccx_whole_s": 5.0, "ccx_peak_mb": 300.0,
             "whole_run_ratio": 2.5, "displacement_difference": 0.07}
    alone = {"members": 101556, "beamrotor_whole_s": 600.0, "beamrotor_solve_s": 300.0,
             "beamrotor_peak_mb": 5600.0}
    write(tmp_path / "frames_ccx.json", {"frames": {"building_6x6x8": frame}})
    write(tmp_path / "frames_ccx_large.json", {"frames": {"building_30x30x36": alone}})
    write(tmp_path / "frame3d_combinations_20.json",
          {"frame": {"members": 9030.0, "cases_s": 0.8, "cases_to_static": 0.38,
                     "write_s": 210.0, "whole_s": 216.0}})
    decks = {"compressor_rotor": {"whole_s": 5.0, "whole_no_charts_s": 2.7, "solve_s": 2.2,
                                  "write_s": 2.2,
                                  "analyses_s": {"response": 1.25, "campbell": 0.5}},
             "jeffcott_internal_damping": {"whole_s": 1.2, "whole_no_charts_s": 0.6,
                                           "solve_s": 0.1, "write_s": 0.66,
                                           "analyses_s": {"campbell": 0.0625}}}
    write(tmp_path / "output.json", {"decks": decks})
    write(tmp_path / "study.json", {"runs": {"serial": {"points_per_s_median": 800.0},
                                             "threads_2": {"points_per_s_median": 1200.0}}})
    run = subprocess.run([sys.executable, str(HERE / "compare.py"), str(tmp_path)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["frames_ccx"] == {"building_6x6x8": frame, "building_30x30x36": alone}
    assert summary["frame3d_combinations"]["20"]["cases_to_static"] == 0.38
    assert summary["decks"]["compressor_rotor"]["whole_no_charts_s"] == 2.7
    assert summary["rotor_decks"]["unbalance_sweep_s"]["solve_s"] == 1.25
    assert summary["rotor_decks"]["stability_onset_s"]["solve_s"] == 0.0625
    assert summary["study_points_per_s"] == {"serial": 800.0, "threads_2": 1200.0}
    assert "2.5x" in run.stdout and "slowest compressor_rotor 5.00 s" in run.stdout


def test_combinations_ratio_recorded(tmp_path):
    """With 1 and 200 combinations measured, summary.json records the whole runs' quotient
    (issue 41 item 6, target 3): 30.0 s over 12.5 s here."""
    for c, whole in ((1, 12.5), (200, 30.0)):
        write(tmp_path / f"frame3d_combinations_{c}.json",
              {"frame": {"members": 9030.0, "cases_s": 0.5, "cases_to_static": 0.3,
                         "write_s": whole - 2.0, "whole_s": whole}})
    run = subprocess.run([sys.executable, str(HERE / "compare.py"), str(tmp_path)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["frame3d_combinations"]["whole_200_over_1"] == pytest.approx(2.4, rel=1e-15)
    assert "200 combinations over 1, whole runs: 2.40 (target 3)" in run.stdout
