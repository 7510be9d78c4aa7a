"""The Python module against closed forms and published figures, and against the command line's
own results directory (the same numbers by a second path)."""
import json
import math
import os
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import beamrotor

PROBLEMS = pathlib.Path(os.environ["BEAMROTOR_SOURCE_DIR"]) / "problems"
MALFORMED = pathlib.Path(os.environ["BEAMROTOR_SOURCE_DIR"]) / "tests" / "problems" / "malformed"

# Hermite elements hold the static cantilever exactly: round-off only (the deck's own
# tolerance, where ~5e-12 is observed).
EXACT = 1e-9


def cantilever_reference(p):
    inertia = math.pi * p["D"] ** 4 / 64
    return {
        "tip": -p["P"] * p["L"] ** 3 / (3 * p["E"] * inertia),
        "root_moment": p["P"] * p["L"],
        "f1": 1.875104**2 / (2 * math.pi * p["L"] ** 2)
        * math.sqrt(p["E"] * inertia / (p["rho"] * math.pi * p["D"] ** 2 / 4)),
    }


def test_parameters_are_the_decks():
    p = beamrotor.parameters(PROBLEMS / "cantilever.yaml")
    assert list(p) == ["L", "D", "P", "E", "rho"]
    assert p["L"] == 1.2 and p["P"] == 1000


def test_cantilever_against_beam_theory():
    run = beamrotor.solve(PROBLEMS / "cantilever.yaml", set={"P": 2500, "L": "1.5"})
    p = run.parameters
    assert p["P"] == 2500 and p["L"] == 1.5
    ref = cantilever_reference(p)
    static = run.results["analyses"][0]
    assert static["type"] == "static"
    tip = static["displacements"]["tip"]["uy"]
    assert abs(tip / ref["tip"] - 1) < EXACT
    # The same tip from the nodal field and from the fields table along the line.
    u = run.displacements("static")
    tip_node = int(np.argmax(run.nodes[:, 0]))
    assert abs(u[tip_node, 1] / ref["tip"] - 1) < EXACT
    fields = run.tables["static"]["fields"]
    assert abs(fields["uy"][-1] / ref["tip"] - 1) < EXACT
    assert run.units["static"]["fields"]["uy"] == "m"
    # Bending moment along the line: linear, P (L - x), the root moment at x = 0.
    x, moment = fields["x"], fields["Mz"]
    assert np.max(np.abs(np.abs(moment) - p["P"] * (p["L"] - x))) < EXACT * ref["root_moment"]
    # Consistent mass, 16 elements: the first frequency within the deck's 1e-6.
    modal = run.results["analyses"][1]
    assert abs(modal["frequencies_hz"][0] / ref["f1"] - 1) < 1e-6
    assert len(run.tables["modal"]["modes"]["frequency"]) == 4


def test_catalogue_section_properties_and_pick():
    # steel_column.yaml takes HEB200 from the section catalogue; results.json carries its
    # properties in the tables' axes (y-y strong), SI units. The printed HE B 200 values are
    # the computed ones to half a unit of their last digit: 5696 cm^4 to 8.8e-5, 2003 cm^4 to
    # 2.5e-4, 642.5 cm^3 to 7.8e-5.
    run = beamrotor.solve(PROBLEMS / "steel_column.yaml")
    (section,) = run.results["catalog_sections"]
    assert section["designation"] == "HEB200" and section["name"] == "column"
    assert abs(section["Iy"] / 5696e-8 - 1) < 8.8e-5
    assert abs(section["Iz"] / 2003e-8 - 1) < 2.5e-4
    assert abs(section["Wpl_y"] / 642.5e-6 - 1) < 7.8e-5
    # `pick` chooses from the list by a parameter: 3 is HEB240, stiffer about y-y, so the
    # deflection in the web's plane falls as Iy rises (exactly, for these elements).
    bigger = beamrotor.solve(PROBLEMS / "steel_column.yaml", set={"size": 3})
    (other,) = bigger.results["catalog_sections"]
    assert other["designation"] == "HEB240"
    uy = run.results["analyses"][0]["displacements"]["end"]["uy"]
    uy_bigger = bigger.results["analyses"][0]["displacements"]["end"]["uy"]
    assert abs(uy_bigger / uy - section["Iy"] / other["Iy"]) < 1e-10


def test_pump_rod_published_reactions_over_a_sweep():
    sweep = beamrotor.solve(PROBLEMS / "pump_rod.yaml", sweep="eta=0,0.4")
    assert isinstance(sweep, beamrotor.Sweep)
    assert sweep.parameter == "eta" and list(sweep.values) == [0, 0.4]
    middle = [abs(r.results["analyses"][0]["reactions"]["middle"]["fy"]) for r in sweep.runs]
    # Published (problems/scenes/README.md section 1): 7.46 kN and 13.33 kN, to half a unit
    # of the last printed digit.
    assert abs(middle[0] - 7460) <= 5
    assert abs(middle[1] - 13330) <= 5
    assert all(r.passed for r in sweep.runs)


