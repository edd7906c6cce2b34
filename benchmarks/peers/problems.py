#!/usr/bin/python3
"""The problems of the peers benchmark (issue 19), shared by glissade's
runner and the peers (GetFEM, CalculiX): meshes, loads and closed forms.

Problem 1, two concentric rings: inner r in [0.5, 1.25] clamped at
r = 0.5, outer r in [1.25, 2], E = 1000, nu = 0.3, plane strain, a radial
inward nodal force LOAD / N on each of the N nodes of r = 2, frictionless
contact between the outer ring's inner edge (master) and the inner ring's
outer edge (slave), touching with zero gap. The outer ring is held against
rigid motion by four tangential supports on r = 2 (u_y = 0 at theta = 0
and pi, u_x = 0 at theta = pi/2 and 3 pi/2), which carry nothing by
symmetry (N is a multiple of 4 so that these nodes exist). Reference:
Lame's solution for one ring a = 0.5, b = 2 (the two rings are then one).

Problem 2, Hertz: a quarter disk R = 1 centred at (0, 1) (x >= 0,
y <= 1), E = 200, nu = 0.3, plane strain, u_x = 0 on x = 0, the top edge
y = 1 driven down by 0.0055, frictionless on the rigid flat y = 0.
Reference: Hertz's plane strain cylinder at the load P that the computed
contact carries.

The contact patch test (issue 36): two blocks on non-matching meshes
(tests/mortar_test.cc, patch_scene), E = 1000, nu = 0.3, plane strain,
the upper [0, 1] x [0.5, 1] on the lower [0, 1] x [0, 0.5], frictionless
(the upper top pushed down, the right sides free) or sticking (every
outer side moved homogeneously). Reference: the uniform stress, each slave
node's traction equal to the applied one (patch_figures).

The module needs only numpy; hertz_mesh needs gmsh, which lives in
Debian's /usr/bin/python3 (it runs itself there when imported elsewhere).

    /usr/bin/python3 problems.py                 # prints the closed forms
    /usr/bin/python3 problems.py mesh H FILE     # writes the Hertz mesh
"""

import math
import os
import subprocess
import sys

import numpy as np

PYTHON = "/usr/bin/python3"

# ------------------------------------------------------------------ rings
RING_E = 1000.0
RING_NU = 0.3
R_CLAMP = 0.5           # inner ring's inner radius, clamped
R_INTERFACE = 1.25      # the contact interface
R_LOADED = 2.0          # outer ring's outer radius, loaded
LOAD_SCALE = 1e-3       # glissade is large-strain: keep it linear
LOAD = 400.0 * LOAD_SCALE   # total radial inward force on r = 2


def lame_coefficients(E, nu):
    """(lambda, mu), 3D values (plane strain uses them as they are)."""
    return E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))


def ring_nodal_force(n):
    """Magnitude of the radial inward force on each of the n nodes of
    r = 2 (the nodal forces of a uniform pressure LOAD / (2 pi 2) on the
    polygon with n sides, all equal)."""
    return LOAD / n


def lame_A(load=LOAD, E=RING_E, nu=RING_NU, a=R_CLAMP, b=R_LOADED):
    """u_r(r) = A (r - a^2 / r) for a ring a < r < b, u(a) = 0, with the
    pressure p = load / (2 pi b) on r = b. Plane strain: sigma_rr =
    2 (lambda + mu) A + 2 mu A a^2 / r^2, and sigma_rr(b) = -p."""
    lam, mu = lame_coefficients(E, nu)
    p = load / (2 * math.pi * b)
    return -p / (2 * (lam + mu) + 2 * mu * a * a / (b * b))


def lame_u_r(r, load=LOAD):
    a = R_CLAMP
    return lame_A(load) * (r - a * a / r)


def lame_u_r2(load=LOAD):
    """Radial displacement at r = 2: -0.0302783 * LOAD_SCALE.
    Check: lambda = 576.923, mu = 384.615, p = 0.4 / (4 pi) = 0.0318310,
    A = -0.0318310 / (2 * 961.538 + 2 * 384.615 / 16) = -1.614843e-5,
    u_r(2) = A (2 - 0.125) = -3.02783e-5."""
    return lame_u_r(R_LOADED, load)


