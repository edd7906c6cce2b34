#!/usr/bin/python3
"""glissade beside GetFEM on GetFEM's multi-body large-sliding demo
(demo_large_sliding_contact.py, case 3): ten bodies, three with a hole, in
a rigid bowl, every boundary both master and slave.

    /usr/bin/python3 benchmarks/peers/multi_body_race.py --mesh PATH \
        [--glissade build/glissade] [--steps 250] [--save 25] \
        [--repeats 1] [--codes glissade,getfem] [--self-contact] \
        [--refine 0] [--passes one] [--plot FILE.png] \
        [--work /tmp/glissade-multi-body]

PATH is GetFEM's tests/meshes/multi_body.mesh (from GetFEM's sources; not
shipped here). Both codes solve the same scene on the same mesh, GetFEM's
triangles cut into quadrilaterals (multi_body_mesh.py), with Q1 elements and
2 x 2 Gauss points: small-strain elasticity, lambda = mu = 1 (E = 2.5, nu =
0.25, plane strain); a body force 0.01 * 1.01^(n - 1) down at step n = 1 ...
250; a zero-order term 0.1 u (GetFEM's mass brick; glissade's Boundary
conditions/Elastic foundation); frictionless contact among all the bodies'
boundaries (glissade: Scene/Contact bodies, one pass unless --passes two,
faceted masters, alert distance 0.05 as GetFEM's release distance) and with the bowl, the
inside of the circle of radius 2 about (0, 1) (glissade: an obstacle
'hole'). GetFEM's contact is its integral augmented-Lagrangian brick;
glissade's the paper's node-to-segment bi-potential method: two
discretisations of one contact law, which agree as the mesh is refined.

Prints, at every `save`-th step: each body's mean displacement (its nodes'
average) in both codes and their difference against its size, the largest
nodal difference against the largest displacement, and the bowl's vertical
force (GetFEM: from the balance of the whole mesh; glissade: its contact
force, and from the same balance beside it). Then each code's time loop
(glissade's run wall time from summary.txt, set-up included; GetFEM's
perf_counter around its steps), repeated REPEATS times alternately, and
their ratio. Nothing here is a test: the figures go to doc/performance.md
and doc/contact.md by hand.
"""

import argparse
import csv
import os
import re
import statistics
import subprocess
import sys

import numpy as np
from scipy.spatial import cKDTree

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import multi_body_mesh  # noqa: E402
from vtu_reader import vtu_arrays  # noqa: E402

E, NU = 2.5, 0.25          # lambda = mu = 1
FOUNDATION = 0.1