def test_reactions_are_linear_in_the_wear():
    one = beamrotor.solve(PROBLEMS / "pump_rod.yaml", set={"w0": 1e-3}, sweep_off=True)
    two = beamrotor.solve(PROBLEMS / "pump_rod.yaml", set={"w0": 2e-3}, sweep_off=True)
    r1 = one.results["analyses"][0]["reactions"]
    r2 = two.results["analyses"][0]["reactions"]
    for support, components in r1.items():
        for name, value in components.items():
            assert abs(r2[support][name] - 2 * value) <= 1e-12 * abs(value) + 1e-9


def test_checks_and_written_results_agree(tmp_path):
    run = beamrotor.solve(PROBLEMS / "pump_rod_hinged.yaml", sweep_off=True)
    assert run.passed
    assert all(c["pass"] for c in run.checks)
    run.write(tmp_path / "out")
    written = json.loads((tmp_path / "out" / "results.json").read_text())
    assert written["checks"] == run.checks
    assert written["analyses"][0]["reactions"] == run.results["analyses"][0]["reactions"]


def test_output_units_give_tables_in_them_and_leave_results_si(tmp_path):
    """units= sets run.tables' units (run.units names them); results stay SI. A length in mm
    is the SI value times 1000, an exact factor: bit for bit."""
    si = beamrotor.solve(PROBLEMS / "cantilever.yaml")
    mm = beamrotor.solve(PROBLEMS / "cantilever.yaml", units={"length": "mm", "force": "kN"})
    assert mm.units["static"]["fields"]["uy"] == "mm"
    assert mm.units["static"]["fields"]["Vy"] == "kN"
    assert mm.units["static"]["fields"]["Mz"] == "kN mm"
    assert np.array_equal(mm.tables["static"]["fields"]["uy"], si.tables["static"]["fields"]["uy"] * 1000)
    assert mm.results["analyses"][0]["displacements"] == si.results["analyses"][0]["displacements"]
    ref = cantilever_reference(si.parameters)
    assert abs(mm.tables["static"]["fields"]["uy"][-1] / (1000 * ref["tip"]) - 1) < EXACT
    # The same from the text form, and write() follows them into the CSV's units line.
    text = beamrotor.solve(PROBLEMS / "cantilever.yaml", units="length=mm,force=kN")
    assert np.array_equal(text.tables["static"]["fields"]["uy"], mm.tables["static"]["fields"]["uy"])
    text.write(tmp_path / "out", charts="none")
    lines = (tmp_path / "out" / "static_fields.csv").read_text().splitlines()
    assert lines[1].startswith("# units: mm,mm,mm,mm,rad,rad,rad,kN")
    # Speeds in Hz: a Campbell table's speed_rpm column is the rpm over 60.
    rotor = beamrotor.solve(PROBLEMS / "forme_shaft_rotor.yaml", sweep_off=True)
    hz = beamrotor.solve(PROBLEMS / "forme_shaft_rotor.yaml", sweep_off=True, units={"speed": "Hz"})
    name = [a for a in rotor.results["analyses"] if a["type"] == "campbell"][0]["name"]
    assert hz.units[name]["campbell"]["speed_rpm"] == "Hz"
    assert np.allclose(hz.tables[name]["campbell"]["speed_rpm"],
                       rotor.tables[name]["campbell"]["speed_rpm"] / 60, rtol=1e-15, atol=0)
    with pytest.raises(ValueError, match="is a force"):
        beamrotor.solve(PROBLEMS / "cantilever.yaml", units={"length": "kN"})


def test_rotor_campbell_tables():
    run = beamrotor.solve(PROBLEMS / "forme_shaft_rotor.yaml", sweep_off=True)
    campbell = [a for a in run.results["analyses"] if a["type"] == "campbell"][0]
    table = run.tables[campbell["name"]]["campbell"]
    speeds = table[next(iter(table))]
    assert isinstance(speeds, np.ndarray) and speeds.size > 10
    assert np.all(np.diff(speeds) > 0)


def test_run_up_tables_hold_the_passage_peak():
    """The run-up's amplitude per revolution peaks where results.json says, and the peak is the
    deck header's Runge-Kutta figure (0.6956 mm at 2638.7 rpm; the average acceleration rule's
    period error at its step is 5e-5)."""
    run = beamrotor.solve(PROBLEMS / "jeffcott_runup.yaml", sweep_off=True)
    table = run.tables["runup"]["runup"]
    peak = [a for a in run.results["analyses"] if a["type"] == "run-up"][0]["points"][0]
    i = int(np.argmax(table["disk_amplitude"]))
    assert table["disk_amplitude"][i] == peak["peak_amplitude"]
    assert table["speed_rpm"][i] == pytest.approx(peak["speed_at_peak_rpm"], rel=1e-12)
    assert peak["peak_amplitude"] == pytest.approx(0.6956e-3, rel=2e-3)
    assert peak["speed_at_peak_rpm"] == pytest.approx(2638.7, rel=1e-3)


