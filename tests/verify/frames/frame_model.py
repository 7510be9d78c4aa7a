"""The frame models of `make verify-frames`: read a model file (JSON, beside this file), give
each section the solid rectangle CalculiX will expand its beams into, and work out each
member's axes by beamrotor's rule (problems/deck/FORMAT.md, Frames).

A section is either a rectangle {"b", "h"} (b along the member's local z, h along local y)
or a table section {"A", "I"} bending in the plane of a planar frame; the latter becomes the
rectangle with the same A and I (h = sqrt(12 I / A), b = A / h), so both programs see the
table's area and second moment exactly.
"""
import json
import math


def _unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def rectangle(section):
    """(b, h) of the rectangle standing for a section."""
    if "b" in section:
        return section["b"], section["h"]
    h = math.sqrt(12 * section["I"] / section["A"])
    return section["A"] / h, h


def properties(section):
    """A, Iz (about local z, bending in x-y), Iy, J and the shear coefficient of the rectangle
    as CalculiX's B31 beam (one C3D8I brick across the section) carries it.

    J: the brick's displacement is trilinear across the section, so the only warping it can
    take under torsion is u_x = c y z; the best c gives J = 4 Iy Iz / (Iy + Iz) (a Ritz bound,
    above Saint-Venant's value: 0.167 a^4 against 0.141 a^4 for a square). Its transverse
    shear strain is constant over the section, so its shear area is A (kappa = 1).
    Both were measured on cantilevers (see README.md in this folder)."""
    b, h = rectangle(section)
    area, iz, iy = b * h, b * h**3 / 12, h * b**3 / 12
    return {"b": b, "h": h, "A": area, "Iz": iz, "Iy": iy, "J": 4 * iy * iz / (iy + iz),
            "kappa": 1.0}


def member_axes(start, end):
    """Unit vectors (ex, ey, ez) of a member by beamrotor's default rule: ez is the part of
    global +z across the member, ey = ez x ex; a member along z gets ey = global +y."""
    ex = _unit([e - s for s, e in zip(start, end)])
    z = [0.0, 0.0, 1.0]
    across = [zc - _dot(z, ex) * xc for zc, xc in zip(z, ex)]
    if math.sqrt(_dot(across, across)) < 1e-9:
        ey = [0.0, 1.0, 0.0]
        return ex, ey, _cross(ex, ey)
    ez = _unit(across)
    return ex, _cross(ez, ex), ez


def load(path):
    with open(path) as fh:
        return prepare(json.load(fh))


def prepare(model):
    """The model (as read from a model file) with its sections' properties and its members'
    axes and lengths added."""
    model["props"] = {name: properties(s) for name, s in model["sections"].items()}
    for m in model["members"]:
        m["axes"] = member_axes(model["nodes"][m["from"]], model["nodes"][m["to"]])
        m["length"] = math.dist(model["nodes"][m["from"]], model["nodes"][m["to"]])
    return model
