#!/usr/bin/python3
"""GetFEM peer, dynamics: the elastic bar hitting a rigid wall
(prm/bar_impact.prm).

    /usr/bin/python3 getfem_bar_impact.py [--refine K] [--mass redistributed]
        [--contact nodal] [--steps-per-unit 100] [--t-end 3]

The bar x in [0, 1], y in [0, 0.1], 100 K x 2 K Q1 cells (FEM_QK(2,1) on
a cartesian mesh, 2 x 2 Gauss, which integrates the Q1 mass exactly),
E = 1, nu = 0, density 1 (c = 1), plane strain small-strain elasticity
(GetFEM's isotropic linearized elasticity brick), u_y = 0 on the top and
bottom edges (rollers, dof constraints with multipliers as in
getfem_hertz.py), initial velocity (-0.001, 0), u = 0; the rigid wall
x = 0, which the left edge touches at t = 0, frictionless.

Contact (--contact): `nodal` (default), GetFEM's nodal contact with rigid
obstacle brick (signed distance "x", one multiplier per node of the left
edge, non-symmetric Alart-Curnier augmented Lagrangian, r = --r), or
`nitsche`, GetFEM's Nitsche contact with rigid obstacle brick (theta = 0,
gamma0 = --gamma0, the elasticity brick's Neumann term).

Time: Newmark, beta = 1/4, gamma = 1/2, dt = 1 / (steps-per-unit x K), by
hand as GetFEM's own demo_dynamic_contact_1D.py does it (GetFEM's model
time dispatcher cannot take a modified mass matrix): every step is one
model solve for u_{n+1} (GetFEM's Newton, MUMPS) with the explicit matrix
M / (beta dt^2) beside the elasticity brick and the explicit right-hand
side M / (beta dt^2) (u_n + dt v_n + dt^2 (1/2 - beta) a_n); then
a_{n+1} = (u_{n+1} - that predictor) / (beta dt^2), v_{n+1} = v_n +
dt ((1 - gamma) a_n + gamma a_{n+1}).

Mass (--mass): `redistributed` (default; Khenous, Laborde and Renard,
2008, which GetFEM offers only as hand-made matrices in its 1D demo, so
it is done here on GetFEM's assembled mass, as glissade does it): the
cells that hold a left-edge node are lumped by the HRZ rule and the
left-edge nodes' mass moved to the cells' other nodes of the same
component in proportion to theirs (cell mass and momentum kept, the
contact nodes massless); `consistent`: plain Newmark, GetFEM's mass.

Prints dofs, steps, the wall time of the time loop alone
(time.perf_counter, set-up excluded) and per step, the Newton iterations,
the contact duration (first to last step whose contact force exceeds
--force-tol x rho c v0 H, + dt; closed form 2 L / c = 2), the mean contact
force over those steps (closed form rho c v0 H = 1e-4), its least and
largest value there and the steps with none (chatter), the mean x velocity
at the end (the x momentum over the mass; closed form +0.001), the energy
(kinetic + strain) at the start and the end and its relative drift; the
last line is the same as JSON. The contact force is the x resultant of
M a + K u (what the wall pushes with, whatever the formulation; for the
nodal brick it is minus the sum of its multipliers).
"""

import argparse
import json
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import problems  # noqa: E402

import getfem as gf  # noqa: E402

gf.util_trace_level(0)

LENGTH, HEIGHT, E, NU, RHO, V0 = 1.0, 0.1, 1.0, 0.0, 1.0, 0.001
BETA, GAMMA = 0.25, 0.5
LEFT, TOP, BOTTOM, CELL = 1, 2, 3, 4


