#!/usr/bin/python3
"""Writes ironing_die_p2.nurbs, the D-shaped die of prm/ironing.prm as
one NURBS patch of degree 2 (the isogeometric die of the ironing study,
doc/studies/ironing.md): a half disk of radius 1, centre (1.2, 5.02),
under a 2 x 1 rectangle, as make_ironing_die_mesh.py draws it for Gmsh.

The D has two corners (the top's); a patch has four. The other two are
where the arc meets the sides, tangentially: corners of 180 degrees,
where the patch's Jacobian vanishes at that one point (as at the
quarter disk's, make_quarter_disk_patches.py). So the whole arc is one
side, exact and C1: the half circle as a rational quadratic B-spline of
four control points, L, (0.2, 4.02), (2.2, 4.02), R, weights 1, 1/2,
1/2, 1, knots 0 0 0 1/2 1 1 1 (each span a quarter circle: its Bezier
points L, (0.2, 4.02), (1.2, 4.02) with weights 1, 1/2, 1/2 satisfy the
conic's w1^2 / (w0 w2) = cos^2 45).

  eta0  arc    from L = (0.2, 5.02) down through (1.2, 4.02) up to
               R = (2.2, 5.02)
  xi1   right  from R up to (2.2, 6.02)
  eta1  top    from (0.2, 6.02) to (2.2, 6.02)
  xi0   left   from L up to (0.2, 6.02)

The middle row of control points is the mean of the arc's and the top's
in homogeneous coordinates (the Coons blend: the sides are straight).

Run from prm/meshes: /usr/bin/python3 make_ironing_die_patch.py
"""
from make_quarter_disk_patches import homogeneous, write

CX, CY, R = 1.2, 5.02, 1.0

arc = [homogeneous(CX - R, CY, 1), homogeneous(CX - R, CY - R, 0.5),
       homogeneous(CX + R, CY - R, 0.5), homogeneous(CX + R, CY, 1)]
# (the top's control points at the Greville abscissae 0, 1/4, 3/4, 1 of
# the knots 0 0 0 1/2 1 1 1: a straight line at uniform speed)
top = [homogeneous(CX - R + 2 * R * g, CY + 1, 1)
       for g in (0, 0.25, 0.75, 1)]
middle = [[(a[k] + b[k]) / 2 for k in range(3)] for a, b in zip(arc, top)]
write([arc, middle, top], "ironing_die_p2.nurbs",
      "# The ironing die (prm/ironing.prm): a half disk of radius 1, centre\n"
      "# (1.2, 5.02), under a 2 x 1 rectangle, as one NURBS patch of degree 2\n"
      "# (written by make_ironing_die_patch.py, which explains its corners).\n",
      xi_knots="0 0 0 0.5 1 1 1",
      names=(("arc", "eta0"), ("right", "xi1"), ("top", "eta1"),
             ("left", "xi0")))
