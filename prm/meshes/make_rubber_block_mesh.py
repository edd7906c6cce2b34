#!/usr/bin/python3
"""The rubber block of prm/rubber_block_drag.prm as a Gmsh (MSH 2.2) file,
its two bottom corners rounded:

    make_rubber_block_mesh.py NX NY R FILE.msh

A 20 x 10 block of NX x NY quadrilaterals whose bottom corners are fillets
of radius R (R = 0: the sharp block, the same mesh as Mesh/Type =
rectangle). The corner squares [0, R] x [0, R] and [20 - R, 20] x [0, R]
are mapped onto the rounded corner along rays from the fillet's centre,
the rest of the mesh is left as it is; physical groups bottom (the flat
part and the fillets), right, top, left and block.

    make_rubber_block_mesh.py 20 10 2 rubber_block_fillet_r2.msh
"""
import math
import sys

WIDTH, HEIGHT = 20.0, 10.0


def rounded(x, y, radius):
    """(x, y) of the rectangle moved onto the block with rounded corners."""
    for centre_x, side in ((WIDTH - radius, 1.0), (radius, -1.0)):
        dx, dy = (x - centre_x) * side, y - radius
        if radius > 0 and dx > 1e-12 and dy < -1e-12:
            distance = math.hypot(dx, dy)
            # where the ray from the centre meets the square's outer edges
            to_square = distance * min(radius / dx, radius / -dy)
            scale = 1 + (radius / to_square - 1) * (distance / to_square)
            return centre_x + side * dx * scale, radius + dy * scale
    return x, y


def main():
    nx, ny, radius, path = (int(sys.argv[1]), int(sys.argv[2]),
                            float(sys.argv[3]), sys.argv[4])

    def node(i, j):
        return j * (nx + 1) + i + 1

    nodes = [rounded(WIDTH * i / nx, HEIGHT * j / ny, radius)
             for j in range(ny + 1) for i in range(nx + 1)]
    lines = ([(1, node(i, 0), node(i + 1, 0)) for i in range(nx)] +
             [(2, node(nx, j), node(nx, j + 1)) for j in range(ny)] +
             [(3, node(i + 1, ny), node(i, ny)) for i in range(nx)] +
             [(4, node(0, j + 1), node(0, j)) for j in range(ny)])
    quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1))
             for j in range(ny) for i in range(nx)]
    with open(path, "w") as out:
        out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n5\n"
                  '1 1 "bottom"\n1 2 "right"\n1 3 "top"\n1 4 "left"\n'
                  '2 5 "block"\n$EndPhysicalNames\n')
        out.write(f"$Nodes\n{len(nodes)}\n")
        for k, (x, y) in enumerate(nodes):
            out.write(f"{k + 1} {x:.15g} {y:.15g} 0\n")
        out.write(f"$EndNodes\n$Elements\n{len(lines) + len(quads)}\n")
        number = 1
        for group, a, b in lines:
            out.write(f"{number} 1 2 {group} {group} {a} {b}\n")
            number += 1
        for q in quads:
            out.write(f"{number} 3 2 5 5 {q[0]} {q[1]} {q[2]} {q[3]}\n")
            number += 1
        out.write("$EndElements\n")


if __name__ == "__main__":
    main()