def write_glissade_scene(bodies, folder, steps, save, self_contact,
                         passes="two"):
    names = [f"body{k}" for k in range(len(bodies))]
    for name, body in zip(names, bodies):
        multi_body_mesh.write_msh(body, os.path.join(folder, name + ".msh"))
    lines = ["subsection Scene",
             f"  set Bodies         = {', '.join(names)}",
             "  set Contact bodies = " +
             ", ".join(f"{n}: surface" for n in names),
             "  set Contact pairs  = bowl",
             "end",
             "subsection Automatic contact",
             f"  set Passes         = {passes}",
             f"  set Self-contact   = {'true' if self_contact else 'false'}",
             "  set Surface        = faceted",
             "  set Alert distance = 0.05",
             "end",
             "subsection Contact bowl",
             "  set Slave body     = *",
             "  set Slave boundary = surface",
             "  set Master body    = rigid",
             "  set Alert distance = 0.05",
             "  subsection Obstacle",
             "    set Type   = hole",
             "    set Point  = 0, 1",
             "    set Radius = 2",
             "  end",
             "end"]
    for name in names:
        lines += [f"subsection Body {name}",
                  "  subsection Mesh",
                  "    set Type = gmsh",
                  f"    set File = {name}.msh",
                  "  end",
                  "  subsection Material",
                  f"    set Young modulus = {E}",
                  f"    set Poisson ratio = {NU}",
                  "    set Kinematics    = small strain",
                  "    set Density       = 1",
                  "  end",
                  "  subsection Boundary conditions",
                  "    set Gravity            = 0, -0.01*1.01^(t-1)",
                  f"    set Elastic foundation = {FOUNDATION}",
                  "  end",
                  "end"]
    lines += ["subsection Load program",
              f"  set Stage end times  = {steps}",
              f"  set Stage increments = {steps}",
              "end",
              "subsection Output",
              "  set Progress               = false",
              f"  set VTU interval           = {save}",
              "  set VTU fields             = displacement",
              f"  set Contact table interval = {steps}",
              "  set Initial state          = false",
              "  set History                = contact_force(bowl)",
              "end"]
    path = os.path.join(folder, "multi_body.prm")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def run_glissade(binary, prm, out):
    subprocess.run([binary, prm, "--set", f"Output/Directory={out}"],
                   check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.txt")) as f:
        first = f.readline()
    seconds = float(re.search(r"([0-9.e+-]+) s wall", first).group(1))
    dofs = int(re.search(r"([0-9]+) dofs", first).group(1))
    return seconds, dofs


def run_getfem(mesh, steps, save, refine, out):
    subprocess.run(["/usr/bin/python3",
                    os.path.join(HERE, "getfem_multi_body.py"),
                    "--mesh", mesh, "--steps", str(steps), "--save",
                    str(save), "--refine", str(refine), "--out", out],
                   check=True, stdout=subprocess.DEVNULL)
    data = np.load(out)
    return float(data["seconds"]), int(data["dofs"])


def glissade_displacements(out, bodies, step):
    """Every node's displacement in body order, from the VTU files of
    increment `step` (deal.II writes each cell's vertices at their
    reference coordinates: matched to the nodes by position)."""
    result = []
    for k, body in enumerate(bodies):
        candidates = [f for f in os.listdir(out)
                      if f.startswith(f"body{k}") and f.endswith(".vtu")
                      and re.search(rf"[-_.]0*{step}\.vtu$", f)]
        if len(candidates) != 1:
            sys.exit(f"{out}: no single VTU of body{k} at increment {step} "
                     f"({candidates})")
        arrays = vtu_arrays(os.path.join(out, candidates[0]))
        points = np.array(arrays["Points"]).reshape(-1, 3)[:, :2]
        u = np.array(arrays["displacement"]).reshape(len(points), -1)[:, :2]
        # (the VTU's points are single precision: the nearest one)
        distance, nearest = cKDTree(points).query(body.points)
        if distance.max() > 1e-6:
            sys.exit(f"{candidates[0]}: a node of body{k} is not among the "
                     f"VTU's points ({distance.max():.2e} away)")
        result.append(u[nearest])
    return np.vstack(result)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mesh", required=True)
    parser.add_argument("--glissade",
                        default=os.path.join(ROOT, "build", "glissade"))
    parser.add_argument("--steps", type=int, default=250)
    parser.add_argument("--save", type=int, default=25)
    parser.add_argument("--repeats", type=int, default=1)
    parser.add_argument("--codes", default="glissade,getfem")
    parser.add_argument("--self-contact", action="store_true")
    parser.add_argument("--refine", type=int, default=0,
                        help="each quadrilateral cut into 4^REFINE in both "
                        "codes")
    parser.add_argument("--passes", default="one", choices=["one", "two"],
                        help="glissade's Automatic contact/Passes")
    parser.add_argument("--work", default="/tmp/glissade-multi-body")
    parser.add_argument("--plot", default="",
                        help="a PNG of both codes' bodies at the last "
                        "saved step that both reached (GetFEM's converged)")
    args = parser.parse_args()

    os.makedirs(args.work, exist_ok=True)
    bodies = multi_body_mesh.multi_body_quads(args.mesh, args.refine)
    prm = write_glissade_scene(bodies, args.work, args.steps, args.save,
                               args.self_contact, args.passes)
    codes = args.codes.split(",")
    times = {c: [] for c in codes}
    dofs = {}
    for r in range(args.repeats):
        for code in (codes if r % 2 == 0 else codes[::-1]):
            if code == "glissade":
                t, n = run_glissade(args.glissade, prm,
                                    os.path.join(args.work, "glissade"))
            else:
                t, n = run_getfem(args.mesh, args.steps, args.save,
                                  args.refine,
                                  os.path.join(args.work, "getfem.npz"))
            times[code].append(t)
            dofs[code] = n
            print(f"round {r + 1}: {code} {t:.2f} s ({n} dofs)", flush=True)
    if len(codes) == 2:
        compare(args, bodies)
        if args.plot:
            print(f"picture: {args.plot}")
        medians = {c: statistics.median(times[c]) for c in codes}
        print(f"time: glissade {medians['glissade']:.2f} s, GetFEM "
              f"{medians['getfem']:.2f} s, ratio glissade / GetFEM "
              f"{medians['glissade'] / medians['getfem']:.3f}")


def compare(args, bodies):
    """The two runs' figures at every saved step (module docstring)."""
    getfem = np.load(os.path.join(args.work, "getfem.npz"))
    out = os.path.join(args.work, "glissade")
    with open(os.path.join(out, "history.csv")) as f:
        history = {int(round(float(r["time"]))): r for r in csv.DictReader(f)}
    unconverged = set(int(s) for s in getfem["unconverged"]) \
        if "unconverged" in getfem else \
        set(int(k) + 1 for k in np.nonzero(getfem["iterations"] >= 50)[0])
    sizes = [np.ptp(b.points, axis=0).max() for b in bodies]
    counts = np.cumsum([0] + [len(b.points) for b in bodies])
    areas = np.array([b.area() for b in bodies])
    drawn = None
    print("step   force    bowl's force up: GetFEM  glissade  (its "
          "balance)  | mean displacement: largest difference / body size "
          "(body) | nodes: largest difference / largest displacement")
    for i, step in enumerate(getfem["steps"]):
        step = int(step)
        if step not in history:
            print(f"{step:4d}  glissade stopped before this step")
            continue
        ug = getfem["displacement"][i].T
        ul = glissade_displacements(out, bodies, step)
        force = getfem["force"][step - 1]
        mean_g = np.array([ug[counts[k]:counts[k + 1]].mean(0)
                           for k in range(len(bodies))])
        mean_l = np.array([ul[counts[k]:counts[k + 1]].mean(0)
                           for k in range(len(bodies))])
        relative = np.linalg.norm(mean_g - mean_l, axis=1) / sizes
        worst = int(np.argmax(relative))
        nodal = np.abs(ug - ul).max() / np.abs(ug).max()
        # glissade's balance, as GetFEM's: the integral of 0.1 u_y plus the
        # body force's
        balance = FOUNDATION * integral(bodies, ul)[1] + force * areas.sum()
        flag = "  (GetFEM not converged)" if step in unconverged else ""
        if not flag:
            drawn = (step, ug, ul)
        print(f"{step:4d}  {force:.5f}  {getfem['bowl'][step - 1][1]:.6f}  "
              f"{float(history[step]['bowl_Fy']):.6f}  ({balance:.6f})  | "
              f"{relative.max():.2e} (body{worst})  |  {nodal:.2e}{flag}")
    if args.plot and drawn:
        plot_bodies(args.plot, bodies, *drawn)


def integral(bodies, u):
    """The integral of the bilinear field u (nodal values, body order) over
    the bodies' quadrilaterals, 2 x 2 Gauss points (exact)."""
    g = 0.5 / np.sqrt(3.)
    points = [(0.5 + a, 0.5 + b) for a in (-g, g) for b in (-g, g)]
    total, offset = np.zeros(2), 0
    for body in bodies:
        x = body.points[body.quads]                  # quads x 4 x 2
        v = u[offset:offset + len(body.points)][body.quads]
        for xi, eta in points:
            N = np.array([(1 - xi) * (1 - eta), xi * (1 - eta), xi * eta,
                          (1 - xi) * eta])
            dxi = np.array([-(1 - eta), 1 - eta, eta, -eta])
            deta = np.array([-(1 - xi), -xi, xi, 1 - xi])
            J = np.stack([np.einsum("k,qkd->qd", dxi, x),
                          np.einsum("k,qkd->qd", deta, x)], axis=1)
            det = J[:, 0, 0] * J[:, 1, 1] - J[:, 0, 1] * J[:, 1, 0]
            total += 0.25 * np.einsum("q,k,qkd->d", det, N, v)
        offset += len(body.points)
    return total


def plot_bodies(path, bodies, step, ug, ul):
    """Every body's boundary, deformed, in both codes, and the bowl."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 7))
    phi = np.linspace(np.pi, 2 * np.pi, 200)
    ax.plot(2 * np.cos(phi), 1 + 2 * np.sin(phi), "k-", lw=1.5)
    offset = 0
    for k, body in enumerate(bodies):
        for u, style, label in ((ug, "r-", "GetFEM"),
                                (ul, "b--", "glissade")):
            x = body.points + u[offset:offset + len(body.points)]
            for j, (a, b) in enumerate(body.boundary):
                ax.plot(x[[a, b], 0], x[[a, b], 1], style, lw=0.8,
                        label=label if k == 0 and j == 0 else None)
        offset += len(body.points)
    ax.set_aspect("equal")
    ax.set_xlim(-1.3, 1.3)
    ax.set_ylim(-1.1, 0.7)
    ax.legend(loc="upper right")
    ax.set_title(f"GetFEM's multi-body demo on the same quadrilaterals, "
                 f"step {step}")
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)


if __name__ == "__main__":
    main()