def test_run_up_on_journal_films_driven_by_a_motor():
    """The journal deck's history: the speed ends where J Omega' = T0 (1 - Omega / Omega_s) - 2
    T_d(Omega) takes it with the journals at Ocvirk's equilibrium (2801.79 rpm, RK4: the deck's
    header), the drag is Petroff's 2 pi mu Omega R^3 L / c at least (the centred journal's), and
    the journals stay inside their clearance."""
    run = beamrotor.solve(PROBLEMS / "journal_runup.yaml", sweep_off=True)
    history = run.tables["films"]["runup_history"]
    w = history["speed"]
    assert history["speed_rpm"][-1] == pytest.approx(2801.79, rel=1e-4)
    petroff = 2 * 2 * np.pi * 0.02 * w * 0.015**3 * 0.012 / 40e-6
    assert np.all(history["film_torque"] > petroff)
    for bearing in ("left", "right"):
        assert np.all(history[bearing + "_eccentricity"] < 1)
        assert np.all(history[bearing + "_eccentricity"] > 0.3)


def test_run_up_on_tilting_pad_films():
    """The tilting-pad test deck (tests/problems/tilting_pad_runup.yaml): the pads' films reach
    Python's tables; the journals stay inside the bearing clearance, and the pads' drag exceeds
    the Couette shear of their arcs at a film of 2 c_p everywhere (thicker than any pad's film
    can be: H = 1 - (m + rho) cos - s sin < 2)."""
    run = beamrotor.solve(PROBLEMS.parent / "tests" / "problems" / "tilting_pad_runup.yaml",
                          sweep_off=True)
    history = run.tables["pads"]["runup_history"]
    w = history["speed"]
    cp = 40e-6 / 0.7  # c_p = c / (1 - m)
    least = 2 * 0.02 * w * 0.02**3 * 0.02 / cp * 4 * np.radians(80) / 2  # two bearings
    assert np.all(history["film_torque"] > least)
    for bearing in ("left", "right"):
        assert np.all(history[bearing + "_eccentricity"] < 1)
        assert np.all(history[bearing + "_eccentricity"] > 0)
        # Each pad's tilt (rad), a dof of the run, moves with the orbit; its film stays open at
        # both edges of the 80 deg arc (1 - a cos 40 - |s| sin 40 > 0, a < 1: |s| < 3.2), so
        # |tilt| = |t . u - s c_p| / R < (c + 3.2 c_p) / R < 5 c_p / R.
        for pad in range(1, 5):
            tilt = history[f"{bearing}_pad{pad}_tilt"]
            assert np.all(np.abs(tilt) < 5 * cp / 0.02)
            assert np.ptp(tilt) > 0


def test_rub_on_a_seal_brakes_the_spin():
    """The seal deck: the disk rests on the seal with the closed-form normal force (70.594 N),
    the friction is mu N and its torque mu N R throughout, and the speed grows at
    (T - mu N R) / J, as the deck's header derives."""
    run = beamrotor.solve(PROBLEMS / "jeffcott_rub.yaml", sweep_off=True)
    history = run.tables["rub"]["runup_history"]
    assert np.allclose(history["seal_normal_force"], 70.594, rtol=1e-5)
    assert np.allclose(history["seal_friction_force"], 0.2 * history["seal_normal_force"],
                       rtol=1e-5)
    assert np.allclose(history["seal_rub_torque"], 0.015 * history["seal_friction_force"],
                       rtol=1e-12)
    assert np.all(history["seal_radial"] > 0.1e-3)
    rate = np.diff(history["speed"]) / np.diff(history["time"])
    assert np.allclose(rate, (1 - 0.211783) / 0.1, rtol=1e-5)
    entry = [a for a in run.results["analyses"] if a["type"] == "run-up"][0]
    seal = entry["rubs"][0]
    assert seal["name"] == "seal" and seal["point"] == "disk"
    assert seal["contact_time"] == pytest.approx(0.3, rel=1e-12)
    assert seal["peak_normal_force"] == pytest.approx(70.594, rel=1e-5)


def test_torsion_of_two_disks(tmp_path):
    # Two disks (Jp 2 and 3 kg m^2) on a light round shaft (D 50 mm, 1 m, G 80 GPa), free:
    # omega^2 = k (J1 + J2) / (J1 J2), k = G pi D^4 / 32 / L; the shaft's inertia is 1e-12
    # of the disks', so the FE frequency agrees to round-off.
    deck = tmp_path / "train.yaml"
    deck.write_text(
        "model: {dimension: lateral}\n"
        "materials:\n  - {name: light, E: 208 GPa, G: 80 GPa, rho: 1e-6}\n"
        "sections:\n  - {name: shaft, shape: circle, D: 50 mm}\n"
        "segments:\n  - {name: shaft, length: 1, section: shaft, elements: 8}\n"
        "masses:\n  - {name: a, at: start, m: 10, Jp: 2, Jd: 1}\n"
        "  - {name: b, at: end, m: 10, Jp: 3, Jd: 1}\n"
        "analyses:\n  - {type: torsion, name: twist, modes: 2}\n")
    run = beamrotor.solve(deck)
    k = 80e9 * math.pi * 0.05**4 / 32
    f = math.sqrt(k * 5 / 6) / (2 * math.pi)
    entry = run.results["analyses"][0]
    assert entry["type"] == "torsion" and entry["free"] is True
    assert entry["frequencies_hz"][1] == pytest.approx(f, rel=1e-11)
    table = run.tables["twist"]["modes"]
    frequencies = table[next(c for c in table if c.startswith("frequency"))]
    assert frequencies[1] == pytest.approx(f, rel=1e-11)


