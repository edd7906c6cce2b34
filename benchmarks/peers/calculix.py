#!/usr/bin/python3
"""CalculiX peer: writes the decks of the two problems (problems.py) and
reads ccx's results.

    /usr/bin/python3 calculix.py rings N DIR                   # DIR/job.inp
    /usr/bin/python3 calculix.py hertz H DIR [--mesh FILE.msh]
    (cd DIR && ccx -i job)                                     # the timed part
    /usr/bin/python3 calculix.py read rings N DIR              # prints JSON
    /usr/bin/python3 calculix.py read hertz H DIR

The model, the same for both problems:

- CPE4: ccx expands it into a one-layer C3D8 brick, full 2 x 2 x 2 Gauss
  integration and no incompatible modes (CalculiX manual, "Four-node plane
  strain element"), z held by MPCs: in the plane exactly Q1 with 2 x 2
  Gauss, as GetFEM's FEM_QK(2,1) and glissade's Q4 (CPE4R would be
  reduced integration, C3D8I incompatible modes). Thickness 1, so forces
  are per unit thickness as in the 2D codes. Results are written on the
  deck's 2D nodes (*NODE FILE's default OUTPUT=2D).
- Linear elasticity, small strain (no NLGEOM), one *STATIC step of one
  increment; ccx iterates on the contact (its Newton-Raphson) with its
  default convergence controls (a linear problem: once the contact
  elements stop changing, the next iteration's residual is round-off).
  Direct solver: SPOOLES (symmetric), the only one in Debian's ccx, on
  one thread by default (ccx takes OMP_NUM_THREADS / CCX_NPROC_EQUATION_
  SOLVER from the environment for more).
- Contact, frictionless (no *FRICTION), *SURFACE BEHAVIOR, PRESSURE-
  OVERCLOSURE=LINEAR, slope K = PENALTY = 1e8 (pressure per length of
  penetration), each problem with the *CONTACT PAIR type ccx did best:
  rings: SURFACE TO SURFACE (face-to-face penalty: the slave faces'
  integration points projected on the master, GetFEM's integral brick's
  way), 2 iterations, against 3 for node-to-face (same u_r(2) within
  3e-6); Hertz: NODE TO SURFACE (node-to-face penalty, nodal like GetFEM's
  rigid obstacle brick and glissade), 6 or 7 iterations, where
  face-to-face takes 18 (its contact elements, per integration point,
  keep changing: 298, 255, 214, ... 140) for the same result (p0 within
  3e-6). Node-to-face's quasi-bilinear law also takes sigma_inf, the
  tension of open springs near the master: SIGMA_INF = 1e-4 (ccx's default
  E / 70,000 would pull on the first open nodes by about 5e-4 of the peak
  nodal force).
  Zero initial gap needs no fix (no ADJUST, no *CONTROLS): in the first
  iteration nothing is in contact, the bodies move into each other (the
  outer ring held by its four supports, the disk by its driven edge), the
  next iterations settle the contact. ccx's manual advises K = 5 to 50 E
  for node-to-face; that would let the disk sink by p0 / K = 5.9 / 1e4 =
  6e-4, 11 % of the drive, so K is 1e8: the penetration is p / K, rings
  0.033 / 1e8 = 3.3e-10 against an interface displacement of 1.7e-5
  (2e-5 relative; u_r(2) is 7e-6 softer than GetFEM's), Hertz 6.0e-8 at
  the centre (measured: "max_penetration") against the drive 0.0055
  (1.1e-5; P 1.3e-5 below GetFEM's). K h / E is 2e4 (rings N = 40) and
  5e3 .. 6e2 (Hertz h = 0.01 .. 0.00125): SPOOLES takes it (no
  convergence trouble at the sizes tried).
- Rigid flat for Hertz: one CPE4 element, x in [-0.2, 1.2], y in
  [-0.2, 0], every node clamped, its top face the master surface (ccx has
  no analytical rigid surface, and *RIGID BODY on expanded 2D elements
  only adds MPCs: a clamped element is exactly rigid). The slave surface is
  the whole arc, as glissade's.
- Output: *NODE FILE, U once at the end (FREQUENCY large: the last
  increment is always written, here the only one). No contact output:
  *CONTACT PRINT CF / CFN work for face-to-face pairs only (ccx 2.20
  segfaults on them with node-to-face), and the rings' CF resultant is zero.

The reader parses job.frd (the last DISP block; ccx writes E12.5, 6
significant digits) and job.sta (iterations), and computes the nodal
contact forces the way every code can: the elements' nodal forces K u on
the slave nodes (problems.quad_internal_forces, Q1 2 x 2 Gauss, the same
element as CPE4), which in equilibrium are the contact forces there (no
other load acts on these nodes). Rings: "interface_pressure" = the inner
ring's total inward radial force on its r = 1.25 nodes / (2 pi 1.25);
Hertz: the arc nodes' vertical forces through problems.
hertz_figures_from_nodal_forces, as the GetFEM peer and glissade's runner.
Node numbers: deck node k + 1 = problems' node k (the rings: the inner
ring's nodes first, then the outer ring's); nothing in ccx requires an
order.
"""

