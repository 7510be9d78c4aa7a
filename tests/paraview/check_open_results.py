"""CTest `paraview`: problems/output/paraview/open_results.py run headless by pvpython.

Solves two frame decks (static: tubes coloured by stress), a modal deck, a rotor deck and a
time series (the cantilever under a suddenly applied load), lets the script render
each to a PNG and save a ParaView state, and checks what came out: the picture has the asked
size, is not one colour, has a white background, a coloured structure (the colour map) and dark
text (title and legend); the state names the radius and colour arrays. The pictures are kept in
<build>/paraview-pictures/ to be looked at.

Exit 77 (CTest: skipped) with the reason when pvpython is missing (ParaView not installed) or
when there is no display and no Xvfb to make one.

    python3 tests/paraview/check_open_results.py --exe build/beamrotor --out build/paraview-pictures
"""
import argparse
import os
import pathlib
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

SKIP = 77
SOURCE = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = SOURCE / "problems/output/paraview/open_results.py"
WIDTH, HEIGHT = 900, 560
SWING = """
analyses:
  - type: transient
    name: swing
    scheme: newmark
    dt: 1e-4
    end: 0.04
    frames: 20
    loads:
      - {at: tip, dof: uy, pieces: [{from: 0, value: -P}]}
"""


def read_png(path):
    """(width, height, rows of (r, g, b) tuples) of an 8-bit RGB or RGBA PNG."""
    data = path.read_bytes()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise AssertionError(f"{path} is not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour_type, _, _, interlace = header
    if depth != 8 or colour_type not in (2, 6) or interlace:
        raise AssertionError(f"{path}: unexpected PNG layout {header}")
    channels = 3 if colour_type == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        line = raw[y * (stride + 1):(y + 1) * (stride + 1)]
        kind, row = line[0], bytearray(line[1:])
        for x in range(stride):
            left = row[x - channels] if x >= channels else 0
            up = previous[x]
            corner = previous[x - channels] if x >= channels else 0
            if kind == 1:
                row[x] = (row[x] + left) & 255
            elif kind == 2:
                row[x] = (row[x] + up) & 255
            elif kind == 3:
                row[x] = (row[x] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                pred = left if pa <= pb and pa <= pc else up if pb <= pc else corner
                row[x] = (row[x] + pred) & 255
        rows.append([tuple(row[i:i + 3]) for i in range(0, stride, channels)])
        previous = row
    return width, height, rows


def check_picture(path, what):
    width, height, rows = read_png(path)
    assert (width, height) == (WIDTH, HEIGHT), f"{what}: {width} x {height}, asked {WIDTH} x {HEIGHT}"
    pixels = [p for row in rows for p in row]
    colours = set(pixels)
    white = sum(1 for p in pixels if min(p) >= 245) / len(pixels)
    # The structure, not the legend (which stands at the right edge): coloured pixels in the
    # left four fifths of the picture.
    body = [p for row in rows for p in row[:width * 4 // 5]]
    saturated = sum(1 for p in body if max(p) - min(p) >= 100) / len(body)
    dark = sum(1 for p in pixels if max(p) <= 80) / len(pixels)
    print(f"{what}: {path.name} {width} x {height}, {len(colours)} colours, white {white:.1%}, "
          f"coloured {saturated:.2%}, dark {dark:.2%}")
    assert len(colours) >= 50, f"{what}: only {len(colours)} colours: an empty or flat picture"
    assert 0.3 <= white <= 0.995, f"{what}: white background covers {white:.1%}"
    assert saturated >= 0.005, f"{what}: no coloured structure ({saturated:.2%} coloured pixels)"
    assert dark >= 0.0005, f"{what}: no text (title, legend) in the picture"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", required=True, help="the beamrotor executable")
    parser.add_argument("--out", required=True, type=pathlib.Path, help="where pictures go")
    args = parser.parse_args()

    pvpython = shutil.which("pvpython")
    if not pvpython:
        print("SKIPPED: pvpython not found: ParaView is not installed (Debian: paraview and "
              "python3-paraview); the ParaView script was not run")
        return SKIP
    command = [pvpython, "--force-offscreen-rendering"]
    server = None
    if not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
        if not shutil.which("Xvfb"):
            print("SKIPPED: no display and no Xvfb (Debian: xvfb) for ParaView's OpenGL; "
                  "the ParaView script was not run")
            return SKIP
        server = start_xvfb()
    try:
        return run_cases(args, command)
    finally:
        if server:
            server.terminate()
            server.wait(timeout=30)


def start_xvfb():
    """A virtual X server on a display number it finds free itself (-displayfd): numbers
    chosen by looking at lock files can be taken by a server in another file system root."""
    read_end, write_end = os.pipe()
    server = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0",
                               "1280x1024x24", "-nolisten", "tcp", "-noreset"], pass_fds=(write_end,),
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_end)
    with os.fdopen(read_end) as pipe:
        number = pipe.readline().strip()
    if not number:
        server.kill()
        raise AssertionError("Xvfb did not start")
    os.environ["DISPLAY"] = f":{number}"
    print(f"paraview: Xvfb on display :{number}")
    return server


def run_cases(args, command):
    args.out.mkdir(parents=True, exist_ok=True)

    cases = [  # deck, analysis, extra options, what the state must name
        ("portal_frame", None, ["--scale", "20"], ["tube_radius", "stress_MPa"]),
        ("frame3d", None, [], ["tube_radius", "stress_MPa"]),
        ("cantilever", "modal", ["--mode", "2"], ["tube_radius", "shape_magnitude"]),
        ("forme_shaft_rotor", "at-speed", [], ["tube_radius", "shape_magnitude"]),
        ("swing", "swing", [], ["tube_radius", "displacement_mm"]),
    ]
    with tempfile.TemporaryDirectory() as work:
        work = pathlib.Path(work)
        # A time series of beams: the cantilever under its tip load applied at t = 0.
        cantilever = (SOURCE / "problems/cantilever.yaml").read_text()
        (work / "swing.yaml").write_text(cantilever[:cantilever.index("\nloads:")] + SWING)
        for deck, analysis, options, names in cases:
            results = work / deck
            deck_file = work / "swing.yaml" if deck == "swing" else SOURCE / f"problems/{deck}.yaml"
            subprocess.run([args.exe, "solve", str(deck_file), "--out", str(results)],
                           check=True, stdout=subprocess.DEVNULL)
            png = args.out / f"{deck}{'_' + analysis if analysis else ''}.png"
            state = work / f"{deck}.pvsm"
            png.unlink(missing_ok=True)
            run = command + [str(SCRIPT), str(results), "--png", str(png), "--state", str(state),
                             "--size", str(WIDTH), str(HEIGHT)] + options
            if analysis:
                run += ["--analysis", analysis]
            done = subprocess.run(run, capture_output=True, text=True, timeout=300)
            if done.returncode != 0 or not png.exists():
                print(done.stdout, done.stderr, sep="\n")
                raise AssertionError(f"{deck}: open_results.py exit {done.returncode}, "
                                     f"picture {'written' if png.exists() else 'missing'}")
            check_picture(png, deck)
            text = state.read_text()
            for name in names:
                assert name in text, f"{deck}: the state does not name {name}"
        # A mode swinging: --frames writes that many pictures, and they differ.
        frames = args.out / "cantilever_swing.png"
        run = command + [str(SCRIPT), str(work / "cantilever"), "--analysis", "modal",
                         "--png", str(frames), "--frames", "4", "--size", str(WIDTH), str(HEIGHT)]
        subprocess.run(run, check=True, capture_output=True, timeout=300)
        pictures = [frames.with_name(f"cantilever_swing_{k:03d}.png") for k in range(4)]
        assert all(p.exists() for p in pictures), "--frames 4 did not write 4 pictures"
        assert pictures[1].read_bytes() != pictures[3].read_bytes(), "the mode does not swing"
    print(f"paraview: {len(cases) + 4} pictures checked, kept in {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
