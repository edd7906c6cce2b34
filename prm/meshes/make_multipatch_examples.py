#!/usr/bin/python3
"""Writes the NURBS files of several patches joined C0 (doc/user_guide.md,
"NURBS patch files") that the tests read, all of degree 2:

quarter_annulus_two_patches.nurbs
    the quarter of the annulus 1 < r < 2 as two patches of 45 degrees
    each (xi out along r, eta round; the rational quadratic arc of 45
    degrees: weights 1, cos 22.5, 1), joined along r at 45 degrees;
quarter_annulus_two_patches_reversed.nurbs
    the same, the second patch's xi and eta both reversed (xi in along r,
    eta clockwise), so that its side on the join runs against the first's;
quarter_annulus_c0.nurbs
    the same shape as one patch whose eta knots 0 0 0 1/2 1/2 1 1 1 join
    the two arcs C0 at 45 degrees: the same functions as the two patches,
    so that the same scene gives the same answer on both;
l_shape_three_patches.nurbs
    the L [0, 2] x [0, 1] + [0, 1] x [1, 2] as three unit squares: A at
    the corner, B to its right (its xi and eta reversed: its side on the
    join runs down where A's runs up), C above it (xi down, eta along x:
    its xi side on A's eta side); A's middle control point moved, so that
    the patch is not affine inside.

Run from prm/meshes: /usr/bin/python3 make_multipatch_examples.py
"""
import math

C = math.cos(math.pi / 8)


def arc_column(r, angle_0, angle_1):
    """The three control points (x, y, w) of the arc of radius r from
    angle_0 to angle_1 (at most 90 degrees apart)."""
    half = (angle_1 - angle_0) / 2
    middle = angle_0 + half
    w = math.cos(half)
    return [(r * math.cos(angle_0), r * math.sin(angle_0), 1.),
            (r / w * math.cos(middle), r / w * math.sin(middle), w),
            (r * math.cos(angle_1), r * math.sin(angle_1), 1.)]


def sector_net(angle_0, angle_1):
    """A 3 x 3 net of the sector 1 < r < 2: xi along r, eta round."""
    columns = [arc_column(r, angle_0, angle_1) for r in (1., 1.5, 2.)]
    # control point (a, b): a along r, b round; xi fastest
    return [columns[a][b] for b in range(3) for a in range(3)]


def reversed_net(net, n_xi, n_eta):
    """The net with both parameters reversed (still counterclockwise)."""
    return [net[(n_xi - 1 - a) + n_xi * (n_eta - 1 - b)]
            for b in range(n_eta) for a in range(n_xi)]


def points_text(net):
    return "".join("%.17g %.17g %.17g\n" % point for point in net)


def patch_text(net, n_xi, n_eta, eta_knots="0 0 0 1 1 1"):
    return ("degrees 2 2\nknots xi 0 0 0 1 1 1\nknots eta %s\n"
            "control points %d %d\n" % (eta_knots, n_xi, n_eta) +
            points_text(net))


def write_quarter_annulus_files():
    first = sector_net(0., math.pi / 4)
    second = sector_net(math.pi / 4, math.pi / 2)
    header = ("# The quarter of the annulus 1 < r < 2 as two patches of 45 "
              "degrees joined C0\n# (written by make_multipatch_examples.py)."
              "\n")
    with open("quarter_annulus_two_patches.nurbs", "w") as f:
        f.write(header)
        f.write("patch\n" + patch_text(first, 3, 3))
        f.write("patch\n" + patch_text(second, 3, 3))
        f.write("join 1 eta1 2 eta0\n"
                "boundary inner 1 xi0 2 xi0\nboundary outer 1 xi1 2 xi1\n"
                "boundary start 1 eta0\nboundary end 2 eta1\n")
    with open("quarter_annulus_two_patches_reversed.nurbs", "w") as f:
        f.write("# The quarter of the annulus 1 < r < 2 as two patches of 45 "
                "degrees joined C0,\n# the second's parameters reversed "
                "(written by make_multipatch_examples.py).\n")
        f.write("patch\n" + patch_text(first, 3, 3))
        f.write("patch\n" + patch_text(reversed_net(second, 3, 3), 3, 3))
        f.write("join 1 eta1 2 eta1\n"
                "boundary inner 1 xi0 2 xi1\nboundary outer 1 xi1 2 xi0\n"
                "boundary start 1 eta0\nboundary end 2 eta0\n")
    with open("quarter_annulus_c0.nurbs", "w") as f:
        f.write("# The quarter of the annulus 1 < r < 2 as one patch whose "
                "two arcs of 45 degrees\n# are joined C0 by the double knot "
                "1/2 (written by make_multipatch_examples.py).\n")
        columns = [arc_column(r, 0., math.pi / 4) +
                   arc_column(r, math.pi / 4, math.pi / 2)[1:]
                   for r in (1., 1.5, 2.)]
        net = [columns[a][b] for b in range(5) for a in range(3)]
        f.write(patch_text(net, 3, 5, "0 0 0 0.5 0.5 1 1 1"))
        f.write("boundary inner xi0\nboundary outer xi1\n"
                "boundary start eta0\nboundary end eta1\n")


def square_net(origin, e_xi, e_eta):
    """The unit square from `origin` along e_xi and e_eta, 3 x 3, w = 1."""
    return [(origin[0] + a / 2 * e_xi[0] + b / 2 * e_eta[0],
             origin[1] + a / 2 * e_xi[1] + b / 2 * e_eta[1], 1.)
            for b in range(3) for a in range(3)]


def write_l_shape():
    a = square_net((0, 0), (1, 0), (0, 1))
    a[4] = (0.6, 0.45, 1.)  # the middle control point moved
    b = square_net((2, 1), (-1, 0), (0, -1))   # xi towards -x, eta -y
    c = square_net((0, 2), (0, -1), (1, 0))    # xi towards -y, eta +x
    with open("l_shape_three_patches.nurbs", "w") as f:
        f.write("# The L [0, 2] x [0, 1] + [0, 1] x [1, 2] as three unit "
                "squares joined C0:\n# A at the corner, B right of it (its "
                "side on the join runs against A's),\n# C above it (its xi "
                "side on A's eta side). Written by\n"
                "# make_multipatch_examples.py.\n")
        for net in (a, b, c):
            f.write("patch\n" + patch_text(net, 3, 3))
        f.write("join 1 xi1 2 xi1\njoin 1 eta1 3 xi1\n"
                "boundary outline 1 xi0 1 eta0 2 xi0 2 eta0 2 eta1 "
                "3 xi0 3 eta0 3 eta1\n")


write_quarter_annulus_files()
write_l_shape()
