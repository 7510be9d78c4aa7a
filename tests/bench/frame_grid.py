"""The 3D frames of `make bench`'s CalculiX comparison, as model dictionaries in the format of
tests/verify/frames/frame_model.py (nodes, members, sections, supports, loads), so that one
model becomes both a beamrotor deck and a ccx input.

- building(nx, nz, storeys): a building of nx x nz bays (4 m along x, 5 m along z) and storeys
  of 3.5 m (y up); columns 0.3 x 0.3 m, beams 0.2 m wide and 0.4 m deep; every base clamped; a
  floor load of 20 kN/m down on every beam and a wind load of 10 kN along x at every joint of
  the windward face (x = 0) above the ground.
- tower(panels): a lattice tower 2 m square in plan with panels 1.5 m high: four legs
  (0.3 x 0.3 m), a ring of four struts at every panel level and an X of two diagonals on
  each face in every panel (0.12 x 0.12 m), the diagonals not joined where they cross; the
  legs' feet clamped; at the top a lateral load of 50 kN along x and 20 kN along z and a down
  load of 100 kN shared by the four legs, and 2 kN along x at every leg joint below.
"""

BAY_X, BAY_Z, STOREY = 4.0, 5.0, 3.5
FLOOR_LOAD, WIND = 2e4, 1e4
STEEL = {"E": 210e9, "nu": 0.3}


def building_members(nx, nz, storeys):
    """Members of building(nx, nz, storeys)."""
    columns = (nx + 1) * (nz + 1) * storeys
    beams = storeys * (nx * (nz + 1) + nz * (nx + 1))
    return columns + beams


def _name(prefix, *index):
    return prefix + "_".join(str(i) for i in index)


def building(nx, nz, storeys):
    nodes, members, point_loads, distributed = {}, [], [], []
    for k in range(storeys + 1):
        for j in range(nz + 1):
            for i in range(nx + 1):
                nodes[_name("n", i, j, k)] = [BAY_X * i, STOREY * k, BAY_Z * j]
    for k in range(storeys):
        for j in range(nz + 1):
            for i in range(nx + 1):
                members.append({"name": _name("c", i, j, k), "from": _name("n", i, j, k),
                                "to": _name("n", i, j, k + 1), "section": "column"})
    for k in range(1, storeys + 1):
        for j in range(nz + 1):
            for i in range(nx + 1):
                for di, dj, prefix in ((1, 0, "x"), (0, 1, "z")):
                    if i + di <= nx and j + dj <= nz:
                        name = _name(prefix, i, j, k)
                        members.append({"name": name, "from": _name("n", i, j, k),
                                        "to": _name("n", i + di, j + dj, k), "section": "beam"})
                        distributed.append({"member": name, "q": [0.0, -FLOOR_LOAD, 0.0]})
            point_loads += [{"at": _name("n", 0, j, k), "f": [WIND, 0.0, 0.0]}
                            for j in range(nz + 1)]
    supports = {_name("n", i, j, 0): "clamped" for j in range(nz + 1) for i in range(nx + 1)}
    return {"title": f"building of {nx} x {nz} bays and {storeys} storeys",
            "dimension": "3d", "material": STEEL,
            "sections": {"column": {"b": 0.3, "h": 0.3}, "beam": {"b": 0.2, "h": 0.4}},
            "nodes": nodes, "members": members, "supports": supports,
            "point_loads": point_loads, "distributed_loads": distributed}


def tower(panels, width=2.0, panel=1.5):
    corners = [(0, 0), (1, 0), (1, 1), (0, 1)]   # in plan, around the square
    nodes, members, point_loads = {}, [], []
    for k in range(panels + 1):
        for c, (a, b) in enumerate(corners):
            nodes[_name("t", c, k)] = [width * a, panel * k, width * b]
    for k in range(panels):
        for c in range(4):
            d = (c + 1) % 4
            members.append({"name": _name("leg", c, k), "from": _name("t", c, k),
                            "to": _name("t", c, k + 1), "section": "leg"})
            members.append({"name": _name("ring", c, k + 1), "from": _name("t", c, k + 1),
                            "to": _name("t", d, k + 1), "section": "brace"})
            members.append({"name": _name("up", c, k), "from": _name("t", c, k),
                            "to": _name("t", d, k + 1), "section": "brace"})
            members.append({"name": _name("down", c, k), "from": _name("t", d, k),
                            "to": _name("t", c, k + 1), "section": "brace"})
    for c in range(4):
        for k in range(1, panels):
            point_loads.append({"at": _name("t", c, k), "f": [2e3, 0.0, 0.0]})
        point_loads.append({"at": _name("t", c, panels), "f": [1.25e4, -2.5e4, 5e3]})
    return {"title": f"lattice tower of {panels} panels", "dimension": "3d", "material": STEEL,
            "sections": {"leg": {"b": 0.3, "h": 0.3}, "brace": {"b": 0.12, "h": 0.12}},
            "nodes": nodes, "members": members,
            "supports": {_name("t", c, 0): "clamped" for c in range(4)},
            "point_loads": point_loads, "distributed_loads": []}