import argparse
import json
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import problems  # noqa: E402

PENALTY = 1e8          # K of the linear pressure-overclosure law
# sigma_inf of node-to-face's quasi-bilinear law: the tension of an open
# contact spring (within c0 sqrt(area) = 1e-3 sqrt(h) of the master): 1e-4,
# 2e-5 of p0, where ccx's default (E / 70,000 = 2.9e-3) would pull 5e-4 of
# the largest nodal force on the open nodes at the edge of the contact.
SIGMA_INF = 1e-4
# The contact formulation of each problem (--contact to change it):
CONTACT = {"rings": "SURFACE TO SURFACE", "hertz": "NODE TO SURFACE"}


# ------------------------------------------------------------------ decks
def num(v):
    """A real for ccx: its fields take 20 characters at most, so 14
    significant digits (-1.3011872240941e-16)."""
    return f"{float(v):.14g}"


def write_nodes(out, nodes, first=1):
    for k, (x, y) in enumerate(nodes):
        out.append(f"{k + first}, {num(x)}, {num(y)}")


def write_elements(out, quads, node_offset, first):
    for k, q in enumerate(quads):
        out.append(f"{k + first}, " + ", ".join(str(v + 1 + node_offset)
                                                 for v in q))


def write_set(out, ids):
    ids = [str(int(i)) for i in ids]
    for k in range(0, len(ids), 10):
        out.append(", ".join(ids[k:k + 10]))


def common_cards(out, E, nu, contact):
    law = num(PENALTY)
    if contact == "NODE TO SURFACE":
        law += ", " + num(SIGMA_INF)
    out += ["*MATERIAL, NAME=MAT", "*ELASTIC", f"{num(E)}, {num(nu)}",
            "*SOLID SECTION, ELSET=EALL, MATERIAL=MAT", "1.",
            "*SURFACE INTERACTION, NAME=FRICTIONLESS",
            "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", law,
            f"*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE={contact}",
            "SLAVE, MASTER"]


def step_cards(out, loads):
    out += ["*STEP", "*STATIC"] + loads + [
        "*NODE FILE, FREQUENCY=1000000", "U", "*END STEP"]


