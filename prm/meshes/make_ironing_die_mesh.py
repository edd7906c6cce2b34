#!/usr/bin/python3
"""Writes ironing_die.msh, the die of prm/ironing.prm: the D of MOOSE's
ironing test (modules/contact/test/tests/pdass_problems/ironing_mesh.jou,
after Yang, Laursen and Meng 2005): a half disk of radius 1 below a 2 x 1
rectangle, the disk's centre at (1.2, 5.02), so that the die spans x in
[0.2, 2.2] and its lowest point is 0.02 above the slab's top (y = 4).
Element edges as MOOSE's: 18 along the arc, 6 up each side, 10 across the
top (quadrilaterals: Gmsh's Frontal-Delaunay paired by Blossom).
Physical groups: contact (the arc and the two sides), top, die.

Needs Gmsh's Python module (Debian: python3-gmsh, in /usr/bin/python3).
Run from prm/meshes: /usr/bin/python3 make_ironing_die_mesh.py
"""
import gmsh

from make_hertz_sphere_meshes import generate_quadrilaterals_and_write

gmsh.initialize(readConfigFiles=False)
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("die")
geo = gmsh.model.geo
cx, cy, r = 1.2, 5.02, 1.0
centre = geo.addPoint(cx, cy, 0)
left = geo.addPoint(cx - r, cy, 0)
bottom = geo.addPoint(cx, cy - r, 0)
right = geo.addPoint(cx + r, cy, 0)
top_right = geo.addPoint(cx + r, cy + 1, 0)
top_left = geo.addPoint(cx - r, cy + 1, 0)
arc_left = geo.addCircleArc(left, centre, bottom)
arc_right = geo.addCircleArc(bottom, centre, right)
side_right = geo.addLine(right, top_right)
top = geo.addLine(top_right, top_left)
side_left = geo.addLine(top_left, left)
loop = geo.addCurveLoop([arc_left, arc_right, side_right, top, side_left])
die = geo.addPlaneSurface([loop])
for curve, n in ((arc_left, 10), (arc_right, 10), (side_right, 7),
                 (side_left, 7), (top, 11)):
    geo.mesh.setTransfiniteCurve(curve, n)
geo.synchronize()
for dim, tags, name, number in ((1, [arc_left, arc_right, side_right, side_left],
                                 "contact", 1),
                                (1, [top], "top", 2), (2, [die], "die", 3)):
    gmsh.model.addPhysicalGroup(dim, tags, number)
    gmsh.model.setPhysicalName(dim, number, name)
generate_quadrilaterals_and_write("ironing_die.msh")
