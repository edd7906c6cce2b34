#!/usr/bin/python3
"""What a body that touches the bowl alone carries, in both codes of a
multi_body_race.py run: a check of each code against the frictionless law
rather than against each other.

    /usr/bin/python3 benchmarks/peers/multi_body_corner_check.py \\
        --mesh PATH --work DIR [--refine 0] --body 2 [--steps 25,50]

A body whose only contact is the rigid bowl (the demo's body 2, the
bracket on the bowl's left, until about step 60) is held by the contact
force F = 0.1 * integral(u) - f A (its balance: the zero-order term and the
body force, from the code's own displacements). Frictionless, that force
is normal to the bowl where the body touches it: its angle to the bowl's
normal at the body's deepest point must be zero. Printed for each code:
F, the gaps of the body's boundary nodes closest to the bowl (negative:
inside it) and that angle.
"""

import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import multi_body_mesh  # noqa: E402
import multi_body_race as race  # noqa: E402

BOWL_CENTRE, BOWL_RADIUS = np.array([0., 1.]), 2.


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mesh", required=True)
    parser.add_argument("--work", required=True,
                        help="multi_body_race.py's --work of a run of both "
                        "codes")
    parser.add_argument("--refine", type=int, default=0)
    parser.add_argument("--body", type=int, default=2)
    parser.add_argument("--steps", default="25,50")
    args = parser.parse_args()

    bodies = multi_body_mesh.multi_body_quads(args.mesh, args.refine)
    counts = np.cumsum([0] + [len(b.points) for b in bodies])
    body = bodies[args.body]
    own = slice(counts[args.body], counts[args.body + 1])
    getfem = np.load(os.path.join(args.work, "getfem.npz"))
    boundary = np.unique(body.boundary.ravel())
    for step in (int(s) for s in args.steps.split(",")):
        i = list(getfem["steps"]).index(step)
        load = getfem["force"][step - 1]
        for code, u in (
                ("GetFEM", getfem["displacement"][i].T[own]),
                ("glissade", race.glissade_displacements(
                    os.path.join(args.work, "glissade"), bodies,
                    step)[own])):
            x = body.points + u
            force = race.FOUNDATION * race.integral([body], u) + \
                np.array([0., load * body.area()])
            gaps = BOWL_RADIUS - np.linalg.norm(x[boundary] - BOWL_CENTRE,
                                                axis=1)
            order = np.argsort(gaps)
            deepest = x[boundary[order[0]]]
            normal = BOWL_CENTRE - deepest
            normal /= np.linalg.norm(normal)
            angle = np.degrees(np.arctan2(
                force[0] * normal[1] - force[1] * normal[0], force @ normal))
            print(f"step {step:3d}  {code:8s}  contact force ({force[0]:+.3e}, "
                  f"{force[1]:+.3e})  closest gaps "
                  f"{' '.join(f'{g:+.5f}' for g in gaps[order[:3]])}  "
                  f"angle to the bowl's normal {angle:+.2f} deg")


if __name__ == "__main__":
    main()
