#!/usr/bin/python3
"""GetFEM's multi-body mesh (tests/meshes/multi_body.mesh, the mesh of its
demo_large_sliding_contact.py, case 3) as quadrilaterals that glissade and
GetFEM both read.

GetFEM's mesh is ten bodies of linear triangles in one mesh, three of them
with a hole. glissade's element spaces are quadrilaterals, so each triangle
is cut into three quadrilaterals (its vertices, edge midpoints and
centroid): the same bodies, the same boundary (every boundary edge cut in
two at its midpoint), and one mesh for both codes. Nothing of GetFEM's file
is kept here: give the path of a copy (from GetFEM's sources,
https://github.com/getfem/getfem/blob/master/tests/meshes/multi_body.mesh).

Used by multi_body_race.py; run alone it prints the bodies:

    /usr/bin/python3 benchmarks/peers/multi_body_mesh.py PATH/multi_body.mesh
"""

import sys

import numpy as np


def read_getfem_mesh(path):
    """Points (n x 2) and triangles (m x 3) of a GetFEM mesh file of
    GT_PK(2,1) convexes."""
    points, triangles = {}, []
    section = None
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words or words[0].startswith("%"):
                continue
            if words[0] == "BEGIN":
                section = " ".join(words[1:])
                continue
            if words[0] == "END":
                section = None
                continue
            if section == "POINTS LIST" and words[0] == "POINT":
                points[int(words[1])] = (float(words[2]), float(words[3]))
            elif section == "MESH STRUCTURE DESCRIPTION" and \
                    words[0] == "CONVEX":
                if words[2] != "'GT_PK(2,1)'":
                    sys.exit(f"{path}: convex {words[1]} is {words[2]}, "
                             "only GT_PK(2,1) triangles are read")
                triangles.append([int(w) for w in words[3:6]])
    if not points or not triangles:
        sys.exit(f"{path}: no points or no triangles found (a GetFEM mesh "
                 "file of linear triangles is expected)")
    index = {pid: k for k, pid in enumerate(sorted(points))}
    xy = np.array([points[pid] for pid in sorted(points)])
    tri = np.array([[index[p] for p in t] for t in triangles])
    return xy, tri


def connected_bodies(n_points, triangles):
    """The triangles of each connected body, bodies ordered by their
    lowest point number."""
    parent = list(range(n_points))

    def root(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for t in triangles:
        for b in t[1:]:
            ra, rb = root(t[0]), root(b)
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)
    groups = {}
    for k, t in enumerate(triangles):
        groups.setdefault(root(t[0]), []).append(k)
    return [np.array(groups[r]) for r in sorted(groups)]


class QuadBody:
    """One body: its points, counterclockwise quadrilaterals and boundary
    segments (pairs of local point numbers)."""

    def __init__(self, points, quads, boundary):
        self.points = points
        self.quads = quads
        self.boundary = boundary

    def area(self):
        p = self.points
        a = 0.
        for q in self.quads:
            x, y = p[q, 0], p[q, 1]
            a += 0.5 * (np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))
        return a


def midpoints_in(points, midpoint):
    """A function (a, b) -> the number of the point midway between points a
    and b, appended to `points` the first time (`midpoint` remembers)."""
    def middle(a, b):
        key = (min(a, b), max(a, b))
        if key not in midpoint:
            midpoint[key] = len(points)
            points.append(0.5 * (points[a] + points[b]))
        return midpoint[key]
    return middle


def split_into_quads(xy, triangles):
    """Each triangle into three quadrilaterals through its edge midpoints
    and centroid; returns the body's points, quads and boundary segments."""
    used = np.unique(triangles)
    local = {g: k for k, g in enumerate(used)}
    points = [xy[g] for g in used]
    midpoint = {}
    middle = midpoints_in(points, midpoint)

    quads, edge_count = [], {}
    for t in triangles:
        a, b, c = (local[g] for g in t)
        pa, pb, pc = points[a], points[b], points[c]
        if (pb[0] - pa[0]) * (pc[1] - pa[1]) - \
                (pb[1] - pa[1]) * (pc[0] - pa[0]) < 0.:
            b, c = c, b
        g = len(points)
        points.append((points[a] + points[b] + points[c]) / 3.)
        mab, mbc, mca = middle(a, b), middle(b, c), middle(c, a)
        quads += [[a, mab, g, mca], [b, mbc, g, mab], [c, mca, g, mbc]]
        for e in ((a, b), (b, c), (c, a)):
            key = (min(e), max(e))
            edge_count[key] = edge_count.get(key, 0) + 1
    boundary = []
    for (a, b), n in edge_count.items():
        if n == 1:
            m = midpoint[(a, b)]
            boundary += [[a, m], [m, b]]
    return QuadBody(np.array(points), np.array(quads), np.array(boundary))


