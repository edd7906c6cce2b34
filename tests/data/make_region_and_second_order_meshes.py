#!/usr/bin/env python3
"""Writes the Gmsh test meshes of mesh_test.cc (no Gmsh needed):

- quarter_annulus_{q8_v22,q9_v41,chords_v22}.msh: r in [1, 2], theta in
  [0, pi/2], 4 x 2 cells; 8-node (MSH 2.2) and 9-node (MSH 4.1) quadrilaterals
  with their mid-side nodes on the arcs, and the first-order mesh of the same
  corners (straight chords). Physical Curves inner, outer, x0 (x = 0), y0.
- two_material_bar_v{22,41}.msh: [0, 2] x [0, 1], 4 x 2 cells, Physical
  Surfaces 'soft' (x < 1) and 'stiff' (x > 1), Physical Curves clamp
  (x = 0) and pull (x = 2).

Run from tests/data: /usr/bin/python3 make_region_and_second_order_meshes.py
"""
import math


def quarter_annulus(n_r, n_theta, order):
    """Nodes at half steps (i, j) in (r, theta); cells ccw in (r, theta)."""
    def node_id(i, j):
        return j * (2 * n_r + 1) + i + 1

    def position(i, j):
        r = 1.0 + i / (2 * n_r)
        t = (math.pi / 2) * j / (2 * n_theta)
        return (r * math.cos(t), r * math.sin(t))

    cells, used = [], set()
    for cj in range(n_theta):
        for ci in range(n_r):
            i, j = 2 * ci, 2 * cj
            corners = [(i, j), (i + 2, j), (i + 2, j + 2), (i, j + 2)]
            mids = [(i + 1, j), (i + 2, j + 1), (i + 1, j + 2), (i, j + 1)]
            centre = [(i + 1, j + 1)]
            ij = corners + (mids if order >= 8 else []) + \
                (centre if order == 9 else [])
            used.update(ij)
            cells.append([node_id(*p) for p in ij])
    # Boundary lines: (group, [ends..., mid]) with the body on the left.
    lines = []
    for cj in range(n_theta):
        j = 2 * cj
        lines.append(("inner", [(0, j + 2), (0, j), (0, j + 1)]))
        lines.append(("outer", [(2 * n_r, j), (2 * n_r, j + 2),
                                (2 * n_r, j + 1)]))
    for ci in range(n_r):
        i = 2 * ci
        lines.append(("y0", [(i, 0), (i + 2, 0), (i + 1, 0)]))
        lines.append(("x0", [(i + 2, 2 * n_theta), (i, 2 * n_theta),
                             (i + 1, 2 * n_theta)]))
    if order == 4:
        lines = [(g, ends[:2]) for g, ends in lines]
    used.update(p for _, ends in lines for p in ends)
    nodes = {node_id(*p): position(*p) for p in used}
    lines = [(g, [node_id(*p) for p in ends]) for g, ends in lines]
    groups = {"inner": 1, "outer": 2, "x0": 3, "y0": 4}
    surfaces = {"ring": (5, cells)}
    return nodes, lines, groups, surfaces