def test_torsion_train_tables(tmp_path):
    # Two disks (J1 1, J2 0.5 kg m^2) on a light shaft (k_a = G pi D^4 / 32 / L) and a damped
    # coupling (kc, c) in series, a torque T cos(2 phi) on J1 at 1800 rpm: the torque in the
    # coupling is |T k J2 / (w^2 J1 J2 - k (J1 + J2))|, k = k_a z / (k_a + z), z = kc + i w c.
    J1, J2, D, L, kc, c, T = 1.0, 0.5, 0.04, 0.5, 2e4, 15.0, 100.0
    deck = tmp_path / "train.yaml"
    deck.write_text(
        "materials:\n  - {name: light, E: 208 GPa, G: 80 GPa, rho: 1e-6}\n"
        "sections:\n  - {name: s, shape: circle, D: 40 mm, material: light}\n"
        "train:\n  shafts:\n"
        "    - {name: a, segments: [{length: 0.5, section: s, elements: 4}],\n"
        "       disks: [{name: d1, at: 0, Jp: 1}]}\n"
        "    - {name: b, segments: [{length: 0.1, section: s, elements: 1}],\n"
        "       disks: [{name: d2, at: 0, Jp: 0.5}]}\n"
        "  couplings:\n    - {name: flex, from: a.end, to: b.d2, stiffness: 2e4, damping: 15}\n"
        "analyses:\n  - {type: torsion, name: twist, modes: 3, speed: 1800 rpm, orders: [2],\n"
        "     speeds: {from: 100 rpm, to: 3000 rpm, steps: 20},\n"
        "     torques: [{at: a.d1, order: 2, amplitude: 100 N m}]}\n")
    run = beamrotor.solve(deck)
    w = 2 * 1800 * 2 * math.pi / 60
    ka = 80e9 * math.pi * D**4 / 32 / L
    z = complex(kc, w * c)
    k = ka * z / (ka + z)
    closed = abs(T * k * J2 / (w * w * J1 * J2 - k * (J1 + J2)))
    train = run.results["analyses"][0]["train"]
    assert train["response"]["torques_n_m"]["flex"]["peak"] == pytest.approx(closed, rel=1e-9)
    response = run.tables["twist"]["response"]
    assert response["speed_rpm"].size == 21 and np.all(response["flex"] > 0)
    crossings = run.tables["twist"]["crossings"]
    assert crossings["speed_rpm"].size == 1
    # In kN m and rad/s: the response table's torques are the N m ones / 1000, its speeds the
    # rpm ones x pi/30; the torques table names each row's unit.
    kn = beamrotor.solve(deck, units={"force": "kN", "speed": "rad/s"})
    shown = kn.tables["twist"]["response"]
    assert kn.units["twist"]["response"]["flex"] == "kN m"
    assert kn.units["twist"]["response"]["speed_rpm"] == "rad/s"
    assert np.allclose(shown["flex"], response["flex"] / 1000, rtol=1e-15, atol=0)
    assert np.allclose(shown["speed_rpm"], response["speed_rpm"] * math.pi / 30, rtol=1e-15, atol=0)
    assert shown["flex"][-1] > 0 and shown["speed_rpm"][-1] == pytest.approx(3000 * math.pi / 30, rel=1e-12)
    torques = kn.tables["twist"]["torques"]
    assert set(torques["quantity"]) == {"torque kN m", "twist rad"}


def test_spring_force_of_a_propped_cantilever(tmp_path):
    # A cantilever (EI, L) propped at its tip by a spring of k = 3 EI / L^3, the tip stiffness:
    # the spring takes half the tip load P (compatibility), exact with Hermite elements but for
    # round-off.
    E, I, L, P = 210e9, 8356e-8, 4.0, 10e3
    k = 3 * E * I / L**3
    deck = tmp_path / "prop.yaml"
    deck.write_text(
        "model: {dimension: planar}\n"
        f"materials: [{{name: steel, E: {E!r}, nu: 0.3}}]\n"
        f"sections: [{{name: b, shape: general, A: 5e-3, I: {I!r}, J: 1e-6, depth: 0.3}}]\n"
        f"nodes: [{{name: A, at: [0, 0]}}, {{name: B, at: [{L!r}, 0]}}]\n"
        "members: [{name: beam, from: A, to: B, section: b, elements: 2}]\n"
        "supports: [{name: A, at: A, fix: clamped}]\n"
        f"springs: [{{name: prop, at: B, dof: uy, k: {k!r}}}]\n"
        f"loads: [{{type: point, at: B, fy: {-P!r}}}]\n")
    run = beamrotor.solve(deck)
    static = run.results["analyses"][0]
    assert static["springs"]["prop"]["fy"] == pytest.approx(P / 2, rel=EXACT)
    table = run.tables["static"]["springs"]
    assert list(table["spring"]) == ["prop"]
    assert table["force"][0] == pytest.approx(P / 2, rel=EXACT)
    assert run.units["static"]["springs"]["force"] == "N"