def lame_interface_pressure(load=LOAD):
    """Contact pressure -sigma_rr(1.25) = 33.0421 * LOAD_SCALE.
    Check: -A (2 * 961.538 + 2 * 384.615 * 0.25 / 1.5625) = 1.614843e-5 *
    2046.154 = 0.0330421."""
    lam, mu = lame_coefficients(RING_E, RING_NU)
    a, r = R_CLAMP, R_INTERFACE
    return -lame_A(load) * (2 * (lam + mu) + 2 * mu * a * a / (r * r))


def ring_mesh(n_around, r_in, r_out, n_through=None):
    """One ring's structured Q4 mesh, nodes exactly as glissade's ring
    mesher (source/mesh/mesh_factory.cc, create_ring) makes them: node
    i * (n_through + 1) + j at theta = 2 pi i / n_around,
    r = r_in + (r_out - r_in) j / n_through.

    Returns (nodes (n, 2) float, cells (m, 4) int), the cells
    counter-clockwise: (i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j),
    i + 1 wrapping to 0 (glissade's deal.II order is (i, j), (i, j + 1),
    (i + 1, j), (i + 1, j + 1): see lexicographic())."""
    if n_through is None:
        n_through = n_around // 10
    i = np.arange(n_around)
    j = np.arange(n_through + 1)
    theta = 2 * math.pi * i / n_around
    r = r_in + (r_out - r_in) * j / n_through
    # Python's math gives the same doubles as std::cos / std::sin on glibc;
    # numpy's vectorised cos may differ in the last bit, so use math.
    nodes = np.array([[rr * math.cos(t), rr * math.sin(t)]
                      for t in theta for rr in r])
    ii, jj = np.meshgrid(i, np.arange(n_through), indexing="ij")
    ii, jj = ii.ravel(), jj.ravel()
    ip = (ii + 1) % n_around

    def v(a, b):
        return a * (n_through + 1) + b
    cells = np.stack([v(ii, jj), v(ii, jj + 1), v(ip, jj + 1), v(ip, jj)],
                     axis=1)
    return nodes, cells


def lexicographic(quads):
    """Counter-clockwise quads -> deal.II / GetFEM order (v0, v1, v3, v2)."""
    quads = np.asarray(quads)
    return quads[:, [0, 1, 3, 2]]


def ring_edge_nodes(n_around, n_through, j):
    """Node indices of one ring's circle j (0 = inner, n_through = outer),
    in order of increasing theta."""
    return np.arange(n_around) * (n_through + 1) + j


def rings(n):
    """Both rings for N = n: a dict with the nodes and cells of 'inner'
    and 'outer' (separate node numberings, coincident nodes on r = 1.25),
    the node sets clamped, loaded, slave, master, the four supports
    [(node, component)] of the outer ring, and the nodal force."""
    if n % 4 or n % 10:
        raise ValueError("N must be a multiple of 20 (n / 10 cells through, "
                         "supports at theta = k pi / 2)")
    nt = n // 10
    inner_nodes, inner_cells = ring_mesh(n, R_CLAMP, R_INTERFACE, nt)
    outer_nodes, outer_cells = ring_mesh(n, R_INTERFACE, R_LOADED, nt)
    loaded = ring_edge_nodes(n, nt, nt)          # outer ring, r = 2
    q = n // 4
    supports = [(loaded[0], 1), (loaded[2 * q], 1),   # theta = 0, pi: u_y
                (loaded[q], 0), (loaded[3 * q], 0)]   # pi/2, 3pi/2: u_x
    return {
        "n": n, "n_through": nt,
        "inner": (inner_nodes, inner_cells),
        "outer": (outer_nodes, outer_cells),
        "clamped": ring_edge_nodes(n, nt, 0),     # inner ring, r = 0.5
        "slave": ring_edge_nodes(n, nt, nt),      # inner ring, r = 1.25
        "master": ring_edge_nodes(n, nt, 0),      # outer ring, r = 1.25
        "loaded": loaded,
        "supports": supports,
        "nodal_force": ring_nodal_force(n),
    }