def rings_deck(n, directory, contact):
    ring = problems.rings(n)
    inner_nodes, inner_cells = ring["inner"]
    outer_nodes, outer_cells = ring["outer"]
    n1, e1 = len(inner_nodes), len(inner_cells)
    nt = ring["n_through"]
    out = ["*HEADING", f"glissade peers: two rings, N = {n}"]
    out.append("*NODE, NSET=NALL")
    write_nodes(out, inner_nodes, 1)
    write_nodes(out, outer_nodes, n1 + 1)
    out.append("*ELEMENT, TYPE=CPE4, ELSET=EALL")
    # Cells counter-clockwise (i, j), (i, j+1), (i+1, j+1), (i+1, j): face
    # S2 (nodes 2-3) is on r_{j+1}, S4 (nodes 4-1) on r_j.
    write_elements(out, inner_cells, 0, 1)
    write_elements(out, outer_cells, n1, e1 + 1)
    out.append("*NSET, NSET=CLAMPED")
    write_set(out, ring["clamped"] + 1)
    # Slave: the inner ring's cells j = nt - 1, face S2 (r = 1.25);
    # master: the outer ring's cells j = 0, face S4 (r = 1.25).
    cells = np.arange(n) * nt
    out.append("*SURFACE, NAME=SLAVE, TYPE=ELEMENT")
    out += [f"{c + nt - 1 + 1}, S2" for c in cells]
    out.append("*SURFACE, NAME=MASTER, TYPE=ELEMENT")
    out += [f"{c + e1 + 1}, S4" for c in cells]
    out.append("*BOUNDARY")
    out.append("CLAMPED, 1, 2")
    for node, component in ring["supports"]:
        out.append(f"{node + n1 + 1}, {component + 1}, {component + 1}")
    common_cards(out, problems.RING_E, problems.RING_NU, contact)
    loads = ["*CLOAD"]
    f = ring["nodal_force"]
    for node in ring["loaded"]:
        x, y = outer_nodes[node]
        r = math.hypot(x, y)
        loads.append(f"{node + n1 + 1}, 1, {num(-f * x / r)}")
        loads.append(f"{node + n1 + 1}, 2, {num(-f * y / r)}")
    step_cards(out, loads)
    write_deck(directory, out)


FLAT = ((-0.2, -0.2), (1.2, -0.2), (1.2, 0.0), (-0.2, 0.0))


def hertz_deck(h, directory, mesh, contact, element="CPE4",
               drive=problems.HERTZ_DRIVE):
    """The Hertz deck; element CAX4 and drive SPHERE_DRIVE make it the
    axisymmetric sphere (x = r, y the axis: ccx's convention too)."""
    if mesh is None:
        mesh = os.path.join(directory, "hertz.msh")
        nodes, quads, groups = problems.hertz_mesh(h, mesh)
    else:
        nodes, quads, groups = problems.read_msh(mesh)
    nn, ne = len(nodes), len(quads)
    out = ["*HEADING", f"glissade peers: Hertz, h = {h}, mesh {mesh}"]
    out.append("*NODE, NSET=NALL")
    write_nodes(out, nodes, 1)
    write_nodes(out, np.array(FLAT), nn + 1)
    out.append(f"*ELEMENT, TYPE={element}, ELSET=EALL")
    write_elements(out, quads, 0, 1)
    out.append(f"{ne + 1}, {nn + 1}, {nn + 2}, {nn + 3}, {nn + 4}")
    # The arc's faces: for each segment, its quad and the face (S1 = nodes
    # 1-2, S2 = 2-3, S3 = 3-4, S4 = 4-1 of the counter-clockwise quad).
    faces = {}
    for e, q in enumerate(quads):
        for s in range(4):
            faces[frozenset((q[s], q[(s + 1) % 4]))] = (e, s)
    out.append("*SURFACE, NAME=SLAVE, TYPE=ELEMENT")
    for a, b in groups["arc"]:
        e, s = faces[frozenset((a, b))]
        out.append(f"{e + 1}, S{s + 1}")
    out.append("*SURFACE, NAME=MASTER, TYPE=ELEMENT")
    out.append(f"{ne + 1}, S3")          # the flat's top face, y = 0
    out.append("*NSET, NSET=AXIS")
    write_set(out, problems.group_nodes(groups["axis"]) + 1)
    out.append("*NSET, NSET=TOP")
    write_set(out, problems.group_nodes(groups["top"]) + 1)
    out.append("*NSET, NSET=FLAT")
    write_set(out, range(nn + 1, nn + 5))
    out += ["*BOUNDARY", "FLAT, 1, 2", "AXIS, 1, 1"]
    common_cards(out, problems.HERTZ_E, problems.HERTZ_NU, contact)
    # (the axis's x is held in both: the plane model's symmetry, the
    # axisymmetric one's axis, which ccx does not hold by itself)
    loads = ["*BOUNDARY", f"TOP, 2, 2, {num(-drive)}"]
    step_cards(out, loads)
    write_deck(directory, out)


