#!/usr/bin/python3
"""Writes the meshes of prm/cattaneo_mindlin.prm (and of
tests/cattaneo_mindlin_test.cc): a cylinder of radius 1 pressed on a
block and then pulled sideways, plane strain, the whole width (a
tangential load has no symmetry line), graded as the Hertz meshes of
make_hertz_sphere_meshes.py (0.0025 at the contact point on the
cylinder, 0.0021 on the block, so that their nodes do not match).

- cattaneo_cylinder.msh: the lower half of the disk of centre (0, 1),
  touching y = 0 at the origin; physical groups arc (the half circle
  from (-1, 1) through (0, 0) to (1, 1)), top (its diameter, y = 1),
  cylinder;
- cattaneo_block.msh: the block [-1, 1] x [-1, 0]; physical groups top,
  bottom, left, right, block;
- hertz_lower_cylinder_r2.msh: the upper half of the disk of radius 2
  and centre (0, -2), touching y = 0 at the origin, graded as the block
  (prm/hertz_two_cylinders.prm: the cylinder above on it); physical
  groups arc, bottom (its diameter, y = -2), cylinder.

Needs Gmsh's Python module (Debian: python3-gmsh, in /usr/bin/python3).
Run from prm/meshes: /usr/bin/python3 make_cattaneo_meshes.py
"""
import gmsh

from make_hertz_sphere_meshes import mesh_and_write


def start(name):
    gmsh.initialize(readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add(name)
    return gmsh.model.geo


def name_groups(groups):
    gmsh.model.geo.synchronize()
    for number, (dim, tags, name) in enumerate(groups, start=1):
        gmsh.model.addPhysicalGroup(dim, tags, number)
        gmsh.model.setPhysicalName(dim, number, name)


def write_half_disk(path, radius, side, flat, h_contact):
    """A half disk touching y = 0 at the origin, counter-clockwise: the
    lower half of the disk of centre (0, radius) for side = 1, the upper
    half of the disk of centre (0, -radius) for side = -1; its diameter
    named `flat`."""
    geo = start("cylinder")
    contact = geo.addPoint(0, 0, 0)
    centre = geo.addPoint(0, side * radius, 0)
    left = geo.addPoint(-radius, side * radius, 0)
    right = geo.addPoint(radius, side * radius, 0)
    first, last = (left, right) if side > 0 else (right, left)
    arcs = [geo.addCircleArc(first, centre, contact),
            geo.addCircleArc(contact, centre, last)]
    diameter = geo.addLine(last, first)
    cylinder = geo.addPlaneSurface([geo.addCurveLoop(arcs + [diameter])])
    name_groups([(1, arcs, "arc"), (1, [diameter], flat),
                 (2, [cylinder], "cylinder")])
    mesh_and_write(contact, path, h_contact)


def write_block(path):
    """The block [-1, 1] x [-1, 0], its top the flat under the cylinder."""
    geo = start("block")
    contact = geo.addPoint(0, 0, 0)
    top_right = geo.addPoint(1, 0, 0)
    top_left = geo.addPoint(-1, 0, 0)
    low_left = geo.addPoint(-1, -1, 0)
    low_right = geo.addPoint(1, -1, 0)
    # the top in two lines, so that the contact point is a node
    top = [geo.addLine(top_right, contact), geo.addLine(contact, top_left)]
    left = geo.addLine(top_left, low_left)
    bottom = geo.addLine(low_left, low_right)
    right = geo.addLine(low_right, top_right)
    block = geo.addPlaneSurface(
        [geo.addCurveLoop(top + [left, bottom, right])])
    name_groups([(1, top, "top"), (1, [bottom], "bottom"),
                 (1, [left], "left"), (1, [right], "right"),
                 (2, [block], "block")])
    mesh_and_write(contact, path, 0.0021)


if __name__ == "__main__":
    write_half_disk("cattaneo_cylinder.msh", 1.0, 1, "top", 0.0025)
    write_block("cattaneo_block.msh")
    write_half_disk("hertz_lower_cylinder_r2.msh", 2.0, -1, "bottom", 0.0021)
