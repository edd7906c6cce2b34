#!/usr/bin/python3
"""GetFEM peer, problem 2: Hertz, the quarter disk on a rigid flat
(problems.py).

    /usr/bin/python3 getfem_hertz.py H [--mesh FILE.msh] --out DIR

On the Gmsh mesh that glissade reads (--mesh; without it the mesh of
element size H at the contact is written to DIR/hertz.msh first), built
from its node and quad arrays (problems.read_msh), Q1 (FEM_QK(2,1)),
2 x 2 Gauss (IM_GAUSS_PARALLELEPIPED(2,2), as CalculiX's CPE4), small-strain
isotropic linear elasticity (plane strain). Contact: GetFEM's nodal contact
with a rigid obstacle brick (add_nodal_contact_with_rigid_obstacle_brick),
frictionless, the obstacle's signed distance "y" (the flat y = 0, its
normal exact at every node), the arc's nodes as slaves, its multipliers
the nodal contact forces, non-symmetric Alart-Curnier (version 1),
r = E. The supports, u_x = 0 on the axis and u_y = -0.0055 on the top
edge, are dof constraints with multipliers (exact at the nodes, as
glissade's). Newton (GetFEM's Model.solve, its line search) to a residual
of 1e-10 (4 or 5 iterations), MUMPS (GetFEM's default here; see
getfem_rings.py). GF_NOISY=1 in the environment prints the iterations.

Writes the displacement once to DIR/getfem_hertz.vtu (export_to_vtu) and
prints as its last line {"code": "getfem", "problem": "hertz", "h",
"dofs" (2 x nodes), "P" (the full contact's load: twice the sum of the
quarter's nodal contact forces), "p0", "a" (problems.
hertz_figures_from_nodal_forces: the largest nodal force over its
tributary length, and 2 sqrt(sum f x^2 / sum f)), "p0_hertz", "a_hertz"
(Hertz at that P), "a_edge" (the last loaded node plus half the next
spacing, for information), "newton_iterations", "top_reaction" (twice
the top edge's vertical reaction, which must equal P)}.
"""

import argparse
import json
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import problems  # noqa: E402

import getfem as gf  # noqa: E402

