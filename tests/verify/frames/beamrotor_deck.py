"""Writes a frame model (frame_model.py) as a beamrotor deck: general sections holding the
rectangle's exact properties, Timoshenko elements (CalculiX's expanded beams deform in shear
with kappa = 1), point loads at nodes, uniform member loads in global axes."""
import json


def _g(x):
    return repr(float(x))


def write(model, path, elements):
    planar = model["dimension"] == "planar"
    out = [f"# Written by tests/verify/frames/beamrotor_deck.py from the model file; the twin of",
           f"# the CalculiX input beside it. {model['title']}",
           f"title: {json.dumps(model['title'])}", "",
           f"model:\n  dimension: {model['dimension']}", "",
           "materials:",
           f"  - {{name: steel, E: {_g(model['material']['E'])}, nu: {_g(model['material']['nu'])},"
           " rho: 7850}", "", "sections:"]
    for name, p in model["props"].items():
        extra = "" if planar else f", Iy: {_g(p['Iy'])}, J: {_g(p['J'])}, width: {_g(p['b'])}"
        key = "I" if planar else "Iz"
        out.append(f"  - {{name: {name}, shape: general, A: {_g(p['A'])}, {key}: {_g(p['Iz'])}"
                   f"{extra}, kappa: {_g(p['kappa'])}, depth: {_g(p['h'])}}}")
    out += ["", "nodes:"]
    for name, xyz in model["nodes"].items():
        at = xyz[:2] if planar else xyz
        out.append(f"  - {{name: {name}, at: [{', '.join(_g(c) for c in at)}]}}")
    out += ["", "members:"]
    for m in model["members"]:
        out.append(f"  - {{name: {m['name']}, from: {m['from']}, to: {m['to']}, section: "
                   f"{m['section']}, elements: {elements}, formulation: timoshenko}}")
    out += ["", "supports:"]
    for node, kind in model["supports"].items():
        fix = "clamped" if kind == "clamped" else "pinned"
        out.append(f"  - {{name: {node}, at: {node}, fix: {fix}}}")
    out += ["", "loads:"]
    axes = ("x", "y") if planar else ("x", "y", "z")
    for load in model["point_loads"]:
        comps = ", ".join(f"f{a}: {_g(v)}" for a, v in zip(axes, load["f"]) if v != 0)
        out.append(f"  - {{type: point, at: {load['at']}, {comps}}}")
    for load in model["distributed_loads"]:
        comps = ", ".join(f"q{a}: {_g(v)}" for a, v in zip(axes, load["q"]) if v != 0)
        out.append(f"  - {{type: distributed, member: {load['member']}, {comps}}}")
    out += ["", "analyses:", "  - {type: static}", ""]
    with open(path, "w") as fh:
        fh.write("\n".join(out))
