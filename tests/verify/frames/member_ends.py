"""The compared quantities of one frame, from each program, under the same names:
`displacement J ux` at every joint that is not a support, `reaction S fx` (and `mz` at a
clamped support), `member M@J N` (N, Vy, Mz in a planar frame; N, Vy, Vz, T, My, Mz in 3d)
at each end J of each member, in member axes (problems/deck/FORMAT.md, Frames).

From ccx, the member end forces are extrapolated, never read at the joint: ccx averages a
node's section forces over the elements that meet there, so at a joint it mixes members, and
next to a knot or a clamp the section forces are disturbed over about a section depth. So
each resultant is fitted along the member with a quadratic in s (exact for the loads here:
nodal loads and uniform member loads) through the member's nodes in its middle half, and the
fit is read at the ends.
Reactions come from the supported member's end the same way: ccx's RF is not the reaction at a
node whose rotations are held (8 elements per member: 12 % of the two-bay frame's load);
where they are free (pinned), RF is checked against the member end, and all balance the loads.
"""
import csv
import json
import os

from ccx_results import ParseError, dat_table, frd_block, section_resultants

SKIP = 0.25   # the part of each member next to either end left out of the fit


def _components(model):
    planar = model["dimension"] == "planar"
    return {"u": ("ux", "uy") if planar else ("ux", "uy", "uz"),
            "f": ("fx", "fy") if planar else ("fx", "fy", "fz"),
            "m": ("mz",) if planar else ("mx", "my", "mz"),
            "member": ("N", "Vy", "Mz") if planar else ("N", "Vy", "Vz", "T", "My", "Mz")}


def _solve3(a, b):
    """Solution of the 3x3 system a x = b (Cramer's rule; a is well conditioned here)."""
    def det(m):
        return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    d = det(a)
    return [det([[b[r] if c == k else a[r][c] for c in range(3)] for r in range(3)]) / d
            for k in range(3)]


def quadratic_ends(s, values, length):
    """Least-squares quadratic through (s, values), read at s = 0 and s = length."""
    t = [x / length for x in s]
    a = [[sum(x ** (i + j) for x in t) for j in range(3)] for i in range(3)]
    b = [sum(v * x ** i for x, v in zip(t, values)) for i in range(3)]
    c = _solve3(a, b)
    return c[0], c[0] + c[1] + c[2]


def _global(resultants, axes, force):
    keys = ("N", "Vy", "Vz") if force else ("T", "My", "Mz")
    return [sum(resultants[k] * axes[i][d] for i, k in enumerate(keys)) for d in range(3)]


def _support_member(model, node):
    ends = [(m, "start" if m["from"] == node else "end") for m in model["members"]
            if node in (m["from"], m["to"])]
    if len(ends) != 1:
        raise ParseError(f"support {node} ends {len(ends)} members; the comparison needs one")
    return ends[0]


def _reaction(ends, member, side, force):
    """Support reaction from the member end resultants at its supported end."""
    sign = -1.0 if side == "start" else 1.0
    return [sign * c for c in _global(ends[member["name"]][side], member["axes"], force)]


