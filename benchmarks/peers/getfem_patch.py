#!/usr/bin/python3
"""GetFEM peer, the contact patch test (issue 36): two blocks on
non-matching meshes, the scene of glissade_patch.prm (tests/mortar_test.cc,
patch_scene).

    /usr/bin/python3 getfem_patch.py UPPER LOWER [--slave upper|lower]
        [--friction] [--contact integral|nodal] [--contact-order K]
        --out DIR

The upper block [0, 1] x [0.5, 1] of UPPER x 3 Q1 cells on the lower
[0, 1] x [0, 0.5] of LOWER x 4 (5 on 8, 7 on 13 in the benchmark), each a
mesh of its own built from its node and quad arrays with GT_QK(2,1), not
by Mesh("cartesian"): that one's cells are GT_LINEAR_PRODUCT(GT_PK(1,1),
GT_PK(1,1)), and on such a master the integral brick's projection of the
master onto the slave (new_projected_fem) stops at the first assembly
with gmm's "non invertible matrix" (GetFEM 5.4.2; the slave may be either;
this, not a rigid mode, is what stopped the first attempt). Q1
(FEM_QK(2,1)), 2 x 2 Gauss, small-strain isotropic linear elasticity,
plane strain,
E = 1000, nu = 0.3. Small strain is enough here: the figure is how far
each slave node's traction is from the uniform one, and the uniform stress
is the exact solution of the small-strain problem as of glissade's
large-strain one (both blocks of one material, a homogeneous deformation);
the applied traction itself differs by the 2 % strain (21.98 against
glissade's 22.17), each code being compared with its own.

Supports, as glissade's scene (dof constraints with multipliers, exact at
the nodes): frictionless, u_x = 0 on both left sides, u_y = -0.02 on the
upper top, u_y = 0 on the lower bottom, the right sides free. Each block is
then held in x by its left side and in y by its top or bottom: no rigid
mode is left to the frictionless contact. --friction: every outer side of
both blocks (upper top, left, right; lower bottom, left, right) moved by
u = (0.004 y, -0.02 y), mu = 0.5: the uniform stress sticks (shear /
pressure 0.057). The interface's two end nodes then belong to supported
sides of both blocks: their contact force goes straight into the supports
and the contact does not determine it (glissade's mortar leaves them
inactive; GetFEM's nodal multipliers there wander, and its Newton takes
up to 56 iterations for them; its integral multiplier there is reached
only through the first interior node's hat function). The figure is
therefore also given without the two ends.

Contact: --contact integral (default) is GetFEM's integral contact between
non-matching meshes (add_integral_contact_between_nonmatching_meshes_brick,
small sliding: the master's displacement projected onto the slave
boundary, new_projected_fem), its multiplier a Q1 field on the slave
boundary (scalar, the normal stress; a vector with friction),
non-symmetric Alart-Curnier (option 1), r = E. The slave is body 1 of the
brick. The contact terms are integrated with the bulk's rule on the slave
faces (2 Gauss points a face), or with --contact-order K (Gauss of that
order on the faces, IM_GAUSS_PARALLELEPIPED(2,K)): the master's projected
shape functions have a kink inside a slave face, which a Gauss rule does
not integrate exactly, and the master's nodes then receive a uniform
pressure's forces inexactly. --contact nodal is GetFEM's nodal contact
between non-matching meshes (add_nodal_contact_between_nonmatching_meshes_
brick: node-to-segment, its multipliers the slave nodes' forces; GetFEM's
Python interface mis-reads its friction variant's arguments, see below).
Newton (GetFEM's Model.solve, at most 200 iterations) to 1e-11, MUMPS.

The figure, as glissade's test reads it: each slave node in contact, its
contact force over its tributary length (the integral of its hat function
on the slave boundary) against the applied traction (the upper top's
support force, K u at the top's nodes, over the top's width 1, with the
sign of the traction on the slave), the largest relative difference of the
vectors. The integral brick's nodal forces are the multiplier field
integrated against the slave's hat functions (f_i = int lambda phi_i); the
multiplier's own nodal values against the applied traction are reported
too ("error_multiplier").

Writes the displacements once to DIR/getfem_patch_upper.vtu and
DIR/getfem_patch_lower.vtu and prints as its last line {"code",
"problem": "patch", "upper", "lower", "slave", "friction", "dofs",
"applied" (the traction vector), "n_checked" (slave nodes in contact),
"n_slave", "error", "error_interior" (the same without the interface's
two end nodes), "error_multiplier", "tractions" (each slave node's x and
traction vector), "newton_iterations"}.
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

E, NU = problems.PATCH_E, problems.PATCH_NU
BOXES = {"upper": (0.0, 0.5, 1.0, 1.0), "lower": (0.0, 0.0, 1.0, 0.5)}


def rectangle(nx, ny, box):
    """Nodes (n, 2) of an nx x ny grid of box (x0, y0, x1, y1), numbered
    row by row, and its quads (m, 4) counter-clockwise."""
    x0, y0, x1, y1 = box
    # The same doubles as deal.II's subdivided_hyper_rectangle: x0 + i dx.
    xs = [x0 + i * (x1 - x0) / nx for i in range(nx + 1)]
    ys = [y0 + j * (y1 - y0) / ny for j in range(ny + 1)]
    nodes = np.array([[x, y] for y in ys for x in xs])
    i, j = np.meshgrid(np.arange(nx), np.arange(ny), indexing="xy")
    i, j = i.ravel(), j.ravel()
    v = j * (nx + 1) + i
    quads = np.stack([v, v + 1, v + nx + 2, v + nx + 1], axis=1)
    return nodes, quads


class Block:
    """One block: its mesh, Q1 vector field and the regions of its sides."""

    SIDES = {"left": ([-1, 0], 1), "right": ([1, 0], 2),
             "bottom": ([0, -1], 3), "top": ([0, 1], 4)}

    def __init__(self, name, cells):
        self.name = name
        self.nodes, self.quads = rectangle(cells, problems.PATCH_LAYERS[name],
                                            BOXES[name])
        # GT_QK(2,1) cells: Mesh("cartesian")'s linear product cells stop
        # the integral brick's projection (the docstring).
        self.mesh = gf.Mesh("empty", 2)
        pts = np.transpose(self.nodes[problems.lexicographic(self.quads)],
                           (2, 1, 0))
        self.mesh.add_convex(gf.GeoTrans("GT_QK(2,1)"), pts)
        for direction, region in self.SIDES.values():
            self.mesh.set_region(region, self.mesh.outer_faces_with_direction(
                direction, 0.01))
        self.fem = gf.Fem("FEM_QK(2,1)")
        self.mf = gf.MeshFem(self.mesh, 2)
        self.mf.set_fem(self.fem)
        self.mim = gf.MeshIm(self.mesh,
                             gf.Integ("IM_GAUSS_PARALLELEPIPED(2,2)"))
        self.dofs = dof_map(self.mf, self.nodes)

    def region(self, side):
        return self.SIDES[side][1]

    def side_nodes(self, side):
        """Indices in self.nodes of the nodes on a side."""
        x0, y0, x1, y1 = BOXES[self.name]
        coordinate, value = {"left": (0, x0), "right": (0, x1),
                             "bottom": (1, y0), "top": (1, y1)}[side]
        return np.nonzero(np.abs(self.nodes[:, coordinate] - value)
                          < 1e-12)[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("upper", type=int, help="upper block's cells along x")
    parser.add_argument("lower", type=int, help="lower block's cells along x")
    parser.add_argument("--slave", choices=("upper", "lower"),
                        default="upper")
    parser.add_argument("--friction", action="store_true",
                        help="Coulomb, mu = 0.5, every outer side moved "
                             "by the homogeneous shear and compression")
    parser.add_argument("--contact", choices=("integral", "nodal"),
                        default="integral")
    parser.add_argument("--contact-order", type=int, default=None,
                        help="Gauss order of the integral contact terms "
                             "(default: the bulk's, 2 points a face)")
    parser.add_argument("--out", default=".")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    lam, mu = problems.lame_coefficients(E, NU)

    blocks = {"upper": Block("upper", args.upper),
              "lower": Block("lower", args.lower)}
    slave = blocks[args.slave]
    master = blocks["lower" if args.slave == "upper" else "upper"]
    slave_side = "bottom" if args.slave == "upper" else "top"
    master_side = "top" if args.slave == "upper" else "bottom"

    md = gf.Model("real")
    md.add_initialized_data("lambda", [lam])
    md.add_initialized_data("mu", [mu])
    for name, block in blocks.items():
        md.add_fem_variable("u_" + name, block.mf)
        md.add_isotropic_linearized_elasticity_brick(
            block.mim, "u_" + name, "lambda", "mu")
        add_supports(md, block, args.friction)

    md.add_initialized_data("r", [E])
    q = 2 if args.friction else 1
    if args.friction:
        md.add_initialized_data("friction", [problems.PATCH_MU])
    if args.contact == "integral":
        # The multiplier: a Q1 field on the slave boundary (the nodes of
        # that side only), scalar (the normal stress) or with friction a
        # vector (the traction).
        mf_full = gf.MeshFem(slave.mesh, q)
        mf_full.set_fem(slave.fem)
        kept = mf_full.basic_dof_on_region(slave.region(slave_side))
        mf_lambda = gf.MeshFem("partial", mf_full, kept)
        md.add_fem_variable("lambda_c", mf_lambda)
        mim_contact = slave.mim
        if args.contact_order:
            mim_contact = gf.MeshIm(slave.mesh, gf.Integ(
                f"IM_GAUSS_PARALLELEPIPED(2,{args.contact_order})"))
        friction = ["friction"] if args.friction else []
        md.add_integral_contact_between_nonmatching_meshes_brick(
            mim_contact, "u_" + slave.name, "u_" + master.name, "lambda_c",
            "r", *friction, slave.region(slave_side),
            master.region(master_side), 1)
    else:
        # The brick makes its multipliers itself: one normal force per
        # slave node (and a tangential one with friction). The slave is rg1
        # (slave1 = 1, slave2 = 0) and Alart-Curnier non-symmetric (1):
        # the defaults.
        strings = ["lambda_n", "r"]
        if args.friction:
            # GetFEM 5.4's interface (gf_model_set.cc) takes the string
            # after multname_n for r, pops the next argument to see whether
            # it is rg1, and when it is a string (the friction variant)
            # drops it and reads r and the coefficient from the two after
            # it: a placeholder stands where it drops one. Without it,
            # "friction" is read as r and rg1 as the coefficient ("Argument
            # 11 must be a string").
            strings = ["lambda_n", "lambda_t", "placeholder", "r", "friction"]
        md.add_nodal_contact_between_nonmatching_meshes_brick(
            slave.mim, master.mim, "u_" + slave.name, "u_" + master.name,
            *strings, slave.region(slave_side), master.region(master_side))

    noisy = ["noisy"] if os.environ.get("GF_NOISY") else []
    iterations, converged = md.solve("max_iter", 200, "max_res", 1e-11,
                                     "lsolver", "mumps", *noisy)
    if not converged:
        sys.exit(f"GetFEM's Newton did not converge in {iterations} "
                 "iterations")

    for name, block in blocks.items():
        block.mf.export_to_vtu(
            os.path.join(args.out, f"getfem_patch_{name}.vtu"), block.mf,
            md.variable("u_" + name), "displacement")

    # The applied traction: the upper top's support force (K u at its nodes,
    # nothing else acts there) over the top's width (small strain: the
    # reference one, 1); on the upper block's bottom the traction is minus
    # it, on the lower block's top it is it.
    upper = blocks["upper"]
    U = md.variable("u_upper")
    u = np.stack([U[upper.dofs[:, 0]], U[upper.dofs[:, 1]]], axis=1)
    internal = problems.quad_internal_forces(upper.nodes, upper.quads, u,
                                             E, NU)
    support = internal[upper.side_nodes("top")].sum(axis=0)
    width = BOXES["upper"][2] - BOXES["upper"][0]
    applied = (-1.0 if args.slave == "upper" else 1.0) * support / width

    # The slave nodes' tractions.
    side = slave.side_nodes(slave_side)
    order = np.argsort(slave.nodes[side, 0])
    side = side[order]
    x = slave.nodes[side, 0]
    normal = np.array([0.0, -1.0 if args.slave == "upper" else 1.0])
    # The hat functions' integrals on the slave side (their tributary
    # lengths) and the mass matrix that turns a field into nodal forces.
    mf_s = gf.MeshFem(slave.mesh, 1)
    mf_s.set_fem(slave.fem)
    M = gf.asm_mass_matrix(slave.mim, mf_s, mf_s,
                           slave.region(slave_side)).full()
    scalar_dof = dof_map(mf_s, slave.nodes, qdim=1)[side, 0]
    M = M[np.ix_(scalar_dof, scalar_dof)]
    tributary = M.sum(axis=1)
    if args.contact == "integral":
        # The multiplier's nodal values, node by node (the partial field's
        # dofs are the kept ones of the full field, in their order).
        values = md.variable("lambda_c").reshape(-1, q)
        where = mf_full.basic_dof_nodes()[:, np.sort(kept)[::q]].T
        field = np.zeros((len(side), q))
        for k, p in enumerate(slave.nodes[side]):
            field[k] = values[np.argmin(np.hypot(*(where - p).T))]
        # The traction on the slave: lambda_n n (lambda_n <= 0 in
        # compression, n the slave's outward normal), or the vector lambda.
        multiplier = (field[:, :1] * normal if q == 1 else field)
        force = M @ multiplier
    else:
        # The nodal brick's multipliers are the slave nodes' forces, in the
        # order of their first dof, along the master's outward normal N
        # and the tangent T that Gram-Schmidt makes of e_x against it
        # (getfem_contact_and_friction_nodal.cc: the slave's rows of BN
        # and BT are -N and -T): the force on the slave is
        # -(lambda_n N + lambda_t T).
        N = -normal
        T = np.array([1.0, 0.0]) - N[0] * N
        T /= np.linalg.norm(T)
        lambda_n = md.variable("lambda_n")
        lambda_t = (md.variable("lambda_t") if args.friction
                    else np.zeros(len(lambda_n)))
        first = np.sort(slave.mf.basic_dof_on_region(
            slave.region(slave_side)))[::2]
        node_of = {int(d): k for k, d in enumerate(slave.dofs[side, 0])}
        force = np.zeros((len(side), 2))
        for k, dof in enumerate(first):
            force[node_of[int(dof)]] = -(lambda_n[k] * N + lambda_t[k] * T)
        multiplier = None
    # In contact: a compressive normal force (1e-9 of the applied one).
    pressing = -(force @ normal) > 1e-9 * np.linalg.norm(applied) * tributary
    error, error_interior, n_checked = problems.patch_figures(
        x, force, tributary, applied, pressing)
    error_multiplier = None
    if multiplier is not None:
        # The multiplier's nodal values are tractions already.
        error_multiplier = problems.patch_figures(
            x, multiplier, np.ones(len(x)), applied, pressing)[0]
    traction = force / tributary[:, None]
    print(json.dumps({
        "code": "getfem" if args.contact == "nodal" else "getfem-integral",
        "problem": "patch", "upper": args.upper, "lower": args.lower,
        "slave": args.slave, "friction": args.friction,
        "contact_order": args.contact_order,
        "dofs": int(upper.mf.nbdof() + blocks["lower"].mf.nbdof()),
        "applied": applied.tolist(),
        "n_checked": n_checked, "n_slave": len(side),
        "error": error, "error_interior": error_interior,
        "error_multiplier": error_multiplier,
        "tractions": [[float(xk), *map(float, t)]
                      for xk, t in zip(x, traction)],
        "newton_iterations": int(iterations),
    }))


def add_supports(md, block, friction):
    """The block's supports as dof constraints with multipliers."""
    if friction:
        sides = ["top", "left", "right"] if block.name == "upper" else \
            ["bottom", "left", "right"]
        held = np.unique(np.concatenate([block.side_nodes(s) for s in sides]))
        y = block.nodes[held, 1]
        rows = [block.dofs[held, 0], block.dofs[held, 1]]
        values = [problems.PATCH_SHEAR * y, -problems.PATCH_DRIVE * y]
    else:
        left = block.side_nodes("left")
        rows, values = [block.dofs[left, 0]], [np.zeros(len(left))]
        if block.name == "upper":
            top = block.side_nodes("top")
            rows.append(block.dofs[top, 1])
            values.append(np.full(len(top), -problems.PATCH_DRIVE))
        else:
            bottom = block.side_nodes("bottom")
            rows.append(block.dofs[bottom, 1])
            values.append(np.zeros(len(bottom)))
    rows, values = np.concatenate(rows), np.concatenate(values)
    B = gf.Spmat("empty", len(rows), block.mf.nbdof())
    for row, dof in enumerate(rows):
        B.add([row], [int(dof)], np.array([[1.0]]))
    name = "supports_" + block.name
    md.add_variable(name, len(rows))
    md.add_constraint_with_multipliers("u_" + block.name, name, B, values)


def dof_map(mf, nodes, qdim=2):
    """The dofs of each node of `nodes` in a Q1 mesh_fem: (n, qdim)."""
    coords = mf.basic_dof_nodes()
    key = {(round(x, 12), round(y, 12)): k
           for k, (x, y) in enumerate(coords.T[::qdim])}
    first = np.array([qdim * key[(round(x, 12), round(y, 12))]
                      for x, y in nodes])
    return np.stack([first + c for c in range(qdim)], axis=1)


if __name__ == "__main__":
    main()
