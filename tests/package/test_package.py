"""The installed package against the build tree: `cmake --install` into a temporary prefix and
the .deb CPack builds, unpacked with dpkg-deb, must each run a shipped deck to the very same
results (same code, same libraries: tables byte for byte, results.json equal but for its
wall-clock times; not within a tolerance), import as a Python
module, and (the .deb) declare the Debian runtime packages it needs. Installed, `--help`
names the installed examples; the .deb ships the ParaView script and the manual page."""
import filecmp
import json
import os
import pathlib
import subprocess
import sys

SOURCE = pathlib.Path(os.environ["BEAMROTOR_SOURCE_DIR"])
BUILD = pathlib.Path(os.environ["BEAMROTOR_BUILD_DIR"])
DECK = "cantilever.yaml"
# Files a results directory holds whose bytes depend only on the numbers (charts are drawn by
# gnuplot, which may or may not be installed, so they are left out).
COMPARED = (".json", ".csv", ".vtu", ".pvd")


def run(*args, **kwargs):
    done = subprocess.run(args, capture_output=True, text=True, **kwargs)
    assert done.returncode == 0, f"{args}: exit {done.returncode}\n{done.stdout}\n{done.stderr}"
    return done


def solve(executable, deck, out):
    run(str(executable), "solve", str(deck), "--out", str(out))
    return out


# Wall-clock times in results.json, the only numbers that differ between two runs.
TIMINGS = {"seconds", "time_s"}


def without_timings(document):
    if isinstance(document, dict):
        return {k: without_timings(v) for k, v in document.items() if k not in TIMINGS}
    if isinstance(document, list):
        return [without_timings(v) for v in document]
    return document


def assert_same_results(installed, reference):
    names = sorted(p.name for p in reference.iterdir() if p.suffix in COMPARED)
    assert "results.json" in names and any(n.endswith(".csv") for n in names)
    tables = [n for n in names if not n.endswith(".json")]
    match, mismatch, errors = filecmp.cmpfiles(reference, installed, tables, shallow=False)
    assert mismatch == [] and errors == [], (mismatch, errors)
    assert match == tables
    for name in names:
        if name.endswith(".json"):
            ours = json.loads((installed / name).read_text())
            theirs = json.loads((reference / name).read_text())
            assert without_timings(ours) == without_timings(theirs), name


def python_module(directory):
    found = list(directory.glob("beamrotor*.so"))
    assert len(found) == 1, found
    return found[0]


def assert_module_solves(site, deck):
    env = dict(os.environ, PYTHONPATH=str(site), PYTHONDONTWRITEBYTECODE="1")
    code = ("import beamrotor, sys; r = beamrotor.solve(sys.argv[1]); "
            "print(beamrotor.__file__); print(r.results['analyses'][0]['reactions'])")
    done = run(sys.executable, "-c", code, str(deck), env=env)
    assert done.stdout.splitlines()[0].startswith(str(site))
    return done.stdout.splitlines()[1]


def reference_module_answer(deck):
    return assert_module_solves(BUILD / "python", deck)


def assert_help_names_examples(executable, examples):
    """--help names the examples directory beside the installed executable."""
    text = " ".join(run(str(executable), "--help").stdout.split())
    assert str(examples.resolve()) in text, text


def test_cmake_install_runs_like_the_build_tree(tmp_path):
    prefix = tmp_path / "prefix"
    run("cmake", "--install", str(BUILD), "--prefix", str(prefix))
    examples = prefix / "share" / "beamrotor" / "examples"
    assert sorted(p.name for p in examples.glob("*.yaml")) == sorted(
        p.name for p in (SOURCE / "problems").glob("*.yaml"))
    for doc in ("README.md", "FORMAT.md", "scenes.md"):
        assert (prefix / "share" / "doc" / "beamrotor" / doc).is_file()
    assert (prefix / "share" / "beamrotor" / "open_results.py").is_file()
    assert_help_names_examples(prefix / "bin" / "beamrotor", examples)
    deck = examples / DECK
    installed = solve(prefix / "bin" / "beamrotor", deck, tmp_path / "installed")
    reference = solve(BUILD / "beamrotor", deck, tmp_path / "reference")
    assert_same_results(installed, reference)
    site = prefix / "lib" / "python3" / "dist-packages"
    python_module(site)
    assert assert_module_solves(site, deck) == reference_module_answer(deck)


def vtk_runtime_package():
    """The package whose VTK libraries the build links: ParaView's (`paraview`) when CMake took
    the VTK of paraview-dev (README: Which VTK), else Debian's libvtk9.x."""
    cache = (BUILD / "CMakeCache.txt").read_text()
    vtk_dir = next((line.partition("=")[2] for line in cache.splitlines()
                    if line.startswith("VTK_DIR:")), "")
    return "paraview" if "/paraview-" in vtk_dir else "libvtk9"


def test_deb_unpacks_runs_and_names_its_runtime_packages(tmp_path):
    run("cpack", "--config", str(BUILD / "CPackConfig.cmake"), "-B", str(tmp_path / "deb"))
    debs = list((tmp_path / "deb").glob("beamrotor_*.deb"))
    assert len(debs) == 1, debs
    info = run("dpkg-deb", "-I", str(debs[0])).stdout
    fields = {}
    for line in info.splitlines():
        key, _, value = line.strip().partition(":")
        fields.setdefault(key, value.strip())
    depends = [d.strip().split(" ")[0] for d in fields["Depends"].split(",")]
    # The runtime libraries beamrotor links, by their Debian 12 package names (prefixes, so a
    # later soname bump still reads right), and what the Python module needs.
    for needed in ("libumfpack", "libcholmod", "libspqr", "libarpack2", "libyaml-cpp",
                   "libmuparser", vtk_runtime_package(), "python3", "python3-numpy"):
        assert any(d.startswith(needed) for d in depends), (needed, depends)
    assert "gnuplot" in fields["Recommends"]
    assert fields["Package"] == "beamrotor"

    root = tmp_path / "root"
    run("dpkg-deb", "-x", str(debs[0]), str(root))
    usr = root / "usr"
    assert (usr / "share" / "beamrotor" / "open_results.py").is_file()
    manual = usr / "share" / "man" / "man1" / "beamrotor.1"
    assert manual.is_file()
    assert "beamrotor solve" in manual.read_text() and "examples" in manual.read_text()
    assert_help_names_examples(usr / "bin" / "beamrotor", usr / "share" / "beamrotor" / "examples")
    deck = usr / "share" / "beamrotor" / "examples" / DECK
    installed = solve(usr / "bin" / "beamrotor", deck, tmp_path / "installed")
    reference = solve(BUILD / "beamrotor", deck, tmp_path / "reference")
    assert_same_results(installed, reference)
    site = usr / "lib" / "python3" / "dist-packages"
    assert assert_module_solves(site, deck) == reference_module_answer(deck)
