#!/usr/bin/python3
"""GetFEM's multi-body large-sliding demo (demo_large_sliding_contact.py,
its case 3) on the quadrilateral mesh that glissade reads too.

    /usr/bin/python3 benchmarks/peers/getfem_multi_body.py --mesh PATH \
        [--degree 1] [--steps 250] [--save 50] --out FILE.npz

Case 3 as the demo sets it: ten bodies of one mesh (three with a hole),
small-strain elasticity with lambda = mu = 1, a body force (0, -vf) per unit
area with vf = 0.01 at the first step and 1 % more at each of the 250
steps, a zero-order term 0.1 u (the demo's 'mass brick', which holds the
bodies before they touch), every boundary master and slave of GetFEM's
integral large-sliding contact brick (raytracing, release distance 0.05,
augmentation r = 0.1, frictionless), and the rigid bowl 2 - sqrt(x^2 +
(y - 1)^2), the inside of a circle of radius 2 about (0, 1). Newton to a
residual of 1e-9, at most 50 iterations a step.

The mesh is GetFEM's multi_body.mesh with every triangle cut into three
quadrilaterals (multi_body_mesh.py): Q`degree` elements with the Gauss
rule of degree 2 `degree` + 1 for the elasticity (2 x 2 points for Q1, as
glissade's Q4) and degree 4 on the contact boundary, as the demo's.

Writes the displacement at every mesh node (bodies in multi_body_mesh's
order) at every `save`-th step and at the last, with each step's body
force, the bowl's force on the bodies from the balance of the whole mesh
(the integral of 0.1 u minus that of the body force: the contact between
bodies cancels), Newton's iterations, the steps where Newton stopped at
its 50 iterations unconverged (GetFEM goes on from there, as the demo
does) and the time loop's seconds.
"""

import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import multi_body_mesh  # noqa: E402

import getfem as gf  # noqa: E402

LAMBDA = MU = 1.
FIRST_FORCE, GROWTH = 0.01, 1.01
ZERO_ORDER = 0.1
R_AUGMENTATION, RELEASE_DISTANCE = 0.1, 0.05
BOWL = "2-sqrt(sqr(x)+sqr(y-1))"


def build_mesh(bodies):
    mesh = gf.Mesh("empty", 2)
    gt = gf.GeoTrans("GT_QK(2,1)")
    for body in bodies:
        # GetFEM's Q_K vertex order is lexicographic: (0,0), (1,0), (0,1),
        # (1,1); the bodies' quads are counterclockwise.
        q = body.quads[:, [0, 1, 3, 2]]
        pts = body.points[q].transpose(2, 1, 0)  # 2 x 4 x n_quads
        mesh.add_convex(gt, pts)
    return mesh


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mesh", required=True,
                        help="GetFEM's tests/meshes/multi_body.mesh")
    parser.add_argument("--degree", type=int, default=1)
    parser.add_argument("--refine", type=int, default=0,
                        help="each quadrilateral cut into 4^REFINE")
    parser.add_argument("--steps", type=int, default=250)
    parser.add_argument("--save", type=int, default=50)
    parser.add_argument("--out", required=True)
    args = parser.parse_args()

    gf.util_trace_level(0)
    bodies = multi_body_mesh.multi_body_quads(args.mesh, args.refine)
    mesh = build_mesh(bodies)
    nodes = np.vstack([b.points for b in bodies]).T

    mfu = gf.MeshFem(mesh, 2)
    mfu.set_classical_fem(args.degree)
    pre_mflambda = gf.MeshFem(mesh, 2)
    pre_mflambda.set_classical_fem(1)
    CONTACT = 1
    mesh.set_region(CONTACT, mesh.outer_faces())
    mim = gf.MeshIm(mesh, 2 * args.degree + 1)
    mim_contact = gf.MeshIm(mesh, 4)

    md = gf.Model("real")
    md.add_fem_variable("u1", mfu)
    md.add_filtered_fem_variable("lambda1", pre_mflambda, CONTACT)
    md.add_initialized_data("clambda1", LAMBDA)
    md.add_initialized_data("cmu1", MU)
    md.add_isotropic_linearized_elasticity_brick(mim, "u1", "clambda1",
                                                 "cmu1")
    md.add_initialized_data("penalty_param1", [ZERO_ORDER])
    md.add_mass_brick(mim, "u1", "penalty_param1")
    vf = FIRST_FORCE
    md.add_initialized_data("data1", [0., -vf])
    md.add_source_term_brick(mim, "u1", "data1")
    md.add_initialized_data("r", R_AUGMENTATION)
    md.add_initialized_data("alpha", 1.)
    md.add_initialized_data("f", 0.)
    brick = md.add_integral_large_sliding_contact_brick_raytracing(
        "r", RELEASE_DISTANCE, "f", "alpha", 0)
    md.add_master_slave_contact_boundary_to_large_sliding_contact_brick(
        brick, mim_contact, CONTACT, "u1", "lambda1", "")
    md.add_rigid_obstacle_to_large_sliding_contact_brick(brick, BOWL, 2)

    area = gf.asm_generic(mim, 0, "1", -1)
    saved, forces, reactions, iterations, unconverged = [], [], [], [], []
    start = time.perf_counter()
    for step in range(args.steps):
        md.set_variable("data1", [0., -vf])
        n_iterations, converged = md.solve("max_iter", 50, "max_res", 1e-9)
        iterations.append(int(n_iterations))
        if not converged:
            unconverged.append(step + 1)
        U = md.variable("u1")
        integral_u = gf.asm_generic(mim, 0, "u1", -1, md)
        # The bowl's force on the bodies: what holds the whole mesh
        # against its body force and zero-order term.
        reactions.append(ZERO_ORDER * np.asarray(integral_u) -
                         np.array([0., -vf]) * area)
        forces.append(vf)
        last = step == args.steps - 1
        if (step + 1) % args.save == 0 or last:
            saved.append((step + 1, gf.compute_interpolate_on(mfu, U, nodes)))
            print(f"step {step + 1}: force {vf:.6g}, bowl "
                  f"{reactions[-1][1]:.6g}, {n_iterations} iterations, "
                  f"{time.perf_counter() - start:.1f} s", flush=True)
        vf *= GROWTH
    seconds = time.perf_counter() - start
    np.savez(args.out, steps=np.array([s for s, _ in saved]),
             displacement=np.array([u for _, u in saved]),
             force=np.array(forces), bowl=np.array(reactions),
             iterations=np.array(iterations),
             unconverged=np.array(unconverged, dtype=int), seconds=seconds,
             dofs=mfu.nbdof(), area=area)
    print(f"dofs {mfu.nbdof()}, time loop {seconds:.2f} s, Newton "
          f"iterations {sum(iterations)}, steps not converged "
          f"{len(unconverged)} {unconverged[:10]}")


if __name__ == "__main__":
    main()