def write_deck(directory, lines):
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, "job.inp"), "w") as f:
        f.write("\n".join(lines) + "\n")


# ---------------------------------------------------------------- results
def read_frd_displacements(path):
    """{node: (ux, uy, uz)} of the last DISP block of an ASCII .frd."""
    blocks = []
    current = None
    with open(path) as f:
        for line in f:
            if line.startswith(" -4  DISP"):
                current = {}
                blocks.append(current)
            elif current is not None:
                if line.startswith(" -1"):
                    node = int(line[3:13])
                    values = [float(line[13 + 12 * k:25 + 12 * k])
                              for k in range(3)]
                    current[node] = values
                elif line.startswith(" -3"):
                    current = None
    if not blocks:
        raise ValueError(f"{path}: no DISP block (did ccx run?)")
    return blocks[-1]


def read_sta_iterations(path):
    """Total iterations of the step (the .sta file's ITRS column)."""
    total = 0
    with open(path) as f:
        for line in f:
            words = line.split()
            if len(words) >= 5 and all(w.isdigit() for w in words[:4]):
                total += int(words[3])
    return total


def displacement_array(disp, first, count):
    return np.array([disp[first + k][:2] for k in range(count)])


def read_rings(n, directory):
    ring = problems.rings(n)
    inner_nodes, inner_cells = ring["inner"]
    outer_nodes, _ = ring["outer"]
    n1 = len(inner_nodes)
    disp = read_frd_displacements(os.path.join(directory, "job.frd"))
    u_inner = displacement_array(disp, 1, n1)
    u_outer = displacement_array(disp, n1 + 1, len(outer_nodes))
    loaded = ring["loaded"]
    x = outer_nodes[loaded]
    e_r = x / np.linalg.norm(x, axis=1)[:, None]
    u_r2 = float(np.mean(np.sum(u_outer[loaded] * e_r, axis=1)))
    # Contact forces on the inner ring's r = 1.25 nodes: K u there.
    f = problems.quad_internal_forces(inner_nodes, inner_cells, u_inner,
                                      problems.RING_E, problems.RING_NU)
    slave = ring["slave"]
    xs = inner_nodes[slave]
    normal = -float(np.sum(f[slave] * xs / np.linalg.norm(xs, axis=1)[:, None]))
    reference = problems.lame_u_r2()
    return {
        "code": "calculix", "problem": "rings", "N": n,
        "dofs": 2 * (n1 + len(outer_nodes)),
        "u_r2": u_r2,
        "interface_pressure": normal / (2 * math.pi * problems.R_INTERFACE),
        "newton_iterations": read_sta_iterations(
            os.path.join(directory, "job.sta")),
        "lame_u_r2": reference,
        "error_u_r2": (u_r2 - reference) / abs(reference),
        "penalty": PENALTY,
    }


def read_hertz(h, directory, mesh):
    if mesh is None:
        mesh = os.path.join(directory, "hertz.msh")
    nodes, quads, groups = problems.read_msh(mesh)
    disp = read_frd_displacements(os.path.join(directory, "job.frd"))
    u = displacement_array(disp, 1, len(nodes))
    f = problems.quad_internal_forces(nodes, quads, u, problems.HERTZ_E,
                                      problems.HERTZ_NU)
    arc = problems.group_nodes(groups["arc"])
    top = problems.group_nodes(groups["top"])
    arc = np.setdiff1d(arc, top)        # the corner (1, 1) is driven
    force = f[arc, 1]
    x = nodes[arc, 0]
    p0, a, P = problems.hertz_figures_from_nodal_forces(x, force)
    p0_hertz, a_hertz = problems.hertz_reference(P)
    penetration = -float(np.min(u[arc, 1] + nodes[arc, 1]))
    return {
        "code": "calculix", "problem": "hertz", "h": h,
        "dofs": 2 * len(nodes), "P": P, "p0": p0, "a": a,
        "p0_hertz": p0_hertz, "a_hertz": a_hertz,
        "error_p0": (p0 - p0_hertz) / p0_hertz,
        "error_a": (a - a_hertz) / a_hertz,
        "a_edge": problems.hertz_edge(x, force),
        "newton_iterations": read_sta_iterations(
            os.path.join(directory, "job.sta")),
        "top_reaction": -2 * float(f[top, 1].sum()),
        "max_penetration": penetration,
        "penalty": PENALTY,
    }