def bar():
    nx, ny = 4, 2
    nodes = {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            nodes[j * (nx + 1) + i + 1] = (2.0 * i / nx, 1.0 * j / ny)
    n = lambda i, j: j * (nx + 1) + i + 1
    soft, stiff = [], []
    for j in range(ny):
        for i in range(nx):
            cell = [n(i, j), n(i + 1, j), n(i + 1, j + 1), n(i, j + 1)]
            (soft if i < nx // 2 else stiff).append(cell)
    lines = [("clamp", [n(0, j + 1), n(0, j)]) for j in range(ny)] + \
            [("pull", [n(nx, j), n(nx, j + 1)]) for j in range(ny)]
    groups = {"clamp": 1, "pull": 2}
    surfaces = {"soft": (3, soft), "stiff": (4, stiff)}
    return nodes, lines, groups, surfaces


LINE_TYPE = {2: 1, 3: 8}
QUAD_TYPE = {4: 3, 8: 16, 9: 10}


def write_physical_names(f, groups, surfaces):
    """The $PhysicalNames records: curves (dimension 1), then surfaces."""
    f.write(f"{len(groups) + len(surfaces)}\n")
    for g, tag in groups.items():
        f.write(f'1 {tag} "{g}"\n')
    for s, (tag, _) in surfaces.items():
        f.write(f'2 {tag} "{s}"\n')


def write_v22(path, mesh):
    nodes, lines, groups, surfaces = mesh
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n")
        write_physical_names(f, groups, surfaces)
        f.write("$EndPhysicalNames\n$Nodes\n" + f"{len(nodes)}\n")
        for k in sorted(nodes):
            f.write(f"{k} {nodes[k][0]!r} {nodes[k][1]!r} 0\n")
        elements = [(LINE_TYPE[len(e)], groups[g], e) for g, e in lines]
        for tag, cells in surfaces.values():
            elements += [(QUAD_TYPE[len(c)], tag, c) for c in cells]
        f.write("$EndNodes\n$Elements\n" + f"{len(elements)}\n")
        for k, (kind, tag, e) in enumerate(elements, 1):
            f.write(f"{k} {kind} 2 {tag} {tag} " + " ".join(map(str, e)) + "\n")
        f.write("$EndElements\n")


def write_v41(path, mesh):
    """One curve entity per boundary group, one surface entity per region;
    all nodes in one block on the first surface (valid MSH 4.1)."""
    nodes, lines, groups, surfaces = mesh
    xs = [p[0] for p in nodes.values()]
    ys = [p[1] for p in nodes.values()]
    box = f"{min(xs)!r} {min(ys)!r} 0 {max(xs)!r} {max(ys)!r} 0"
    with open(path, "w") as f:
        f.write("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n")
        write_physical_names(f, groups, surfaces)
        f.write("$EndPhysicalNames\n$Entities\n")
        f.write(f"0 {len(groups)} {len(surfaces)} 0\n")
        for g, tag in groups.items():
            f.write(f"{tag} {box} 1 {tag} 0\n")
        for s, (tag, _) in surfaces.items():
            f.write(f"{tag} {box} 1 {tag} 0\n")
        f.write("$EndEntities\n$Nodes\n")
        keys = sorted(nodes)
        first_surface = next(iter(surfaces.values()))[0]
        f.write(f"1 {len(keys)} {keys[0]} {keys[-1]}\n")
        f.write(f"2 {first_surface} 0 {len(keys)}\n")
        f.writelines(f"{k}\n" for k in keys)
        f.writelines(f"{nodes[k][0]!r} {nodes[k][1]!r} 0\n" for k in keys)
        f.write("$EndNodes\n$Elements\n")
        blocks = []
        for g, tag in groups.items():
            es = [e for h, e in lines if h == g]
            blocks.append((1, tag, LINE_TYPE[len(es[0])], es))
        for s, (tag, cells) in surfaces.items():
            blocks.append((2, tag, QUAD_TYPE[len(cells[0])], cells))
        total = sum(len(b[3]) for b in blocks)
        f.write(f"{len(blocks)} {total} 1 {total}\n")
        k = 1
        for dim, tag, kind, es in blocks:
            f.write(f"{dim} {tag} {kind} {len(es)}\n")
            for e in es:
                f.write(f"{k} " + " ".join(map(str, e)) + "\n")
                k += 1
        f.write("$EndElements\n")


write_v22("quarter_annulus_q8_v22.msh", quarter_annulus(2, 4, 8))
write_v41("quarter_annulus_q9_v41.msh", quarter_annulus(2, 4, 9))
write_v22("quarter_annulus_chords_v22.msh", quarter_annulus(2, 4, 4))
write_v22("two_material_bar_v22.msh", bar())
write_v41("two_material_bar_v41.msh", bar())
