#!/usr/bin/python3
"""The ironing study (doc/studies/ironing.md): prm/ironing.prm run with
each contact discretisation, the forces on the die over the slide written
as one CSV and one PNG, and each variant's oscillation of the forces over
the steady slide (t in [2.5, 6.5]) about their slow trend (a quadratic in
t, least squares), in % of their mean: the largest departure and the
total variation of the departure (the sum of its changes from increment
to increment), and the run's wall time.

    /usr/bin/python3 benchmarks/ironing/run_ironing.py [--glissade build/glissade]
        [--output output/ironing_study]

A variant that stops (node-to-segment on the faceted master does, at
t = 1.1) is drawn up to where it stopped and said so.
"""
import argparse
import csv
import os
import subprocess
import sys
import time

import numpy as np

VARIANTS = [
    ("mortar", ["Contact ironing/Discretisation=mortar"]),
    ("mortar, B-spline", ["Contact ironing/Discretisation=mortar",
                          "Contact ironing/Surface=bspline"]),
    # The slab isogeometric (NURBS of degree 2, 70 x 10 elements): the
    # master is its exact top, mortar integrating over it.
    ("mortar, NURBS slab", ["Contact ironing/Discretisation=mortar",
                            "Contact ironing/Surface=nurbs",
                            "Body slab/Element/Space=nurbs",
                            "Body slab/Element/Degree=2"]),
    # Both bodies isogeometric (prm/ironing_nurbs.prm): the die one NURBS
    # patch of degree 2 with its arc exact, the slave side its arc with
    # mortar on its own functions, the slab's exact top the master.
    ("mortar, NURBS die and slab", [], "ironing_nurbs.prm"),
    ("node-to-segment, B-spline",
     ["Contact ironing/Discretisation=node-to-segment",
      "Contact ironing/Surface=bspline"]),
    ("node-to-segment, faceted",
     ["Contact ironing/Discretisation=node-to-segment",
      "Contact ironing/Surface=faceted"]),
]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(os.path.dirname(here))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--glissade", default=os.path.join(root, "build", "glissade"))
    parser.add_argument("--output", default="output/ironing_study")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)

    rows, table = [], []
    for k, (label, sets, *scene) in enumerate(VARIANTS):
        directory = os.path.join(args.output, label.replace(", ", "_").replace(" ", "-"))
        command = [args.glissade,
                   os.path.join(root, "prm", scene[0] if scene else "ironing.prm"),
                   "--set", "Output/Directory=" + directory,
                   "--set", "Output/VTU interval=0",
                   "--set", "Output/Contact table interval=0"]
        for s in sets:
            command += ["--set", s]
        print(f"[{k + 1}/{len(VARIANTS)}] {label} ...", flush=True)
        start = time.time()
        finished = subprocess.run(command, stdout=subprocess.DEVNULL,
                                  stderr=subprocess.PIPE, text=True)
        wall = time.time() - start
        history = list(csv.DictReader(open(os.path.join(directory, "history.csv"))))
        t = np.array([float(r["time"]) for r in history])
        normal = -np.array([float(r["die_Ry_top"]) for r in history])
        tangential = np.array([float(r["die_Rx_top"]) for r in history])
        for r, n, f in zip(history, normal, tangential):
            rows.append([label, r["time"], n, f])
        stopped = finished.returncode != 0
        steady = t >= 2.5 - 1e-9
        figures = [label, t[-1], "stopped" if stopped else "completed", wall]
        if steady.sum() > 10:
            for force in (normal, tangential):
                trend = np.polyval(np.polyfit(t[steady], force[steady], 2), t[steady])
                mean = force[steady].mean()
                departure = force[steady] - trend
                figures += [mean, 100 * np.abs(departure).max() / mean,
                            100 * np.abs(np.diff(departure)).sum() / mean]
        else:
            figures += [float("nan")] * 6
        table.append(figures)

    with open(os.path.join(args.output, "ironing_forces.csv"), "w") as out:
        out.write("variant,time,normal_force,tangential_force\n")
        for r in rows:
            out.write(f"{r[0]},{r[1]},{r[2]:.12g},{r[3]:.12g}\n")

    print("\nIroning, forces on the die over the steady slide (t in [2.5, 6.5])")
    print(f"{'variant':>28} {'last t':>7} {'run':>10} {'wall s':>7} {'normal':>9} "
          f"{'osc. %':>7} {'TV %':>7} {'tangential':>10} {'osc. %':>7} {'TV %':>7}")
    for f in table:
        print(f"{f[0]:>28} {f[1]:7.3f} {f[2]:>10} {f[3]:7.1f} {f[4]:9.2f} "
              f"{f[5]:7.3f} {f[6]:7.2f} {f[7]:10.2f} {f[8]:7.3f} {f[9]:7.2f}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for label, *_ in VARIANTS:
        mine = [r for r in rows if r[0] == label]
        t = [float(r[1]) for r in mine]
        axes[0].plot(t, [r[2] for r in mine], label=label)
        axes[1].plot(t, [r[3] for r in mine], label=label)
    axes[0].set_ylabel("normal force on the die")
    axes[1].set_ylabel("tangential force on the die")
    axes[1].set_xlabel("t (die moved by x = t, pressed 1 deep at t = 2)")
    axes[0].legend()
    axes[0].set_title("Ironing (mu = 0.5): forces over the slide")
    for a in axes:
        a.grid(alpha=0.3)
    figure.tight_layout()
    png = os.path.join(args.output, "ironing_forces.png")
    figure.savefig(png, dpi=110)
    print("wrote", png, "and", os.path.join(args.output, "ironing_forces.csv"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