def refined(body):
    """Each quadrilateral into four (edge midpoints and centre), each
    boundary segment into two: the same polygonal bodies."""
    points = [p for p in body.points]
    middle = midpoints_in(points, {})

    quads = []
    for a, b, c, d in body.quads:
        centre = len(points)
        points.append(0.25 * (points[a] + points[b] + points[c] + points[d]))
        ab, bc, cd, da = middle(a, b), middle(b, c), middle(c, d), middle(d, a)
        quads += [[a, ab, centre, da], [ab, b, bc, centre],
                  [centre, bc, c, cd], [da, centre, cd, d]]
    boundary = []
    for a, b in body.boundary:
        m = middle(a, b)
        boundary += [[a, m], [m, b]]
    return QuadBody(np.array(points), np.array(quads), np.array(boundary))


def multi_body_quads(path, refinements=0):
    """The ten bodies of GetFEM's multi_body.mesh as QuadBody objects, each
    quadrilateral cut into 4^refinements."""
    xy, triangles = read_getfem_mesh(path)
    bodies = [split_into_quads(xy, triangles[group])
              for group in connected_bodies(len(xy), triangles)]
    for _ in range(refinements):
        bodies = [refined(b) for b in bodies]
    return bodies


def boundary_loops(body):
    """The body's boundary segments grouped by closed curve, the outer one
    (the widest) first."""
    parent = {}

    def root(a):
        parent.setdefault(a, a)
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for a, b in body.boundary:
        ra, rb = root(a), root(b)
        if ra != rb:
            parent[max(ra, rb)] = min(ra, rb)
    loops = {}
    for k, (a, _) in enumerate(body.boundary):
        loops.setdefault(root(a), []).append(k)
    loops = list(loops.values())
    loops.sort(key=lambda ks: -np.ptp(body.points[body.boundary[ks].ravel()],
                                      axis=0).max())
    return loops


def write_msh(body, path):
    """A body as a Gmsh 2.2 file: its quads in the Physical Surface 'body'
    and its whole boundary, the outer curve and the walls of its holes, in
    the Physical Line 'surface' (every boundary takes part in the contact,
    as in GetFEM's demo)."""
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
        f.write("$PhysicalNames\n2\n1 2 \"surface\"\n2 1 \"body\"\n"
                "$EndPhysicalNames\n")
        f.write(f"$Nodes\n{len(body.points)}\n")
        for k, (x, y) in enumerate(body.points):
            f.write(f"{k + 1} {x:.17g} {y:.17g} 0\n")
        f.write("$EndNodes\n")
        f.write(f"$Elements\n{len(body.boundary) + len(body.quads)}\n")
        k = 1
        for a, b in body.boundary:
            f.write(f"{k} 1 2 2 2 {a + 1} {b + 1}\n")
            k += 1
        for q in body.quads:
            f.write(f"{k} 3 2 1 1 " + " ".join(str(v + 1) for v in q) + "\n")
            k += 1
        f.write("$EndElements\n")


def _main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    bodies = multi_body_quads(sys.argv[1])
    for k, body in enumerate(bodies):
        lo, hi = body.points.min(0), body.points.max(0)
        print(f"body{k}: {len(body.quads)} quads, {len(body.points)} nodes, "
              f"area {body.area():.4f}, {len(body.boundary)} boundary "
              f"segments in {len(boundary_loops(body))} curves, box [{lo[0]:.3f}, {hi[0]:.3f}] x "
              f"[{lo[1]:.3f}, {hi[1]:.3f}]")


if __name__ == "__main__":
    _main()