# ------------------------------------------------------------------ Hertz
HERTZ_E = 200.0
HERTZ_NU = 0.3
HERTZ_R = 1.0
HERTZ_DRIVE = 0.0055     # the top edge's downward displacement
# The graded mesh: element size h_contact within HERTZ_FINE of the origin
# (the contact and the material under it), then growing linearly with the
# distance, by (HERTZ_COARSE - h) / (HERTZ_FAR - HERTZ_FINE), about 2.3 %
# of it (HERTZ_COARSE itself is never reached: the farthest point, (1, 1),
# is at 1.41; the size there is about 0.03). Dofs (2 x nodes) with
# Gmsh 4.8.4: h = 0.01: 5,110; 0.005: 9,626; 0.0025: 18,000;
# 0.00125: 36,534 (the earlier measurement had 37,466).
HERTZ_FINE = 0.1
HERTZ_FAR = 2.3
HERTZ_COARSE = 0.05


def hertz_reference(P, E=HERTZ_E, nu=HERTZ_NU, R=HERTZ_R):
    """Hertz, plane strain cylinder on a rigid flat, P the force per unit
    thickness of the full contact: (p0, a)."""
    e_star = E / (1 - nu * nu)
    a = math.sqrt(4 * P * R / (math.pi * e_star))
    return 2 * P / (math.pi * a), a


# The axisymmetric Hertz problem (issue 34): the same quarter disk, x = r
# and y the axis, is the meridian of a sphere of radius 1; its top (the
# equatorial plane) driven down by SPHERE_DRIVE puts a / R near 0.05.
SPHERE_DRIVE = 0.0027


def sphere_reference(P, E=HERTZ_E, nu=HERTZ_NU, R=HERTZ_R):
    """Hertz, a sphere on a rigid flat, P the total load: (p0, a)."""
    e_star = E / (1 - nu * nu)
    a = (3 * P * R / (4 * e_star)) ** (1 / 3)
    return 3 * P / (2 * math.pi * a * a), a


def sphere_figures_from_ring_forces(x, y, force):
    """(p0, a, P) of an axisymmetric contact from its arc nodes' ring forces
    (for the full turn), as glissade's tests read them:

    x, y   the reference position of each node of the arc (x = r),
    force  its axial contact force (> 0 pushing the sphere up).

    P  = sum(force) over the contact zone (hertz_contact_zone),
    a  = sqrt(5 / 2 sum(force r^2) / P): for p0 sqrt(1 - r^2 / a^2) on the
         disk, sum f r^2 = (2 / 5) a^2 P,
    p0 = the force of the node on the axis over the ring its hat function
         covers on its face, 2 pi L (2 r_0 + r_1) / 6 = pi L r_1 / 3.
    """
    order = np.argsort(np.asarray(x, dtype=float))
    x = np.asarray(x, dtype=float)[order]
    y = np.asarray(y, dtype=float)[order]
    _, f = hertz_contact_zone(x, np.asarray(force, dtype=float)[order])
    P = float(f.sum())
    a = math.sqrt(2.5 * float((f * x * x).sum()) / P)
    length = math.hypot(x[1] - x[0], y[1] - y[0])
    p0 = float(f[0]) / (2 * math.pi * length * (2 * x[0] + x[1]) / 6)
    return p0, a, P


def axisymmetric_quad_internal_forces(nodes, quads, u, E, nu):
    """f = K u for axisymmetric Q1 (x = r), full 2 x 2 Gauss, the nodal
    forces of the full turn (2 pi r dA): CalculiX's CAX4 in the plane.
    (n, 2); u is (n, 2)."""
    lam, mu = lame_coefficients(E, nu)
    D = np.array([[lam + 2 * mu, lam, lam, 0], [lam, lam + 2 * mu, lam, 0],
                  [lam, lam, lam + 2 * mu, 0], [0, 0, 0, mu]])
    X, U = nodes[quads], u[quads]
    f = np.zeros_like(u)
    g = 1 / math.sqrt(3)
    ref = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=float)
    for xi, eta in ((-g, -g), (g, -g), (g, g), (-g, g)):
        N = (1 + ref[:, 0] * xi) * (1 + ref[:, 1] * eta) / 4          # (4,)
        dN = np.stack([ref[:, 0] * (1 + ref[:, 1] * eta) / 4,
                       ref[:, 1] * (1 + ref[:, 0] * xi) / 4], axis=1)  # (4,2)
        J = np.einsum("mai,aj->mij", X, dN)
        det = J[:, 0, 0] * J[:, 1, 1] - J[:, 0, 1] * J[:, 1, 0]
        inv = np.empty_like(J)
        inv[:, 0, 0], inv[:, 1, 1] = J[:, 1, 1] / det, J[:, 0, 0] / det
        inv[:, 0, 1], inv[:, 1, 0] = -J[:, 0, 1] / det, -J[:, 1, 0] / det
        G = np.einsum("aj,mji->mai", dN, inv)                          # (m,4,2)
        r = X[:, :, 0] @ N                                              # (m,)
        grad = np.einsum("mak,mai->mki", U, G)
        u_r = U[:, :, 0] @ N
        eps = np.stack([grad[:, 0, 0], grad[:, 1, 1], u_r / r,
                        grad[:, 0, 1] + grad[:, 1, 0]], axis=1)  # rr zz tt rz
        s = eps @ D.T
        w = 2 * math.pi * r * det
        f_r = (s[:, 0, None] * G[:, :, 0] + s[:, 3, None] * G[:, :, 1]
               + s[:, 2, None] * N[None, :] / r[:, None]) * w[:, None]
        f_z = (s[:, 1, None] * G[:, :, 1] + s[:, 3, None] * G[:, :, 0]) * w[:, None]
        np.add.at(f, quads, np.stack([f_r, f_z], axis=2))
    return f


