#!/usr/bin/python3
"""Writes the meshes of prm/hertz_sphere.prm and prm/hertz_two_spheres.prm
(and of the axisymmetric Hertz tests, tests/axisymmetric_test.cc):
the meridian of a sphere of radius 1 touching y = 0 at the origin, x = r
in [0, 1] (the axis is x = 0), graded to 0.0025 within 0.08 of the contact
point and 0.08 beyond 1.5 from it (quadrilaterals: Gmsh's Frontal-Delaunay
paired by Blossom). Physical groups: arc (the sphere's surface), axis,
top (the equatorial plane), sphere.

- hertz_sphere_upper.msh: the sphere above the plane, centre (0, 1);
- hertz_sphere_lower.msh: its mirror below, centre (0, -1);
- hertz_sphere_whole.msh: the whole sphere's meridian, the half disk
  x >= 0 of centre (0, 1) (prm/sphere_impact.prm), its arc the whole
  surface;
- hertz_flat_block.msh: a block [0, 1] x [-1, 0] under the contact point
  (the plane-strain cylinder on a deformable flat of tests/mortar_test.cc),
  graded to 0.0021 at the contact, so that its nodes do not match the
  upper sphere's 0.0025 (physical groups top, axis, bottom, right, block).

Needs Gmsh's Python module (Debian: python3-gmsh, in /usr/bin/python3).
Run from prm/meshes: /usr/bin/python3 make_hertz_sphere_meshes.py
"""
import re

import gmsh

H_CONTACT, FINE, FAR, COARSE = 0.0025, 0.08, 1.5, 0.08


def mesh_and_write(contact, path, h_contact=H_CONTACT):
    """Meshes the model, graded from the contact point, and writes it."""
    field = gmsh.model.mesh.field
    distance = field.add("Distance")
    field.setNumbers(distance, "PointsList", [contact])
    size = field.add("Threshold")
    field.setNumber(size, "InField", distance)
    field.setNumber(size, "SizeMin", h_contact)
    field.setNumber(size, "SizeMax", COARSE)
    field.setNumber(size, "DistMin", FINE)
    field.setNumber(size, "DistMax", FAR)
    field.setAsBackgroundMesh(size)
    for option, value in (("Mesh.MeshSizeExtendFromBoundary", 0),
                          ("Mesh.MeshSizeFromPoints", 0),
                          ("Mesh.MeshSizeFromCurvature", 0)):
        gmsh.option.setNumber(option, value)
    generate_quadrilaterals_and_write(path)


def generate_quadrilaterals_and_write(path):
    """Meshes the model in quadrilaterals (Frontal-Delaunay paired by
    Blossom), writes it as Gmsh 2.2 text with ten significant digits per
    coordinate (plenty for a mesh, and half the file), and finalises
    Gmsh (also used by make_ironing_die_mesh.py)."""
    for option, value in (("Mesh.Algorithm", 6), ("Mesh.RecombineAll", 1),
                          ("Mesh.RecombinationAlgorithm", 1),
                          ("Mesh.ElementOrder", 1),
                          ("Mesh.MshFileVersion", 2.2), ("Mesh.Binary", 0)):
        gmsh.option.setNumber(option, value)
    gmsh.model.mesh.generate(2)
    gmsh.write(path)
    gmsh.finalize()
    text = open(path).read()
    head, nodes, tail = re.split(r"(?<=\$Nodes\n)|(?=\$EndNodes)", text)
    lines = nodes.strip().split("\n")
    out = [lines[0]] + [" ".join([f[0]] + [f"{float(v):.10g}" for v in f[1:]])
                        for f in (line.split() for line in lines[1:])]
    open(path, "w").write(head + "\n".join(out) + "\n" + tail)


def write(path, side):
    """The quarter disk of centre (0, side): the hemisphere touching y = 0."""
    gmsh.initialize(readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("sphere")
    geo = gmsh.model.geo
    contact = geo.addPoint(0, 0, 0)
    centre = geo.addPoint(0, side, 0)
    equator = geo.addPoint(1, side, 0)
    arc = geo.addCircleArc(contact, centre, equator)
    top = geo.addLine(equator, centre)
    axis = geo.addLine(centre, contact)
    # counter-clockwise in both: the lower sphere's loop runs backwards
    loop = geo.addCurveLoop([arc, top, axis] if side > 0 else [-axis, -top, -arc])
    sphere = geo.addPlaneSurface([loop])
    geo.synchronize()
    for dim, tag, name, number in ((1, arc, "arc", 1), (1, axis, "axis", 2),
                                   (1, top, "top", 3), (2, sphere, "sphere", 4)):
        gmsh.model.addPhysicalGroup(dim, [tag], number)
        gmsh.model.setPhysicalName(dim, number, name)
    mesh_and_write(contact, path)


def write_whole(path):
    """The whole sphere's meridian: the half disk x >= 0 of centre (0, 1),
    its arc from the contact point (0, 0) round to (0, 2)."""
    gmsh.initialize(readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("sphere")
    geo = gmsh.model.geo
    contact = geo.addPoint(0, 0, 0)
    centre = geo.addPoint(0, 1, 0)
    equator = geo.addPoint(1, 1, 0)
    pole = geo.addPoint(0, 2, 0)
    lower = geo.addCircleArc(contact, centre, equator)
    upper = geo.addCircleArc(equator, centre, pole)
    axis = geo.addLine(pole, contact)
    sphere = geo.addPlaneSurface([geo.addCurveLoop([lower, upper, axis])])
    geo.synchronize()
    for dim, tags, name, number in ((1, [lower, upper], "arc", 1),
                                    (1, [axis], "axis", 2),
                                    (2, [sphere], "sphere", 4)):
        gmsh.model.addPhysicalGroup(dim, tags, number)
        gmsh.model.setPhysicalName(dim, number, name)
    mesh_and_write(contact, path)


def write_flat_block(path):
    """A block [0, 1] x [-1, 0], its top the flat under the contact point."""
    gmsh.initialize(readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("block")
    geo = gmsh.model.geo
    contact = geo.addPoint(0, 0, 0)
    corner = geo.addPoint(1, 0, 0)
    low_right = geo.addPoint(1, -1, 0)
    low_left = geo.addPoint(0, -1, 0)
    top = geo.addLine(corner, contact)
    axis = geo.addLine(contact, low_left)
    bottom = geo.addLine(low_left, low_right)
    right = geo.addLine(low_right, corner)
    block = geo.addPlaneSurface([geo.addCurveLoop([top, axis, bottom, right])])
    geo.synchronize()
    for dim, tag, name, number in ((1, top, "top", 1), (1, axis, "axis", 2),
                                   (1, bottom, "bottom", 3),
                                   (1, right, "right", 4),
                                   (2, block, "block", 5)):
        gmsh.model.addPhysicalGroup(dim, [tag], number)
        gmsh.model.setPhysicalName(dim, number, name)
    mesh_and_write(contact, path, 0.0021)


if __name__ == "__main__":
    write("hertz_sphere_upper.msh", 1.0)
    write("hertz_sphere_lower.msh", -1.0)
    write_whole("hertz_sphere_whole.msh")
    write_flat_block("hertz_flat_block.msh")
