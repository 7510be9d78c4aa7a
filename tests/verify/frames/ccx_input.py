"""Writes a frame model (frame_model.py) as a CalculiX input: B31 beams (each expanded by ccx
into C3D8I bricks across a RECT section), `elements` per member, the members' local 1-direction
along beamrotor's local z; uniform member loads as nodal forces (q h / 2 at each end of every
element); clamped supports fix dofs 1-6, pinned ones 1-3. Asks for the joints' displacements
and the supports' reactions in the .dat file and the beams' section forces in the .frd file.

Returns the mesh: node numbers of the joints and, per member, its node numbers from `from` to
`to` with their distances along it."""


def _g(x):
    return f"{float(x):.15g}"


def _set_lines(numbers):
    """A set's node numbers, 16 to a line (ccx reads no more from one line)."""
    return "\n".join(", ".join(str(n) for n in numbers[k:k + 16])
                     for k in range(0, len(numbers), 16))


def write(model, path, elements):
    numbers = {name: i + 1 for i, name in enumerate(model["nodes"])}
    coords = {numbers[n]: xyz for n, xyz in model["nodes"].items()}
    next_node, next_element = len(numbers) + 1, 1
    members, element_lines, loads = {}, [], {}
    for m in model["members"]:
        start, end = model["nodes"][m["from"]], model["nodes"][m["to"]]
        chain = [numbers[m["from"]]]
        for k in range(1, elements):
            coords[next_node] = [s + (e - s) * k / elements for s, e in zip(start, end)]
            chain.append(next_node)
            next_node += 1
        chain.append(numbers[m["to"]])
        step = m["length"] / elements
        members[m["name"]] = {"nodes": chain, "s": [k * step for k in range(elements + 1)]}
        ez = m["axes"][2]
        b, h = model["props"][m["section"]]["b"], model["props"][m["section"]]["h"]
        element_lines.append(f"*ELEMENT, TYPE=B31, ELSET={m['name'].upper()}")
        for a, c in zip(chain, chain[1:]):
            element_lines.append(f"{next_element}, {a}, {c}")
            next_element += 1
        element_lines += [f"*BEAM SECTION, ELSET={m['name'].upper()}, MATERIAL=STEEL, "
                          "SECTION=RECT", f"{_g(b)}, {_g(h)}", ", ".join(_g(c) for c in ez)]
    for load in model["distributed_loads"]:
        mesh = members[load["member"]]
        step = mesh["s"][1]
        for a, c in zip(mesh["nodes"], mesh["nodes"][1:]):
            for n in (a, c):
                loads[n] = [f + q * step / 2 for f, q in zip(loads.get(n, [0, 0, 0]), load["q"])]
    for load in model["point_loads"]:
        n = numbers[load["at"]]
        loads[n] = [f + p for f, p in zip(loads.get(n, [0, 0, 0]), load["f"])]
    joints = _set_lines([numbers[n] for n in model["nodes"]])
    supports = _set_lines([numbers[n] for n in model["supports"]])
    out = ["** Written by tests/verify/frames/ccx_input.py; the twin of the beamrotor deck beside",
           f"** it. {model['title']}", "*NODE, NSET=NALL"]
    out += [f"{n}, {', '.join(_g(c) for c in coords[n])}" for n in sorted(coords)]
    out += [f"*NSET, NSET=JOINTS\n{joints}", f"*NSET, NSET=SUPPORTS\n{supports}"]
    out += element_lines
    out += ["*MATERIAL, NAME=STEEL", "*ELASTIC",
            f"{_g(model['material']['E'])}, {_g(model['material']['nu'])}", "*BOUNDARY"]
    for node, kind in model["supports"].items():
        out.append(f"{numbers[node]}, 1, {6 if kind == 'clamped' else 3}")
    out += ["*STEP", "*STATIC", "*CLOAD"]
    for n in sorted(loads):
        out += [f"{n}, {d + 1}, {_g(v)}" for d, v in enumerate(loads[n]) if v != 0]
    out += ["*NODE PRINT, NSET=JOINTS", "U", "*NODE PRINT, NSET=SUPPORTS", "RF",
            "*NODE FILE, OUTPUT=2D", "U", "*EL FILE, SECTION FORCES, OUTPUT=2D", "S",
            "*END STEP", ""]
    with open(path, "w") as fh:
        fh.write("\n".join(out))
    return {"joints": numbers, "members": members, "loads": loads}