def numbers_of(run):
    """A run's results and tables without the times it took, tables as plain lists."""
    def untimed(x):
        if isinstance(x, dict):
            return {k: untimed(v) for k, v in x.items() if k not in ("time_s", "seconds")}
        if isinstance(x, list):
            return [untimed(v) for v in x]
        return x
    tables = {a: {t: {c: list(v) for c, v in cols.items()} for t, cols in ts.items()}
              for a, ts in run.tables.items()}
    return untimed(run.results), tables


def test_threads_solving_at_once_get_what_one_alone_gets():
    # solve() lets go of the GIL while a deck solves, so Python threads solve side by side.
    # The compressor deck runs ARPACK (rotor modes, Campbell, maps) and UMFPACK (fluid-film
    # bearings, unbalance), which call BLAS. Before ARPACK's runs took turns and BLAS was a
    # build that may be called from two threads, such pairs crashed the interpreter (a
    # corrupted heap), deadlocked, or returned other log decrements (-inf, inf) in 1 or 2 of
    # 6 runs: every run here must equal the lone one to the last bit.
    from concurrent.futures import ThreadPoolExecutor
    deck = PROBLEMS / "compressor_rotor.yaml"
    alone = numbers_of(beamrotor.solve(deck))
    with ThreadPoolExecutor(2) as pool:
        side_by_side = list(pool.map(lambda _: numbers_of(beamrotor.solve(deck)), range(6)))
    for run in side_by_side:
        assert run == alone


def test_bad_input_raises_deck_error_with_its_place(tmp_path):
    deck = tmp_path / "bad.yaml"
    deck.write_text("parameters:\n  L: 1\nsegments:\n  - {length: -L, section: rod, elements: 2}\n")
    with pytest.raises(beamrotor.DeckError) as error:
        beamrotor.solve(deck)
    e = error.value
    assert isinstance(e, ValueError)
    assert e.file == str(deck)
    assert e.line >= 1
    assert str(e).startswith(f"{deck}:{e.line}:")


def test_unknown_parameter_is_bad_input():
    with pytest.raises(beamrotor.DeckError) as error:
        beamrotor.solve(PROBLEMS / "cantilever.yaml", set={"nonsense": 1})
    assert "nonsense" in str(error.value)


def test_a_mechanism_raises_solve_error():
    with pytest.raises(beamrotor.SolveError) as error:
        beamrotor.solve(MALFORMED / "unsupported_structure.yaml")
    assert isinstance(error.value, RuntimeError)
    assert error.value.message


def test_set_refuses_what_is_not_a_number_or_expression():
    with pytest.raises(TypeError):
        beamrotor.solve(PROBLEMS / "cantilever.yaml", set={"P": [1, 2]})


def csv_header_and_rows(path):
    """The names line and the number of rows (the units line, a comment, is no row)."""
    lines = [line for line in path.read_text().splitlines() if not line.startswith("#")]
    return lines[0], len(lines) - 1


@pytest.mark.parametrize("deck", ["continuous_beam.yaml", "compressor_rotor.yaml"])
def test_csv_tables_read_by_numpy_as_written(tmp_path, deck):
    """numpy.genfromtxt(names=True) reads every CSV table of a results directory with the
    column names as run.tables has them (no unit fused into a name, no quotes kept in text),
    and its numbers bit for bit."""
    run = beamrotor.solve(PROBLEMS / deck, sweep_off=True)
    run.write(tmp_path / "out", charts="none")
    name = next(iter(run.tables))
    stem = re.sub(r"[^A-Za-z0-9._-]", "_", name)
    for key, table in run.tables[name].items():
        path = tmp_path / "out" / f"{stem}_{key}.csv"
        read = np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8",
                                deletechars="", replace_space="_")
        assert list(read.dtype.names) == [c.replace(" ", "_") for c in table], path.name
        for column, values in table.items():
            got = np.atleast_1d(read[column.replace(" ", "_")])
            if getattr(values, "dtype", None) is not None and values.dtype.kind == "f":
                same = (got == values) | (np.isnan(got) & np.isnan(values))
                assert same.all(), (path.name, column)
            else:
                assert [str(v) for v in got] == [str(v) for v in values], (path.name, column)


@pytest.mark.parametrize("deck", ["continuous_beam.yaml", "compressor_rotor.yaml",
                                  "forme_shaft_rotor.yaml", "portal_frame.yaml",
                                  "snt32_drive.yaml", "mo10_steady.yaml", "pump_rod.yaml",
                                  "jeffcott_runup.yaml", "jeffcott_rub.yaml",
                                  "machine_base_frame.yaml"])