CONTACT_THRESHOLD = 1e-3   # relative to the largest nodal force


def hertz_contact_zone(x, force):
    """(x, force) sorted by x, the forces outside the contact zone set to
    0. The zone is the run of consecutive nodes, from the first loaded one
    on (the axis node), whose force exceeds CONTACT_THRESHOLD times the
    largest: forces computed as K u from rounded displacements (CalculiX
    writes 6 digits) leave a noise of about 1e-4 of the largest force on
    nodes far from the contact, which would weigh in the second moment
    (x^2 up to 1). Cutting at 1e-3 changes a by less than 1e-4 relative."""
    x = np.asarray(x, dtype=float)
    f = np.asarray(force, dtype=float)
    order = np.argsort(x)
    x, f = x[order], f[order]
    if len(f) == 0 or f.max() <= 0:
        return x, np.zeros_like(f)
    loaded = f > CONTACT_THRESHOLD * f.max()
    first = int(np.argmax(loaded))
    last = first
    while last + 1 < len(f) and loaded[last + 1]:
        last += 1
    zone = np.zeros_like(f)
    zone[first:last + 1] = f[first:last + 1]
    return x, zone


def hertz_figures_from_nodal_forces(x, force):
    """(p0, a, P) of the full contact from the quarter model's nodal
    contact forces, as every code reports them the same way:

    x      the undeformed (reference) abscissa of each node of the arc,
    force  its normal contact force (> 0 pushing the disk up); nodes out
           of contact may be left in with force 0. The node at x = 0 is on
           the symmetry axis: it carries half of the full model's force.

    Only the contact zone counts (hertz_contact_zone: the consecutive
    nodes from the axis whose force exceeds 1e-3 of the largest).
    P  = 2 * sum(force)                         (the full contact),
    p0 = the largest nodal pressure force_i / l_i, with l_i the node's
         tributary length (x_{i+1} - x_{i-1}) / 2 along x, the model
         mirrored about x = 0 (the axis node: x_1 / 2 for its half force),
    a  = 2 sqrt(sum(force x^2) / sum(force)): the half-width of the
         pressure from its second moment (for Hertz's p0 sqrt(1 - x^2/a^2)
         the ratio is a^2 / 4). Unlike the last loaded node (hertz_edge),
         which jumps by whole elements, this moves smoothly with the mesh;
         with nodal forces consistent with a pressure p its bias is the
         interpolation error of x^2, at most +h^2 / (3 a^2) relative
         (h the element length at the contact).
    """
    x, f = hertz_contact_zone(x, force)
    total = f.sum()
    if total <= 0:
        return 0.0, 0.0, 0.0
    P = 2 * total
    scale = max(abs(x[-1]), 1e-300)
    if abs(x[0]) > 1e-9 * scale:
        raise ValueError("the first node of the arc is not on x = 0")
    mirrored = np.concatenate([[-x[1]], x, [x[-1]]])
    tributary = (mirrored[2:] - mirrored[:-2]) / 2
    tributary[0] = x[1] / 2        # the axis node: half of its full length
    tributary[-1] = max(tributary[-1], 1e-300)
    p0 = float(np.max(f / tributary))
    a = 2 * math.sqrt(float(np.sum(f * x * x)) / total)
    return p0, a, P


