#!/usr/bin/python3
"""GetFEM peer, problem 1: the two concentric rings (problems.py).

    /usr/bin/python3 getfem_rings.py N --out DIR

Both rings on glissade's nodes (problems.ring_mesh), each its own mesh and
displacement variable (one GetFEM mesh would merge the coincident nodes of
r = 1.25 and glue the rings), Q1 (FEM_QK(2,1)), 2 x 2 Gauss
(IM_GAUSS_PARALLELEPIPED(2,2), as CalculiX's CPE4), small-strain isotropic
linear elasticity (GetFEM's 2D linearized elasticity with the 3D lambda is
plane strain). Contact: GetFEM's integral contact between non-matching
meshes brick (add_integral_contact_between_nonmatching_meshes_brick),
frictionless, a Q1 multiplier (the contact pressure) on the inner ring's
outer edge (slave), the integration points projected on the outer ring's
inner edge (master), non-symmetric Alart-Curnier (option 1), r = E.
Why not the nodal brick (add_nodal_contact_between_nonmatching_meshes_
brick, --brick nodal): it projects each slave node on one master facet,
and here every slave node lies on a master vertex, so its contact normal
is a facet normal tilted by pi / N from the radius; frictionless, the
rings then slide along those tilted normals and the outer ring comes out
softer: u_r(2) off by -2.2 % at N = 40, -0.53 % at N = 80. The integral
brick gives the glued ring's solution (the same mesh with the nodes of
r = 1.25 merged, checked to 1e-12): -0.357 % and -0.0885 %, the error of
Q1 itself, converging at h^2.
Clamp u = 0 at r = 0.5 by simplification (the dofs eliminated), the four
tangential supports as dof constraints with multipliers, the nodal loads
as an explicit right-hand side. Newton (GetFEM's Model.solve) to a residual
of 1e-12 (the nodal loads are 0.4 / N): 2 or 3 iterations. Direct solver:
MUMPS (what GetFEM's 'auto' picks in 2D below 250,000 dofs when built with
MUMPS, as Debian's is; Debian's GetFEM 5.4 with 'superlu' crashes on this
model, segmentation fault). Debian's nodal brick prints a stray "ok here".

Writes the displacement once, one VTU per ring as glissade writes one per
body (DIR/getfem_rings_inner.vtu, DIR/getfem_rings_outer.vtu, GetFEM's
export_to_vtu, binary), and prints as its last line
{"code": "getfem", "problem": "rings", "N", "dofs" (displacement dofs,
2 x nodes of both rings, as glissade counts them), "u_r2" (mean radial
displacement of the r = 2 nodes), "interface_pressure" (the total normal
contact force over 2 pi 1.25, the force being the sum of the inward radial
nodal forces K u of the inner ring's elements at its r = 1.25 nodes, as
the CalculiX reader computes it and as glissade's sum of r_n amounts to),
"newton_iterations", "interface_pressure_multiplier" (GetFEM's own: the
integral of the multiplier over the slave edge over 2 pi 1.25, larger by
1 / cos(pi / N), the chords being longer than their radial projection),
"brick", "lame_u_r2", "error_u_r2" (relative)}.
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

import getfem as gf  # noqa: E402

gf.util_trace_level(0)    # no "Trace 2 ... assembly" lines


def build_mesh(nodes, cells):
    """A GetFEM mesh of Q4 cells given counter-clockwise; the convex ids
    are the cell indices. Returns (mesh, points of the cells)."""
    m = gf.Mesh("empty", 2)
    lex = problems.lexicographic(cells)
    pts = np.transpose(nodes[lex], (2, 1, 0))   # (dim, 4, n_cells)
    m.add_convex(gf.GeoTrans("GT_QK(2,1)"), pts)
    return m


def dof_map(mf, nodes):
    """x and y dofs of each node of `nodes` in the Q1 vector mesh_fem."""
    coords = mf.basic_dof_nodes()               # (2, n_dofs)
    scale = np.abs(nodes).max()
    key = {(round(x / scale, 9), round(y / scale, 9)): k
           for k, (x, y) in enumerate(coords.T[::2])}
    first = np.array([2 * key[(round(x / scale, 9), round(y / scale, 9))]
                      for x, y in nodes])
    return np.stack([first, first + 1], axis=1)


def faces_region(m, region, radius):
    """Region `region` := outer faces of m inside the ball of `radius`;
    region + 1 := the other outer faces."""
    m.set_region(region, m.outer_faces_in_ball([0.0, 0.0], radius))
    m.set_region(region + 1, m.outer_faces())
    m.region_subtract(region + 1, region)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("n", type=int)
    parser.add_argument("--out", default=".")
    parser.add_argument("--brick", choices=("integral", "nodal"),
                        default="integral")
    parser.add_argument("--lsolver", default="mumps")
    args = parser.parse_args()
    ring = problems.rings(args.n)
    E, nu = problems.RING_E, problems.RING_NU
    lam, mu = problems.lame_coefficients(E, nu)

    inner_nodes, inner_cells = ring["inner"]
    outer_nodes, outer_cells = ring["outer"]
    m1 = build_mesh(inner_nodes, inner_cells)
    m2 = build_mesh(outer_nodes, outer_cells)
    CLAMPED, SLAVE = 1, 2          # inner ring: r = 0.5, r = 1.25
    MASTER = 3                     # outer ring: r = 1.25 (4: r = 2)
    faces_region(m1, CLAMPED, 0.5 * (problems.R_CLAMP + problems.R_INTERFACE))
    faces_region(m2, MASTER,
                 0.5 * (problems.R_INTERFACE + problems.R_LOADED))

    fem = gf.Fem("FEM_QK(2,1)")
    integ = gf.Integ("IM_GAUSS_PARALLELEPIPED(2,2)")
    mf1, mf2 = gf.MeshFem(m1, 2), gf.MeshFem(m2, 2)
    mf1.set_fem(fem)
    mf2.set_fem(fem)
    mim1, mim2 = gf.MeshIm(m1, integ), gf.MeshIm(m2, integ)
    dofs1 = dof_map(mf1, inner_nodes)
    dofs2 = dof_map(mf2, outer_nodes)

    md = gf.Model("real")
    md.add_fem_variable("u1", mf1)
    md.add_fem_variable("u2", mf2)
    md.add_initialized_data("lambda", [lam])
    md.add_initialized_data("mu", [mu])
    md.add_isotropic_linearized_elasticity_brick(mim1, "u1", "lambda", "mu")
    md.add_isotropic_linearized_elasticity_brick(mim2, "u2", "lambda", "mu")
    md.add_Dirichlet_condition_with_simplification("u1", CLAMPED)

    # The four tangential supports of the outer ring: B u2 = 0.
    supports = ring["supports"]
    B = gf.Spmat("empty", len(supports), mf2.nbdof())
    for row, (node, component) in enumerate(supports):
        B.add([row], [int(dofs2[node, component])], np.array([[1.0]]))
    md.add_variable("supports", len(supports))
    md.add_constraint_with_multipliers("u2", "supports", B,
                                       np.zeros(len(supports)))

    # Radial inward nodal forces LOAD / N on the nodes of r = 2.
    F = np.zeros(mf2.nbdof())
    loaded = ring["loaded"]
    x = outer_nodes[loaded]
    e_r = x / np.linalg.norm(x, axis=1)[:, None]
    F[dofs2[loaded, 0]] = -ring["nodal_force"] * e_r[:, 0]
    F[dofs2[loaded, 1]] = -ring["nodal_force"] * e_r[:, 1]
    md.add_explicit_rhs("u2", F)

    md.add_initialized_data("r", [E])
    if args.brick == "nodal":
        md.add_nodal_contact_between_nonmatching_meshes_brick(
            mim1, mim2, "u1", "u2", "lambda_n", "r", SLAVE, MASTER)
    else:
        mfl = gf.MeshFem(m1, 1)
        mfl.set_fem(fem)
        md.add_filtered_fem_variable("lambda_n", mfl, SLAVE)
        md.add_integral_contact_between_nonmatching_meshes_brick(
            mim1, "u1", "u2", "lambda_n", "r", SLAVE, MASTER, 1)

    iterations, converged = md.solve("max_iter", 50, "max_res", 1e-12,
                                     "lsolver", args.lsolver)
    if not converged:
        sys.exit(f"GetFEM's Newton did not converge in {iterations} "
                 "iterations")

    U1 = md.variable("u1")
    U2 = md.variable("u2")
    u_loaded = np.stack([U2[dofs2[loaded, 0]], U2[dofs2[loaded, 1]]], 1)
    u_r2 = float(np.mean(np.sum(u_loaded * e_r, axis=1)))
    # The total normal contact force, as glissade's runner and the
    # CalculiX reader take it: the sum over the inner ring's r = 1.25 nodes
    # of the inward radial nodal force, here K u of the inner ring's
    # elements there (problems.quad_internal_forces, the same Q1 2 x 2).
    u1 = np.stack([U1[dofs1[:, 0]], U1[dofs1[:, 1]]], axis=1)
    f1 = problems.quad_internal_forces(inner_nodes, inner_cells, u1, E, nu)
    slave = ring["slave"]
    xs = inner_nodes[slave]
    normal = -float(np.sum(f1[slave] * xs /
                           np.linalg.norm(xs, axis=1)[:, None]))
    # GetFEM's own figure: the integral of the multiplier over the slave
    # polygon (pressure x chord length), cos(pi / N) above the radial sum
    # (the chords' normals are tilted by pi / N at the nodes); the nodal
    # brick's multipliers are nodal normal forces along tilted normals.
    if args.brick == "nodal":
        multiplier = float(np.sum(np.abs(md.variable("lambda_n"))))
    else:
        multiplier = abs(float(gf.asm_generic(mim1, 0, "lambda_n", SLAVE,
                                              md)))

    os.makedirs(args.out, exist_ok=True)
    # Once, one file per body as glissade writes them.
    mf1.export_to_vtu(os.path.join(args.out, "getfem_rings_inner.vtu"),
                      mf1, U1, "displacement")
    mf2.export_to_vtu(os.path.join(args.out, "getfem_rings_outer.vtu"),
                      mf2, U2, "displacement")

    reference = problems.lame_u_r2()
    print(json.dumps({
        "code": "getfem", "problem": "rings", "N": args.n,
        "dofs": int(mf1.nbdof() + mf2.nbdof()),
        "u_r2": u_r2,
        "interface_pressure": normal / (2 * math.pi * problems.R_INTERFACE),
        "newton_iterations": int(iterations),
        "interface_pressure_multiplier":
            multiplier / (2 * math.pi * problems.R_INTERFACE),
        "brick": args.brick,
        "lame_u_r2": reference,
        "error_u_r2": (u_r2 - reference) / abs(reference),
    }))


if __name__ == "__main__":
    main()