def test_tables_hold_every_table_the_command_line_writes(tmp_path, deck):
    """Every CSV file of the results directory is a table of run.tables, with its columns and
    rows: the load cases, the bearing loads, the critical-speed map and the orbits too."""
    run = beamrotor.solve(PROBLEMS / deck, sweep_off=True)
    run.write(tmp_path / "out", charts="none")
    written = sorted((tmp_path / "out").glob("*.csv"))
    assert written
    # The files' stems: the analysis' name, characters other than letters, digits, - _ . as _.
    stems = {name: re.sub(r"[^A-Za-z0-9._-]", "_", name) for name in run.tables}
    found = 0
    for path in written:
        owners = [name for name, stem in stems.items() if path.name.startswith(stem + "_")]
        assert owners, path.name
        name = max(owners, key=len)
        key = path.name[len(stems[name]) + 1:-len(".csv")]
        assert key in run.tables[name], (path.name, list(run.tables[name]))
        table = run.tables[name][key]
        _, rows = csv_header_and_rows(path)
        assert len(table) == len(run.units[name][key])
        assert all(len(column) == rows for column in table.values()), path.name
        found += 1
    assert found == sum(len(tables) for tables in run.tables.values())


def test_a_python_without_numpy_gets_an_error_naming_numpy_and_the_python(tmp_path):
    code = ("import sys; sys.modules['numpy'] = None\n"
            "try:\n    import beamrotor\n"
            "except ImportError as e:\n    print(e)\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=dict(os.environ))
    message = done.stdout
    assert "beamrotor needs NumPy" in message, (done.stdout, done.stderr)
    built = f"{sys.version_info.major}.{sys.version_info.minor}"
    assert f"built for Python {built}" in message
    assert sys.executable in message
    assert "python3-numpy" in message


def read_study_csv(path):
    """study.csv as {column: list of cells}, numbers as floats (the file's shortest exact
    decimals read back), empty cells as NaN, text as str."""
    import csv
    with open(path, newline="") as f:
        rows = [row for row in csv.reader(f) if not (row and row[0].startswith("#"))]
    columns = {}
    for k, name in enumerate(rows[0]):
        cells = [row[k] for row in rows[1:]]
        try:
            columns[name] = [float(c) if c else math.nan for c in cells]
        except ValueError:
            columns[name] = cells
    return columns


def test_study_gives_the_command_lines_table_to_the_bit(tmp_path):
    """beamrotor.study against `beamrotor study` with the same grid: every column of the table
    equal bit for bit, the same summary, and the worst point's run at the worst parameters."""
    deck = PROBLEMS / "pump_rod.yaml"
    grid = ["eta=0:0.4:4", "w0=0.5e-3:1.5e-3:2"]
    outputs = ["stress max <= 60 MPa"]
    study = beamrotor.study(deck, sweep=grid, outputs=outputs, threads=2)
    command = [os.environ["BEAMROTOR_EXE"], "study", str(deck), "--out", str(tmp_path / "cli")]
    for axis in grid:
        command += ["--sweep", axis]
    command += ["--output", outputs[0]]
    subprocess.run(command, check=True, capture_output=True)
    expected = read_study_csv(tmp_path / "cli" / "study.csv")
    assert list(study.table) == list(expected)
    # Rows in point order (threads may finish points in another order).
    ours_order = np.argsort(study.table["point"], kind="stable")
    theirs_order = np.argsort(np.array(expected["point"]), kind="stable")
    for name, cells in expected.items():
        ours = study.table[name]
        cells = [cells[i] for i in theirs_order]
        if isinstance(ours, np.ndarray):
            ours = ours[ours_order]
            theirs = np.array(cells, dtype=float)
            assert ours.shape == theirs.shape, name
            same = (ours == theirs) | (np.isnan(ours) & np.isnan(theirs))
            assert same.all(), name
        else:
            assert [ours[i] for i in ours_order] == cells, name
    assert len(study.table["point"]) == 15
    summary = json.loads((tmp_path / "cli" / "summary.json").read_text())
    assert study.summary["points"] == summary["points"] == 15
    assert study.summary["worst_point"]["parameters"] == summary["worst_point"]["parameters"]
    worst = study.worst
    for name, value in summary["worst_point"]["parameters"].items():
        assert worst.parameters[name] == value
    written = json.loads((tmp_path / "cli" / "worst" / "results.json").read_text())
    assert worst.results["analyses"][0]["reactions"] == written["analyses"][0]["reactions"]
    assert study.directory is None


def test_spectrum_combinations_table():
    # problems/machine_base_frame.yaml's quake: directions x and z by 100/30. Its sway modes
    # are along x or z alone, so E_x's base force along x is M Sa (Sa = 2.5 ag S on the
    # plateau, S = 1.15 on ground C) and E_z's along x is 0: the combination led by x gives
    # M Sa along x, the one led by z 0.3 M Sa. Each quantity's governing row holds its largest.
    run = beamrotor.solve(PROBLEMS / "machine_base_frame.yaml")
    table = run.tables["quake"]["spectrum_combinations"]
    p = run.parameters
    MSa = p["M"] * 2.5 * p["ag"] * 1.15
    rows = list(zip(table["combination"], table["quantity"], table["component"],
                    table["value"], table["governs"]))
    base_x = {c: v for c, q, k, v, g in rows if q == "base_force" and k == "x"}
    assert abs(base_x["x + 0.3 z"] / MSa - 1) < EXACT
    assert abs(base_x["z + 0.3 x"] / (0.3 * MSa) - 1) < EXACT
    for i in range(0, len(rows), 2):
        pair = rows[i:i + 2]
        assert pair[0][1:3] == pair[1][1:3]
        best = max(r[3] for r in pair)
        assert sum(r[4] for r in pair) == 1
        assert all(r[3] == best for r in pair if r[4] == 1)
    entry = next(a for a in run.results["analyses"] if a["name"] == "quake")
    assert [c["name"] for c in entry["combinations"]] == ["x + 0.3 z", "z + 0.3 x"]


def test_moving_load_with_the_deck_loads():
    # problems/crane_girder.yaml's analysis with_weight: the girder's self-weight q = rho A g
    # stands while the trolley runs, adding its own moment q x (L - x) / 2 at `under` (x there)
    # to the position rule's; the wheels' governing place is the same. Exact: round-off.
    run = beamrotor.solve(PROBLEMS / "crane_girder.yaml")
    p = run.parameters
    x = p["L"] / 2 - p["a"] / 4
    rule = p["P"] * x**2 * 2 / p["L"]
    q = 7850 * p["A"] * 9.81
    weight = q * x * (p["L"] - x) / 2
    alone = run.tables["trolley"]["envelopes"]
    both = run.tables["with_weight"]["envelopes"]
    assert abs(both["deck_loads"][0] / weight - 1) < EXACT
    assert abs(both["max"][0] / (rule + weight) - 1) < EXACT
    assert alone["deck_loads"][0] == 0
    assert both["first_wheel_at_max"][0] == alone["first_wheel_at_max"][0]
    entry = run.results["analyses"][1]
    assert entry["deck_loads"] is True
    assert entry["files"]["envelope_vtu"] == "with_weight_envelope.vtu"


def test_moving_load_tables_and_envelope():
    # problems/crane_girder.yaml: two wheels P at spacing a on a simply supported span L. The
    # largest moment by the position rule, P (L/2 - a/4)^2 * 2 / L, under the wheel at
    # x = L/2 - a/4; the influence line of the moment there peaks at x (L - x) / L per newton.
    # Both exact (cubics per element, extremes in closed form): round-off only.
    run = beamrotor.solve(PROBLEMS / "crane_girder.yaml")
    p = run.parameters
    x = p["L"] / 2 - p["a"] / 4
    rule = p["P"] * x**2 * 2 / p["L"]
    envelopes = run.tables["trolley"]["envelopes"]
    assert abs(envelopes["max"][0] / rule - 1) < EXACT
    assert abs(envelopes["first_wheel_at_max"][0] - (x + p["a"])) < EXACT * p["L"]
    line = run.tables["trolley"]["influence"]
    peak = np.max(line["resultant_Mz_at_under"])
    assert abs(peak / (x * (p["L"] - x) / p["L"]) - 1) < EXACT
    moving = run.results["analyses"][0]
    assert moving["type"] == "moving-load"
    assert abs(moving["quantities"][0]["max"]["value"] / rule - 1) < EXACT


def cantilever_tip(length):
    """The cantilever deck's tip deflection, -P L^3 / (3 E I) in m (P = 1 kN, E = 210 GPa,
    D = 50 mm)."""
    return -1000.0 * length**3 / (3 * 210e9 * math.pi * 0.05**4 / 64)


def test_check_in_output_units_is_si_times_the_factor():
    """check(units=) against check() in SI: lengths x 1000, forces / 1000, moments in kN mm
    (x 1), rotations as they are; a zero-reference check's absolute error and tolerance follow
    its unit. The SI values are the closed forms to the deck's 1e-9."""
    si = beamrotor.check(PROBLEMS / "cantilever.yaml")
    mm = beamrotor.check(PROBLEMS / "cantilever.yaml", units={"length": "mm", "force": "kN"})
    assert [c["name"] for c in mm] == [c["name"] for c in si]
    by_name = {c["name"]: (a, c) for a, c in zip(si, mm)}
    a, b = by_name["tip deflection"]
    assert a["unit"] == "m" and b["unit"] == "mm"
    assert b["computed"] == a["computed"] * 1000  # 1000 is exact: bit for bit
    assert b["reference"] == a["reference"] * 1000
    assert abs(a["computed"] / cantilever_tip(1.2) - 1) < EXACT
    assert not b["absolute"] and b["error"] == a["error"] and b["tolerance"] == 1e-9
    a, b = by_name["root force"]
    assert (a["unit"], b["unit"]) == ("N", "kN")
    assert b["reference"] == pytest.approx(a["reference"] / 1000, rel=1e-15)
    assert b["reference"] == pytest.approx(1.0, rel=1e-15)  # P = 1 kN
    a, b = by_name["root moment"]
    assert (a["unit"], b["unit"]) == ("N m", "kN mm")
    assert b["reference"] == pytest.approx(1200.0, rel=1e-15)  # P L = 1.2 kN m
    a, b = by_name["tip rotation"]
    assert a["unit"] == b["unit"] == "rad" and b["computed"] == a["computed"]
    assert all(c["pass"] for c in mm)
    # A string of units as --units takes it; a sweep names each value in the units.
    swept = beamrotor.check(PROBLEMS / "cantilever.yaml", sweep="L=1m,1.2m", units="length=mm")
    tips = [c for c in swept if c["name"] == "tip deflection"]
    assert [t["at"]["value"] for t in tips] == [1000.0, 1200.0]
    assert {t["at"]["unit"] for t in tips} == {"mm"} and tips[0]["at"]["parameter"] == "L"
    for tip, length in zip(tips, (1.0, 1.2)):
        assert abs(tip["computed"] / (1000 * cantilever_tip(length)) - 1) < EXACT
    with pytest.raises(ValueError, match="length"):
        beamrotor.check(PROBLEMS / "cantilever.yaml", units={"length": "kN"})


def test_converge_in_output_units_is_si_times_the_factor(tmp_path):
    """converge(units=): each method's value column in mm is convergence.json's SI value x 1000
    (bit for bit), its time columns in ms; written, the table and chart say so."""
    study = beamrotor.converge(PROBLEMS / "cantilever.yaml", quantity="displacement tip uy",
                               levels=2, repeats=1, out=tmp_path / "c",
                               units={"length": "mm", "time": "ms"})
    method = study.results["methods"][0]
    table = study.tables[method["name"]]
    assert study.units[method["name"]]["value"] == "mm"
    assert study.units[method["name"]]["total"] == "ms"
    values = [level["value"] for level in method["levels"]]
    assert list(table["value"]) == [v * 1000 for v in values]
    assert abs(table["value"][0] / (1000 * cantilever_tip(1.2)) - 1) < EXACT
    total = [level["time_s"]["total"] for level in method["levels"]]
    assert table["total"] == pytest.approx([t * 1000 for t in total], rel=1e-15)
    written = np.genfromtxt(tmp_path / "c" / ("convergence_" + method["name"] + ".csv"),
                            delimiter=",", names=True)
    assert list(written["value"]) == list(table["value"])
    chart = (tmp_path / "c" / "convergence_time.gp").read_text()
    assert "wall time (total) [ms]" in chart


def test_overlay_in_output_units_is_si_times_the_factor(tmp_path):
    """overlay(units=): each deck's fields table in mm and kN is the SI table times the exact
    factors (x 1000 bit for bit, / 1000 to one rounding); the tip is the closed form."""
    decks = [PROBLEMS / "cantilever.yaml", PROBLEMS / "simply_supported.yaml"]
    si = beamrotor.overlay(decks)
    mm = beamrotor.overlay(decks, units="length=mm,force=kN", out=tmp_path / "o",
                           quantity="deflection")
    assert set(mm.tables) == {"cantilever", "simply_supported"}
    a, b = si.tables["cantilever"], mm.tables["cantilever"]
    assert si.units["cantilever"]["uy"] == "m" and mm.units["cantilever"]["uy"] == "mm"
    assert mm.units["cantilever"]["Vy"] == "kN"
    assert list(b["uy"]) == [v * 1000 for v in a["uy"]]
    assert list(b["x"]) == [v * 1000 for v in a["x"]]
    assert b["Vy"] == pytest.approx(a["Vy"] / 1000, rel=1e-15)
    assert abs(b["uy"][-1] / (1000 * cantilever_tip(1.2)) - 1) < EXACT
    written = (tmp_path / "o" / "overlay.gp").read_text()
    assert "deflection [mm]" in written
    assert (tmp_path / "o" / "cantilever_fields.csv").exists()
    with pytest.raises(ValueError, match="quantity"):
        beamrotor.overlay(decks, quantity="torque")


def test_study_table_names_its_units_and_genfromtxt_reads_it(tmp_path):
    """study(units=): the table stays in the units study.csv names (SI), bit for bit the same
    as without units; genfromtxt(names=True) reads the written file to the same numbers; the
    worst point's Run is in the units chosen."""
    deck = PROBLEMS / "pump_rod.yaml"
    grid = ["eta=0:0.4:2", "w0=0.5e-3:1.5e-3:1"]
    plain = beamrotor.study(deck, sweep=grid, outputs=["stress max"])
    shown = beamrotor.study(deck, sweep=grid, outputs=["stress max"], out=tmp_path / "s",
                            units={"length": "mm", "stress": "MPa"})
    assert shown.units["eta"] == "m" and shown.units["stress max"] == "Pa"
    assert shown.units["status"] == ""
    for name, column in plain.table.items():
        if isinstance(column, np.ndarray):
            assert np.array_equal(shown.table[name], column, equal_nan=True)
    read = np.genfromtxt(tmp_path / "s" / "study.csv", delimiter=",", names=True,
                         dtype=None, encoding="utf-8")
    assert read.dtype.names[:3] == ("point", "eta", "w0")
    assert list(read["eta"]) == list(shown.table["eta"])
    assert list(read["stress_max"]) == list(shown.table["stress max"])
    assert shown.summary["outputs"][0]["unit"] == "Pa"
    assert shown.worst.units["bending"]["fields"]["x"] == "mm"
    assert plain.worst.units["bending"]["fields"]["x"] == "m"