def hertz_edge(x, force):
    """Another measure of a, for information: the last node of the contact
    zone plus half the distance to the next one (jumps by h/2)."""
    x, f = hertz_contact_zone(x, force)
    loaded = np.nonzero(f > 0)[0]
    if len(loaded) == 0:
        return 0.0
    k = loaded[-1]
    return float(x[k] + (x[k + 1] - x[k]) / 2) if k + 1 < len(x) else float(x[k])


# ---------------------------------------------------------- patch test
PATCH_E = 1000.0
PATCH_NU = 0.3
PATCH_DRIVE = 0.02      # the upper top's downward displacement
PATCH_SHEAR = 0.004     # friction: u = (0.004 y, -0.02 y) on every side
PATCH_MU = 0.5          # the friction coefficient (shear / pressure 0.057)
PATCH_MESHES = ((5, 8), (7, 13))     # cells along x, upper on lower
PATCH_LAYERS = {"upper": 3, "lower": 4}   # cells across each block


def patch_figures(x, force, tributary, applied, in_contact):
    """(largest, largest_interior, n) of the patch test, as glissade's
    test (mortar_patch_test) reads it:

    x           the slave nodes' abscissae,
    force       each one's contact force vector (n, 2) on the slave,
    tributary   each one's tributary length (the integral of its hat
                function on the slave boundary),
    applied     the traction vector the slave should carry,
    in_contact  which nodes count (glissade: active; a peer: pressed).

    largest = max |force / tributary - applied| / |applied| over the nodes
    in contact; largest_interior the same without the interface's two end
    nodes (with friction both blocks' ends are supported: glissade's mortar
    leaves them inactive, a peer may load them); n the nodes in contact.
    """
    order = np.argsort(np.asarray(x, dtype=float))
    force = np.asarray(force, dtype=float)[order]
    tributary = np.asarray(tributary, dtype=float)[order]
    counted = np.asarray(in_contact, dtype=bool)[order]
    applied = np.asarray(applied, dtype=float)
    deviation = (np.linalg.norm(force / tributary[:, None] - applied, axis=1)
                 / np.linalg.norm(applied))
    interior = counted.copy()
    interior[[0, -1]] = False

    def largest(among):
        return float(deviation[among].max()) if among.any() else math.nan
    return largest(counted), largest(interior), int(counted.sum())


def _write_hertz_mesh_with_gmsh(h_contact, path):
    import gmsh
    gmsh.initialize(readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", int(os.environ.get("GMSH_VERBOSE", "0")))
        gmsh.model.add("hertz")
        geo = gmsh.model.geo
        o = geo.addPoint(0, 0, 0)            # the first contact point
        c = geo.addPoint(0, 1, 0)            # the centre
        t = geo.addPoint(1, 1, 0)
        arc = geo.addCircleArc(o, c, t)      # (0,0) -> (1,1), below centre
        top = geo.addLine(t, c)
        axis = geo.addLine(c, o)
        loop = geo.addCurveLoop([arc, top, axis])
        disk = geo.addPlaneSurface([loop])
        geo.synchronize()
        gmsh.model.addPhysicalGroup(1, [arc], 1)
        gmsh.model.setPhysicalName(1, 1, "arc")
        gmsh.model.addPhysicalGroup(1, [axis], 2)
        gmsh.model.setPhysicalName(1, 2, "axis")
        gmsh.model.addPhysicalGroup(1, [top], 3)
        gmsh.model.setPhysicalName(1, 3, "top")
        gmsh.model.addPhysicalGroup(2, [disk], 4)
        gmsh.model.setPhysicalName(2, 4, "disk")

        # Size h_contact within HERTZ_FINE of the origin (the contact and
        # the material under it), growing linearly towards HERTZ_COARSE at
        # HERTZ_FAR. Frontal-Delaunay triangles (Mesh.Algorithm 6) paired
        # into quads by Blossom: quads of about the size asked (the arc's
        # segments near the origin are 0.992 h). Gmsh 4.8.4's
        # Frontal-Delaunay for quads (8) crashes here. Blossom may print
        # "WARNING: shrinks.length==shrinks_max" on the finest mesh: harmless.
        field = gmsh.model.mesh.field
        dist = field.add("Distance")
        field.setNumbers(dist, "PointsList", [o])
        thr = field.add("Threshold")
        field.setNumber(thr, "InField", dist)
        field.setNumber(thr, "SizeMin", h_contact)
        field.setNumber(thr, "SizeMax", HERTZ_COARSE)
        field.setNumber(thr, "DistMin", HERTZ_FINE)
        field.setNumber(thr, "DistMax", HERTZ_FAR)
        field.setAsBackgroundMesh(thr)
        gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
        gmsh.option.setNumber("Mesh.Algorithm", 6)
        gmsh.option.setNumber("Mesh.RecombineAll", 1)
        gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 1)
        gmsh.option.setNumber("Mesh.ElementOrder", 1)
        gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
        gmsh.option.setNumber("Mesh.Binary", 0)
        gmsh.option.setNumber("Mesh.SaveAll", 0)
        gmsh.model.mesh.generate(2)
        types = gmsh.model.mesh.getElementTypes(2)
        if list(types) != [3]:
            # Blossom leaves a triangle only in odd cases: then split all.
            gmsh.option.setNumber("Mesh.SubdivisionAlgorithm", 1)
            gmsh.model.mesh.refine()
            types = gmsh.model.mesh.getElementTypes(2)
            if list(types) != [3]:
                raise RuntimeError(f"Hertz mesh is not all quads: {types}")
        gmsh.model.mesh.removeDuplicateNodes()
        directory = os.path.dirname(os.path.abspath(path))
        os.makedirs(directory, exist_ok=True)
        gmsh.write(path)
    finally:
        gmsh.finalize()


