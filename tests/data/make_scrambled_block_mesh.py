#!/usr/bin/env python3
"""Writes block_16x8_scrambled.msh (no Gmsh needed): [0, 2] x [0, 1] in
16 x 8 square cells, listed in a scrambled order (cell c of the row-major
numbering is element (37 c) mod 128), as a mesher's file may list them;
Physical Curves left (x = 0), right (x = 2), bottom (y = 0), top (y = 1)
and the Physical Surface block. MSH 2.2.

glissade puts a file's cells in the order of a Hilbert curve
(include/glissade/mesh/cell_order.h); tests/CMakeLists.txt counts by hand
the cells each of two processes holds.

Run from tests/data: /usr/bin/python3 make_scrambled_block_mesh.py
"""
NX, NY = 16, 8


def node(i, j):
    return j * (NX + 1) + i + 1


lines = []
for i in range(NX):
    lines.append((3, node(i, 0), node(i + 1, 0)))
    lines.append((4, node(i + 1, NY), node(i, NY)))
for j in range(NY):
    lines.append((1, node(0, j + 1), node(0, j)))
    lines.append((2, node(NX, j), node(NX, j + 1)))
row_major = [(i, j) for j in range(NY) for i in range(NX)]
cells = [None] * len(row_major)
for c, ij in enumerate(row_major):
    cells[(37 * c) % len(row_major)] = ij

with open("block_16x8_scrambled.msh", "w") as f:
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
    f.write("$PhysicalNames\n5\n1 1 \"left\"\n1 2 \"right\"\n"
            "1 3 \"bottom\"\n1 4 \"top\"\n2 5 \"block\"\n$EndPhysicalNames\n")
    f.write(f"$Nodes\n{(NX + 1) * (NY + 1)}\n")
    for j in range(NY + 1):
        for i in range(NX + 1):
            f.write(f"{node(i, j)} {2.0 * i / NX:g} {1.0 * j / NY:g} 0\n")
    f.write("$EndNodes\n")
    f.write(f"$Elements\n{len(lines) + len(cells)}\n")
    k = 1
    for group, a, b in lines:
        f.write(f"{k} 1 2 {group} {group} {a} {b}\n")
        k += 1
    for i, j in cells:
        f.write(f"{k} 3 2 5 5 {node(i, j)} {node(i + 1, j)} "
                f"{node(i + 1, j + 1)} {node(i, j + 1)}\n")
        k += 1
    f.write("$EndElements\n")