gf.util_trace_level(0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("h", type=float)
    parser.add_argument("--mesh", default=None)
    parser.add_argument("--out", default=".")
    parser.add_argument("--contact", choices=("nodal", "integral"),
                        default="nodal",
                        help="GetFEM's nodal contact brick, or its integral "
                             "one (the multiplier a Q1 field on the arc, the "
                             "contact condition integrated: the weak form "
                             "glissade's mortar writes)")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.mesh:
        nodes, quads, groups = problems.read_msh(args.mesh)
    else:
        nodes, quads, groups = problems.hertz_mesh(
            args.h, os.path.join(args.out, "hertz.msh"))
    E, nu = problems.HERTZ_E, problems.HERTZ_NU
    lam, mu = problems.lame_coefficients(E, nu)

    m = gf.Mesh("empty", 2)
    pts = np.transpose(nodes[problems.lexicographic(quads)], (2, 1, 0))
    m.add_convex(gf.GeoTrans("GT_QK(2,1)"), pts)
    ARC = 1
    # The arc's faces: the outer faces whose two nodes are arc nodes.
    arc_nodes = problems.group_nodes(groups["arc"])
    faces = m.outer_faces()
    on_arc = np.zeros(len(nodes), bool)
    on_arc[arc_nodes] = True
    pid_of = pid_map(m, nodes)
    keep = []
    for k in range(faces.shape[1]):
        pids = m.pid_in_faces(faces[:, k:k + 1])
        if all(on_arc[pid_of[p]] for p in pids):
            keep.append(k)
    m.set_region(ARC, faces[:, keep])

    fem = gf.Fem("FEM_QK(2,1)")
    mf = gf.MeshFem(m, 2)
    mf.set_fem(fem)
    mim = gf.MeshIm(m, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,2)"))
    dofs = dof_map(mf, nodes)

    md = gf.Model("real")
    md.add_fem_variable("u", mf)
    md.add_initialized_data("lambda", [lam])
    md.add_initialized_data("mu", [mu])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")

    # u_x = 0 on the axis, u_y = -drive on the top edge, at the nodes.
    axis = problems.group_nodes(groups["axis"])
    top = problems.group_nodes(groups["top"])
    rows = [dofs[axis, 0], dofs[top, 1]]
    values = [np.zeros(len(axis)), np.full(len(top), -problems.HERTZ_DRIVE)]
    rows, values = np.concatenate(rows), np.concatenate(values)
    B = gf.Spmat("empty", len(rows), mf.nbdof())
    for row, dof in enumerate(rows):
        B.add([row], [int(dof)], np.array([[1.0]]))
    md.add_variable("supports", len(rows))
    md.add_constraint_with_multipliers("u", "supports", B, values)

    # The brick's multipliers: one per node of the region, in the order of
    # the nodes' first dof.
    region_dofs = mf.basic_dof_on_region(ARC)
    contact_x_dofs = np.sort(region_dofs)[::2]
    md.add_initialized_data("r", [E])
    if args.contact == "nodal":
        md.add_variable("lambda_n", len(contact_x_dofs))
        md.add_nodal_contact_with_rigid_obstacle_brick(
            mim, "u", "lambda_n", "r", ARC, "y", 1)
    else:
        # The multiplier a scalar Q1 field on the arc, the obstacle the
        # signed distance y as a field; Alart-Curnier, unsymmetric (1).
        mf_scalar = gf.MeshFem(m, 1)
        mf_scalar.set_fem(fem)
        mf_lambda = gf.MeshFem("partial", mf_scalar,
                               mf_scalar.basic_dof_on_region(ARC))
        md.add_fem_variable("lambda_n", mf_lambda)
        md.add_initialized_fem_data("obstacle", mf_scalar,
                                    mf_scalar.basic_dof_nodes()[1])
        md.add_integral_contact_with_rigid_obstacle_brick(
            mim, "u", "lambda_n", "obstacle", "r", ARC, 1)

    # 1e-10 on GetFEM's residual norm (absolute; 0.23 at the first
    # iteration, its round-off floor about 1.4e-12 at h = 0.005, which
    # 1e-12 does not reach: 100 iterations, not converged).
    noisy = ["noisy"] if os.environ.get("GF_NOISY") else []
    iterations, converged = md.solve("max_iter", 100, "max_res", 1e-10,
                                     "lsolver", "mumps", *noisy)
    if not converged:
        sys.exit(f"GetFEM's Newton did not converge in {iterations} "
                 "iterations")

    U = md.variable("u")
    mf.export_to_vtu(os.path.join(args.out, "getfem_hertz.vtu"),
                     mf, U, "displacement")

    # Check: the elements' forces K u at the top edge (its reaction).
    u = np.stack([U[dofs[:, 0]], U[dofs[:, 1]]], axis=1)
    internal = problems.quad_internal_forces(nodes, quads, u, E, nu)
    top_reaction = -2 * float(internal[top, 1].sum())
    if args.contact == "nodal":
        # Nodal contact forces: the multipliers (<= 0 in compression).
        force = -md.variable("lambda_n")
        x = mf.basic_dof_nodes()[0, contact_x_dofs]
    else:
        # The integral brick's nodal forces are what balances the elements'
        # forces at the arc's nodes (nothing else acts on them in y).
        order = np.argsort(nodes[arc_nodes, 0])
        x = nodes[arc_nodes, 0][order]
        force = internal[arc_nodes, 1][order]
    p0, a, P = problems.hertz_figures_from_nodal_forces(x, force)
    p0_hertz, a_hertz = problems.hertz_reference(P)
    print(json.dumps({
        "code": "getfem" if args.contact == "nodal" else "getfem-integral",
        "problem": "hertz", "h": args.h,
        "dofs": int(mf.nbdof()), "P": P, "p0": p0, "a": a,
        "p0_hertz": p0_hertz, "a_hertz": a_hertz,
        "error_p0": (p0 - p0_hertz) / p0_hertz,
        "error_a": (a - a_hertz) / a_hertz,
        "a_edge": problems.hertz_edge(x, force),
        "newton_iterations": int(iterations),
        "top_reaction": top_reaction,
    }))


def pid_map(m, nodes):
    """GetFEM point id -> index in `nodes`."""
    pids = m.pid_from_coords(nodes.T)
    inverse = np.full(m.max_pid() + 1, -1)
    inverse[pids] = np.arange(len(nodes))
    return inverse


def dof_map(mf, nodes):
    """x and y dofs of each node of `nodes` in the Q1 vector mesh_fem."""
    coords = mf.basic_dof_nodes()
    key = {(round(x, 12), round(y, 12)): k
           for k, (x, y) in enumerate(coords.T[::2])}
    first = np.array([2 * key[(round(x, 12), round(y, 12))]
                      for x, y in nodes])
    return np.stack([first, first + 1], axis=1)


if __name__ == "__main__":
    main()