def read_sphere(h, directory, mesh):
    """The axisymmetric Hertz run: ring forces K u (full turn) on the arc."""
    if mesh is None:
        mesh = os.path.join(directory, "hertz.msh")
    nodes, quads, groups = problems.read_msh(mesh)
    disp = read_frd_displacements(os.path.join(directory, "job.frd"))
    u = displacement_array(disp, 1, len(nodes))
    f = problems.axisymmetric_quad_internal_forces(
        nodes, quads, u, problems.HERTZ_E, problems.HERTZ_NU)
    arc = problems.group_nodes(groups["arc"])
    top = problems.group_nodes(groups["top"])
    arc = np.setdiff1d(arc, top)
    p0, a, P = problems.sphere_figures_from_ring_forces(
        nodes[arc, 0], nodes[arc, 1], f[arc, 1])
    p0_hertz, a_hertz = problems.sphere_reference(P)
    return {
        "code": "calculix", "problem": "sphere", "h": h,
        "dofs": 2 * len(nodes), "P": P, "p0": p0, "a": a,
        "p0_hertz": p0_hertz, "a_hertz": a_hertz,
        "error_p0": (p0 - p0_hertz) / p0_hertz,
        "error_a": (a - a_hertz) / a_hertz,
        "newton_iterations": read_sta_iterations(
            os.path.join(directory, "job.sta")),
        "top_reaction": -float(f[top, 1].sum()),
        "penalty": PENALTY,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("words", nargs="+",
                        help="rings N DIR | hertz H DIR | sphere H DIR | "
                             "read rings|hertz|sphere SIZE DIR")
    parser.add_argument("--contact", default=None,
                        choices=("SURFACE TO SURFACE", "NODE TO SURFACE"),
                        help="the *CONTACT PAIR TYPE (default: rings "
                             "SURFACE TO SURFACE, hertz NODE TO SURFACE)")
    parser.add_argument("--mesh", default=None,
                        help="Hertz: the Gmsh file (default DIR/hertz.msh, "
                             "written if the deck is written)")
    args = parser.parse_args()
    words = args.words
    if words[0] == "read" and len(words) == 4:
        problem, size, directory = words[1:]
        if problem == "rings":
            result = read_rings(int(size), directory)
        elif problem == "sphere":
            with open(os.path.join(directory, "mesh.txt")) as f:
                result = read_sphere(float(size), directory, f.read().strip())
        else:
            mesh = args.mesh
            if mesh is None and os.path.exists(
                    os.path.join(directory, "mesh.txt")):
                with open(os.path.join(directory, "mesh.txt")) as f:
                    mesh = f.read().strip()
            result = read_hertz(float(size), directory, mesh)
        print(json.dumps(result))
    elif len(words) == 3 and words[0] == "rings":
        rings_deck(int(words[1]), words[2], args.contact or CONTACT["rings"])
    elif len(words) == 3 and words[0] in ("hertz", "sphere"):
        if words[0] == "hertz":
            hertz_deck(float(words[1]), words[2], args.mesh,
                       args.contact or CONTACT["hertz"])
        else:
            hertz_deck(float(words[1]), words[2], args.mesh,
                       args.contact or CONTACT["hertz"], "CAX4",
                       problems.SPHERE_DRIVE)
        # The reader needs the mesh: remember where it is.
        mesh = os.path.abspath(args.mesh) if args.mesh else os.path.join(
            os.path.abspath(words[2]), "hertz.msh")
        with open(os.path.join(words[2], "mesh.txt"), "w") as f:
            f.write(mesh + "\n")
    else:
        parser.error("expected rings N DIR, hertz H DIR, or read ...")


if __name__ == "__main__":
    main()