def read_msh(path):
    """A Gmsh MSH 4.1 ASCII file of points, lines and quads: (nodes (n, 2),
    quads (m, 4) counter-clockwise, groups {name: array}) with 0-based
    node indices in the order of the file's nodes; a 1D group is an
    (k, 2) array of its segments, a 2D one an array of quad indices."""
    with open(path) as f:
        lines = f.read().split("\n")
    k = 0
    names = {}
    tags = {}            # node tag -> index
    coords = []
    entity_groups = {}   # (dim, entity tag) -> [physical tags]
    quads, quad_entities = [], []
    segments, segment_entities = [], []
    while k < len(lines):
        line = lines[k].strip()
        if line == "$PhysicalNames":
            count = int(lines[k + 1])
            for m in range(count):
                dim, tag, name = lines[k + 2 + m].split(maxsplit=2)
                names[(int(dim), int(tag))] = name.strip('"')
            k += count + 2
        elif line == "$Entities":
            counts = [int(v) for v in lines[k + 1].split()]
            k += 2
            for dim in range(4):
                for _ in range(counts[dim]):
                    words = lines[k].split()
                    tag = int(words[0])
                    start = 4 if dim == 0 else 7
                    n_phys = int(words[start])
                    entity_groups[(dim, tag)] = [
                        int(v) for v in words[start + 1:start + 1 + n_phys]]
                    k += 1
        elif line == "$Nodes":
            n_blocks = int(lines[k + 1].split()[0])
            k += 2
            for _ in range(n_blocks):
                _, _, parametric, n = (int(v) for v in lines[k].split())
                block_tags = [int(lines[k + 1 + m]) for m in range(n)]
                for m in range(n):
                    xyz = lines[k + 1 + n + m].split()
                    tags[block_tags[m]] = len(coords)
                    coords.append((float(xyz[0]), float(xyz[1])))
                k += 1 + 2 * n
        elif line == "$Elements":
            n_blocks = int(lines[k + 1].split()[0])
            k += 2
            for _ in range(n_blocks):
                dim, entity, etype, n = (int(v) for v in lines[k].split())
                for m in range(n):
                    words = [int(v) for v in lines[k + 1 + m].split()]
                    if etype == 3:
                        quads.append([tags[v] for v in words[1:5]])
                        quad_entities.append(entity)
                    elif etype == 1:
                        segments.append([tags[v] for v in words[1:3]])
                        segment_entities.append(entity)
                    elif etype != 15:
                        raise ValueError(f"{path}: element type {etype}")
                k += 1 + n
        else:
            k += 1
    nodes = np.array(coords)
    quads = np.array(quads, dtype=int)
    # Counter-clockwise (Gmsh's are for a surface of normal +z; be sure).
    p = nodes[quads]
    area2 = ((p[:, 2, 0] - p[:, 0, 0]) * (p[:, 3, 1] - p[:, 1, 1]) -
             (p[:, 3, 0] - p[:, 1, 0]) * (p[:, 2, 1] - p[:, 0, 1]))
    quads[area2 < 0] = quads[area2 < 0][:, ::-1]
    groups = {}
    for dim, items, entities in ((1, segments, segment_entities),
                                 (2, list(range(len(quads))), quad_entities)):
        for item, entity in zip(items, entities):
            for phys in entity_groups.get((dim, entity), []):
                groups.setdefault(names.get((dim, phys), str(phys)),
                                  []).append(item)
    groups = {name: np.array(v, dtype=int) for name, v in groups.items()}
    return nodes, quads, groups


