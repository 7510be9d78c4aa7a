"""Reads what CalculiX wrote for a frame (ccx_input.py): the .dat tables (joint displacements,
support reactions) and the .frd blocks (beam-node displacements, section forces), refusing
anything that does not look as expected rather than guessing.

.dat: a header line `displacements (vx,vy,vz) for set JOINTS and time ...` (or `forces
(fx,fy,fz) for set SUPPORTS ...`), a blank line, then `node v1 v2 v3` rows up to the next
blank line. .frd: a result block opens with ` -4  NAME  ncomp ...`, lists its components in
` -5` lines and holds ` -1` rows: the node number in columns 4-13, then one value every 12
columns (fixed width: values may touch, `9.78E+01-9.66E+02`), and closes with ` -3`.

With SECTION FORCES the six `stress` components of a beam node are (ccx User's Manual,
*EL FILE): SXX the shear force along the local 1-direction n1, SYY along n2 = t x n1, SZZ
the normal force along the tangent t, SXY the torque about t, SYZ the bending moment about
n1, SZX about n2, acting on the part of the beam before the node from the part after it.
"""
import math
import re


class ParseError(RuntimeError):
    pass


def dat_table(path, kind, nset):
    """{node: (v1, v2, v3)} of the .dat block `kind` (displacements or forces) for `nset`."""
    with open(path) as fh:
        lines = fh.read().split("\n")
    header = re.compile(rf"^\s*{kind} \([a-z,]+\) for set {nset.upper()} and time")
    starts = [i for i, line in enumerate(lines) if header.match(line)]
    if len(starts) != 1:
        raise ParseError(f"{path}: {len(starts)} '{kind}' blocks for set {nset}, expected 1")
    rows, i = {}, starts[0] + 1
    while i < len(lines) and not lines[i].strip():
        i += 1
    while i < len(lines) and lines[i].strip():
        fields = lines[i].split()
        if len(fields) != 4:
            raise ParseError(f"{path}:{i + 1}: expected node and 3 values, got {lines[i]!r}")
        rows[int(fields[0])] = tuple(float(f) for f in fields[1:])
        i += 1
    return rows


def frd_block(path, name, components):
    """{node: tuple of `components` values} of the .frd result block `name` (DISP, STRESS)."""
    with open(path) as fh:
        lines = fh.read().split("\n")
    starts = [i for i, line in enumerate(lines) if re.match(rf"^ -4\s+{name}\s", line)]
    if len(starts) != 1:
        raise ParseError(f"{path}: {len(starts)} {name} blocks, expected 1")
    i = starts[0] + 1
    names = []
    while lines[i].startswith(" -5"):
        names.append(lines[i].split()[1])
        i += 1
    if names[:components] != list(_COMPONENTS[name])[:components]:
        raise ParseError(f"{path}: {name} components {names}, expected {_COMPONENTS[name]}")
    rows = {}
    while not lines[i].startswith(" -3"):
        line = lines[i]
        if not line.startswith(" -1"):
            raise ParseError(f"{path}:{i + 1}: expected a ' -1' row, got {line!r}")
        values = [float(line[13 + 12 * k:25 + 12 * k]) for k in range(components)]
        if any(not math.isfinite(v) for v in values):
            raise ParseError(f"{path}:{i + 1}: a value that is not a number")
        rows[int(line[3:13])] = tuple(values)
        i += 1
    return rows


_COMPONENTS = {"DISP": ("D1", "D2", "D3"),
               "STRESS": ("SXX", "SYY", "SZZ", "SXY", "SYZ", "SZX")}


def section_resultants(stress):
    """Section forces of a beam node as beamrotor's member resultants (N, Vy, Vz, T, My, Mz):
    ccx's n1 is the member's local z, so n2 = t x n1 = -y."""
    sxx, syy, szz, sxy, syz, szx = stress
    return {"N": szz, "Vy": -syy, "Vz": sxx, "T": sxy, "My": -szx, "Mz": syz}