def redistribute(m, mf, mim, md0, M):
    """Khenous-Laborde-Renard on M (in place): the left edge's cells HRZ
    lumped, their left-edge nodes' mass moved to their other nodes."""
    contact = set(int(d) for d in mf.basic_dof_on_region(LEFT))
    for cv in np.unique(m.region(LEFT)[0]):
        m.set_region(CELL, np.array([[cv]]))
        Me = gf.asm_generic(mim, 2, f"{RHO}*u.Test_u", CELL, md0)
        dofs = [int(d) for d in mf.basic_dof_from_cv(int(cv))]
        for i in dofs:
            for j in dofs:
                M[i, j] = M[i, j] - Me[i, j]
        for comp in (0, 1):        # dof = 2 node + component (qdim 2)
            cd = [i for i in dofs if i % 2 == comp]
            cell_mass = sum(Me[i, j] for i in cd for j in cd)
            diag = np.array([Me[i, i] for i in cd])
            lumped = diag * cell_mass / diag.sum()
            on = np.array([i in contact for i in cd])
            lumped[~on] += lumped[on].sum() * lumped[~on] / lumped[~on].sum()
            lumped[on] = 0.0
            for i, mass in zip(cd, lumped):
                M[i, i] = M[i, i] + mass


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--refine", type=int, default=1)
    parser.add_argument("--steps-per-unit", type=int, default=100,
                        help="time steps per unit time at --refine 1")
    parser.add_argument("--t-end", type=float, default=3.0)
    parser.add_argument("--mass", choices=("redistributed", "consistent"),
                        default="redistributed")
    parser.add_argument("--contact", choices=("nodal", "nitsche"),
                        default="nodal")
    parser.add_argument("--r", type=float, default=E,
                        help="augmentation parameter of the nodal brick")
    parser.add_argument("--gamma0", type=float, default=E,
                        help="Nitsche parameter (GetFEM's gamma0)")
    parser.add_argument("--max-res", type=float, default=1e-12)
    parser.add_argument("--force-tol", type=float, default=1e-6)
    args = parser.parse_args()
    k = args.refine
    nx, ny = 100 * k, 2 * k
    dt = 1.0 / (args.steps_per_unit * k)
    steps = int(round(args.t_end / dt))
    lam, mu = problems.lame_coefficients(E, NU)

    m = gf.Mesh("cartesian", np.linspace(0, LENGTH, nx + 1),
                np.linspace(0, HEIGHT, ny + 1))
    faces = m.outer_faces()
    normals = m.normal_of_faces(faces)
    m.set_region(LEFT, faces[:, normals[0] < -0.5])
    m.set_region(TOP, faces[:, normals[1] > 0.5])
    m.set_region(BOTTOM, faces[:, normals[1] < -0.5])
    mf = gf.MeshFem(m, 2)
    mf.set_fem(gf.Fem("FEM_QK(2,1)"))
    mim = gf.MeshIm(m, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,2)"))
    n = mf.nbdof()
    xdofs = np.arange(0, n, 2)
    left_x = [int(d) for d in mf.basic_dof_on_region(LEFT) if d % 2 == 0]
    assert np.allclose(mf.basic_dof_nodes()[:, 0::2],
                       mf.basic_dof_nodes()[:, 1::2])

    # K and M, once (a model holding u alone, so that they are n x n).
    md0 = gf.Model("real")
    md0.add_fem_variable("u", mf)
    md0.add_initialized_data("lambda", [lam])
    md0.add_initialized_data("mu", [mu])
    K = gf.asm_generic(mim, 2, "lambda*Div_u*Div_Test_u"
                       " + mu*(Grad_u+Grad_u'):Grad_Test_u", -1, md0)
    M = gf.asm_generic(mim, 2, f"{RHO}*u.Test_u", -1, md0)
    if args.mass == "redistributed":
        redistribute(m, mf, mim, md0, M)
    mass = float(np.sum(M.mult(np.tile([1.0, 0.0], n // 2))[xdofs]))

    md = gf.Model("real")
    md.add_fem_variable("u", mf)
    md.add_initialized_data("lambda", [lam])
    md.add_initialized_data("mu", [mu])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")
    Mdyn = gf.Spmat("copy", M)
    Mdyn.scale(1.0 / (BETA * dt * dt))
    md.add_explicit_matrix("u", "u", Mdyn)
    inertia = md.add_explicit_rhs("u", np.zeros(n))
    rollers = sorted(int(d) for region in (TOP, BOTTOM)
                     for d in mf.basic_dof_on_region(region) if d % 2 == 1)
    B = gf.Spmat("empty", len(rollers), n)
    for row, dof in enumerate(rollers):
        B.add([row], [dof], np.array([[1.0]]))
    md.add_variable("rollers", len(rollers))
    md.add_constraint_with_multipliers("u", "rollers", B,
                                       np.zeros(len(rollers)))
    if args.contact == "nodal":
        md.add_variable("lambda_n", len(mf.basic_dof_on_region(LEFT)) // 2)
        md.add_initialized_data("r", [args.r])
        md.add_nodal_contact_with_rigid_obstacle_brick(
            mim, "u", "lambda_n", "r", LEFT, "x", 1)
    else:
        mfd = gf.MeshFem(m, 1)
        mfd.set_fem(gf.Fem("FEM_QK(2,1)"))
        md.add_initialized_fem_data("obstacle", mfd, mfd.eval("x"))
        md.add_initialized_data("gamma0", [args.gamma0])
        md.add_Nitsche_contact_with_rigid_obstacle_brick(
            mim, "u", md.Neumann_term("u", LEFT), "obstacle", "gamma0",
            LEFT, 0.0)

    u, v, a = np.zeros(n), np.zeros(n), np.zeros(n)   # M a0 = -K u0 = 0
    v[xdofs] = -V0
    md.set_variable("u", u)

    def energy(u, v):
        return 0.5 * (v @ M.mult(v) + u @ K.mult(u))

    energy0 = energy(u, v)
    force = np.zeros(steps)
    iterations, gap = 0, 0.0
    start = time.perf_counter()
    for step in range(steps):
        predictor = u + dt * v + dt * dt * (0.5 - BETA) * a
        md.set_private_rhs(inertia, Mdyn.mult(predictor))
        its, converged = md.solve("max_iter", 50, "max_res", args.max_res,
                                  "lsolver", "mumps")
        if not converged:
            sys.exit(f"Newton did not converge at step {step + 1}")
        iterations += int(its)
        u_new = md.variable("u")
        a_new = (u_new - predictor) / (BETA * dt * dt)
        v = v + dt * ((1 - GAMMA) * a + GAMMA * a_new)
        u, a = u_new, a_new
        force[step] = float(np.sum((M.mult(a) + K.mult(u))[xdofs]))
        gap = min(gap, float(u[left_x].min()))    # the wall is x = 0
    elapsed = time.perf_counter() - start

    reference = RHO * np.sqrt(E / RHO) * V0 * HEIGHT
    on = np.nonzero(force > args.force_tol * reference)[0]
    first, last = (int(on[0]), int(on[-1])) if len(on) else (0, -1)
    window = force[first:last + 1]
    duration = (last - first + 1) * dt
    energy1 = energy(u, v)
    velocity = float(np.sum(M.mult(v)[xdofs])) / mass
    figures = {
        "code": "getfem", "problem": "bar_impact", "refine": k,
        "contact": args.contact, "mass": args.mass,
        "dofs": int(n), "steps": steps, "dt": dt,
        "loop_time": elapsed, "time_per_step": elapsed / steps,
        "newton_iterations": iterations,
        "contact_start": (first + 1) * dt, "contact_end": (last + 1) * dt,
        "contact_duration": duration,
        "mean_contact_force": float(window.mean()) if len(window) else 0.0,
        "min_contact_force": float(window.min()) if len(window) else 0.0,
        "max_contact_force": float(window.max()) if len(window) else 0.0,
        "zero_force_steps_in_contact":
            int(np.sum(window <= args.force_tol * reference)),
        "impulse": float(np.sum(force) * dt),
        "least_gap": gap, "final_velocity": velocity,
        "energy_start": energy0, "energy_end": energy1,
        "energy_drift": (energy1 - energy0) / energy0,
    }
    print(f"GetFEM, {args.contact} contact, "
          f"{args.mass} mass, Newmark beta = {BETA}, gamma = {GAMMA}")
    print(f"dofs {n}, steps {steps}, dt {dt:g}")
    print(f"time loop {elapsed:.3f} s, {1e3 * elapsed / steps:.3f} ms/step, "
          f"{iterations} Newton iterations")
    print(f"contact from t = {figures['contact_start']:.4g} to "
          f"{figures['contact_end']:.4g}: duration {duration:.4g} "
          "(closed form 2)")
    print(f"mean contact force {figures['mean_contact_force']:.6g} "
          f"(closed form {reference:g}), min "
          f"{figures['min_contact_force']:.4g}, max "
          f"{figures['max_contact_force']:.4g}, "
          f"{figures['zero_force_steps_in_contact']} steps without")
    print(f"least gap x + u_x on the left edge {gap:.3g}")
    print(f"velocity at the end {velocity:.6g} (closed form {V0:g})")
    print(f"energy start {energy0:.6g}, end {energy1:.6g}, drift "
          f"{figures['energy_drift']:.3e}")
    print(json.dumps(figures))


if __name__ == "__main__":
    main()