def group_nodes(segments):
    """The sorted node indices of a 1D group."""
    return np.unique(np.asarray(segments).ravel())


def hertz_mesh(h_contact, path):
    """Writes the Hertz mesh, Gmsh MSH 4.1 ASCII with the physical groups
    arc, axis, top (1D) and disk (2D), to path, and returns
    (nodes, quads, groups) as read_msh reads it back."""
    try:
        import gmsh  # noqa: F401
        here = True
    except ImportError:
        here = False
    if here:
        _write_hertz_mesh_with_gmsh(float(h_contact), path)
    else:        # not Debian's /usr/bin/python3: gmsh runs there
        subprocess.run([PYTHON, os.path.abspath(__file__), "mesh",
                        repr(float(h_contact)), path], check=True)
    return read_msh(path)


def quad_internal_forces(nodes, quads, u, E, nu):
    """f = K u for plane strain Q1, full 2 x 2 Gauss (GetFEM's FEM_QK(2,1)
    with the default integration, CalculiX's CPE4): the nodal forces the
    elements exert, (n, 2). At a node with no applied load they are the
    contact (or support) reactions. u is (n, 2)."""
    lam, mu = lame_coefficients(E, nu)
    D = np.array([[lam + 2 * mu, lam, 0], [lam, lam + 2 * mu, 0],
                  [0, 0, mu]])
    X = nodes[quads]                     # (m, 4, 2), counter-clockwise
    U = u[quads]
    f = np.zeros_like(u)
    g = 1 / math.sqrt(3)
    ref = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=float)
    for xi, eta in ((-g, -g), (g, -g), (g, g), (-g, g)):
        dN = np.stack([ref[:, 0] * (1 + ref[:, 1] * eta) / 4,
                       ref[:, 1] * (1 + ref[:, 0] * xi) / 4], axis=1)  # (4,2)
        J = np.einsum("mai,aj->mij", X, dN)          # dx_i / dxi_j
        det = J[:, 0, 0] * J[:, 1, 1] - J[:, 0, 1] * J[:, 1, 0]
        inv = np.empty_like(J)
        inv[:, 0, 0], inv[:, 1, 1] = J[:, 1, 1] / det, J[:, 0, 0] / det
        inv[:, 0, 1], inv[:, 1, 0] = -J[:, 0, 1] / det, -J[:, 1, 0] / det
        G = np.einsum("aj,mji->mai", dN, inv)        # dN_a / dx_i
        grad = np.einsum("mak,mai->mki", U, G)       # du_k / dx_i
        eps = np.stack([grad[:, 0, 0], grad[:, 1, 1],
                        grad[:, 0, 1] + grad[:, 1, 0]], axis=1)
        s = eps @ D.T                                 # sxx, syy, sxy
        sig = np.stack([np.stack([s[:, 0], s[:, 2]], 1),
                        np.stack([s[:, 2], s[:, 1]], 1)], 1)  # (m,2,2)
        fe = np.einsum("mij,maj->mai", sig, G) * det[:, None, None]
        np.add.at(f, quads, fe)
    return f


def _main():
    if len(sys.argv) == 4 and sys.argv[1] == "mesh":
        _write_hertz_mesh_with_gmsh(float(sys.argv[2]), sys.argv[3])
        return
    lam, mu = lame_coefficients(RING_E, RING_NU)
    print(f"rings: lambda {lam:.6f} mu {mu:.6f} LOAD {LOAD}")
    print(f"  u_r(2) = {lame_u_r2():.7e} "
          f"({lame_u_r2() / LOAD_SCALE:.7f} * LOAD_SCALE)")
    print(f"  interface pressure = {lame_interface_pressure():.7e} "
          f"({lame_interface_pressure() / LOAD_SCALE:.6f} * LOAD_SCALE)")


if __name__ == "__main__":
    _main()