def ccx_quantities(model, mesh, stem):
    comps = _components(model)
    disp = dat_table(stem + ".dat", "displacements", "JOINTS")
    forces = dat_table(stem + ".dat", "forces", "SUPPORTS")
    frd_disp = frd_block(stem + ".frd", "DISP", 3)
    stress = frd_block(stem + ".frd", "STRESS", 6)
    joints = mesh["joints"]
    if sorted(disp) != sorted(joints.values()) or len(forces) != len(model["supports"]):
        raise ParseError(f"{stem}.dat: the joints or supports are not all there")
    big = max(abs(v) for row in disp.values() for v in row)
    for n, row in disp.items():   # the same numbers through both files (print precisions)
        if max(abs(a - b) for a, b in zip(row, frd_disp[n])) > 1e-5 * big:
            raise ParseError(f"{stem}: node {n} displaced differently in .dat and .frd")
    ends = {}
    for m in model["members"]:
        chain = mesh["members"][m["name"]]
        keep = [k for k, s in enumerate(chain["s"])
                if SKIP * m["length"] <= s <= (1 - SKIP) * m["length"]]
        local = [section_resultants(stress[chain["nodes"][k]]) for k in keep]
        s = [chain["s"][k] for k in keep]
        start, end = {}, {}
        for key in ("N", "Vy", "Vz", "T", "My", "Mz"):
            start[key], end[key] = quadratic_ends(s, [r[key] for r in local], m["length"])
        ends[m["name"]] = {"start": start, "end": end}
    out = {}
    for name, n in joints.items():
        if name not in model["supports"]:
            for d, c in enumerate(comps["u"]):
                out[f"displacement {name} {c}"] = disp[n][d]
    total = sum(abs(f[d]) for f in mesh["loads"].values() for d in range(3))
    balance = [sum(f[d] for f in mesh["loads"].values()) for d in range(3)]
    for node, kind in model["supports"].items():
        member, side = _support_member(model, node)
        force = _reaction(ends, member, side, True)
        balance = [b + f for b, f in zip(balance, force)]
        if kind == "pinned":   # ccx's RF is the reaction only where no rotation is held
            for d, c in enumerate(comps["f"]):
                if abs(forces[joints[node]][d] - force[d]) > 1e-3 * total:
                    raise ParseError(f"{stem}: reaction {node} {c}: RF "
                                     f"{forces[joints[node]][d]:g}, member end {force[d]:g}")
        for d, c in enumerate(comps["f"]):
            out[f"reaction {node} {c}"] = force[d]
        if kind == "clamped":
            moment = _reaction(ends, member, side, False)
            for c in comps["m"]:
                out[f"reaction {node} {c}"] = moment["xyz".index(c[1])]
    if max(abs(b) for b in balance) > 1e-3 * total:
        raise ParseError(f"{stem}: the reactions leave {balance} of the loads unbalanced")
    for m in model["members"]:
        for side, joint in (("start", m["from"]), ("end", m["to"])):
            for c in comps["member"]:
                out[f"member {m['name']}@{joint} {c}"] = ends[m["name"]][side][c]
    return out


def _member_rows(path):
    with open(path) as fh:
        # The line after the names holds their units, as a comment ("# units: ...").
        rows = [r for r in csv.DictReader(fh) if not next(iter(r.values()), "").startswith("#")]
    return rows[0], rows[-1]


def beamrotor_quantities(model, directory):
    comps = _components(model)
    with open(os.path.join(directory, "results.json")) as fh:
        analysis = json.load(fh)["analyses"][0]
    out = {}
    for name in model["nodes"]:
        if name not in model["supports"]:
            for c in comps["u"]:
                out[f"displacement {name} {c}"] = analysis["displacements"][name][c]
    for node, kind in model["supports"].items():
        reaction = analysis["reactions"][node]
        for c in comps["f"] + (comps["m"] if kind == "clamped" else ()):
            out[f"reaction {node} {c}"] = reaction[c]
    for m in model["members"]:
        first, last = _member_rows(os.path.join(directory, analysis["members"][m["name"]]["csv"]))
        for row in (first, last):   # the same member axes as the ccx input was given
            for axis, key in ((1, "ey"), (2, "ez")):
                got = [float(row[f"{key}_{d}"]) for d in "xyz"]
                if max(abs(a - b) for a, b in zip(got, m["axes"][axis])) > 1e-9:
                    raise ParseError(f"member {m['name']}: beamrotor's {key} is {got}, "
                                     f"the ccx input assumed {m['axes'][axis]}")
        for row, joint in ((first, m["from"]), (last, m["to"])):
            for c in comps["member"]:
                out[f"member {m['name']}@{joint} {c}"] = float(row[c])
    return out
