#!/usr/bin/python3
"""Writes the quarter disk of radius 1 and centre (0, 1), x >= 0, y <= 1,
as one NURBS patch of degree 2 (quarter_disk_p2.nurbs) and its degree
elevation to 3 (quarter_disk_p3.nurbs): the cylinder of the plane Hertz
problem (prm/hertz_cylinder_nurbs.prm), touching y = 0 at the origin.

A quarter disk has three corners and a patch four: the fourth, M, is put
on the arc at 45 degrees, a corner of 180 degrees where the patch's
Jacobian vanishes (at that point only; no Gauss point lies there). On the
arc, rather than on a straight side, the cells' straight-edged images
stay convex there (a Lagrange space on the file's cells), and the contact
side is one exact arc (the rational quadratic of 45 degrees: weights 1,
cos 22.5, 1), far from M:

  eta0  arc       from A = (0, 0) to M = (sin 45, 1 - cos 45)
  xi1   free arc  from M to B = (1, 1)
  eta1  top       from C = (0, 1) to B
  xi0   axis      from A up to C

The inner control point is the Coons blend of the sides' middle ones,
in homogeneous coordinates. Degree elevation of each Bezier direction
(Farin): Q_i = i / (p + 1) P_(i-1) + (1 - i / (p + 1)) P_i on (w x, w y, w).

Run from prm/meshes: /usr/bin/python3 make_quarter_disk_patches.py
"""
import math

S = math.sin(math.pi / 4)
T = math.tan(math.pi / 8)
W = math.cos(math.pi / 8)


def homogeneous(x, y, w):
    return [w * x, w * y, w]


def quadratic_net():
    """The 3 x 3 net, rows of eta (b), each along xi (a)."""
    net = [[None] * 3 for _ in range(3)]
    net[0] = [homogeneous(0, 0, 1), homogeneous(T, 0, W),
              homogeneous(S, 1 - S, 1)]
    net[2] = [homogeneous(0, 1, 1), homogeneous(0.5, 1, 1),
              homogeneous(1, 1, 1)]
    net[1][0] = homogeneous(0, 0.5, 1)
    net[1][2] = homogeneous(1, 2 - 2 * S, W)
    net[1][1] = [(net[0][1][k] + net[2][1][k] + net[1][0][k] + net[1][2][k])
                 / 2 - (net[0][0][k] + net[0][2][k] + net[2][0][k] +
                        net[2][2][k]) / 4 for k in range(3)]
    return net


def elevate(row):
    """One Bezier row of degree p as degree p + 1."""
    p = len(row) - 1
    out = [row[0]]
    for i in range(1, p + 1):
        a = i / (p + 1)
        out.append([a * row[i - 1][k] + (1 - a) * row[i][k]
                    for k in range(3)])
    out.append(row[p])
    return out


def elevated(net):
    rows = [elevate(row) for row in net]
    columns = [elevate([rows[b][a] for b in range(len(rows))])
               for a in range(len(rows[0]))]
    return [[columns[a][b] for a in range(len(columns))]
            for b in range(len(columns[0]))]


def write(net, path, title, xi_knots=None,
          names=(("arc", "eta0"), ("free_arc", "xi1"), ("top", "eta1"),
                 ("axis", "xi0"))):
    """Writes the net (rows of eta, each along xi) as a patch file of one
    element in eta (and in xi unless xi_knots says otherwise)."""
    p = len(net) - 1
    eta_knots = " ".join(["0"] * (p + 1) + ["1"] * (p + 1))
    with open(path, "w") as out:
        out.write(title)
        out.write("degrees %d %d\nknots xi %s\nknots eta %s\n" %
                  (p, p, xi_knots or eta_knots, eta_knots))
        out.write("control points %d %d\n" % (len(net[0]), len(net)))
        for row in net:
            for wx, wy, w in row:
                out.write("%.17g %.17g %.17g\n" % (wx / w, wy / w, w))
        for name, side in names:
            out.write("boundary %s %s\n" % (name, side))


def title(p):
    return ("# The quarter disk of radius 1, centre (0, 1), x >= 0, y <= 1, as\n"
            "# one NURBS patch of degree %d (written by\n"
            "# make_quarter_disk_patches.py, which explains its corners).\n"
            % p)


if __name__ == "__main__":
    net = quadratic_net()
    write(net, "quarter_disk_p2.nurbs", title(2))
    write(elevated(net), "quarter_disk_p3.nurbs", title(3))
