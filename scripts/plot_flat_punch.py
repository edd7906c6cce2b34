"""The flat punches' contact tables against the closed forms:

    build/glissade prm/flat_punch.prm
    build/glissade prm/flat_punch_axisymmetric.prm
    /usr/bin/python3 scripts/plot_flat_punch.py \\
        --plane output_flat_punch [more ...] \\
        --axisymmetric output_flat_punch_axisymmetric [more ...] \\
        [--png flat_punch.png]

Left, each plane run's pressure (r_n over the node's tributary length) over
Sadowsky's P / (pi sqrt(a^2 - x^2)); right, each axisymmetric run's
(r_n over the node's ring area) over Boussinesq's P / (2 pi a sqrt(a^2 -
r^2)): both divided by the mean pressure, P the normal reactions' sum (for
the full turn in the axisymmetric one), a = 1. The last table of each
directory; a directory's name is its label. Prints each run's largest
difference within a / 2.
"""
import argparse
import csv
import glob
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402

A = 1.0

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("--plane", nargs="*", default=[])
parser.add_argument("--axisymmetric", nargs="*", default=[])
parser.add_argument("--png", default="flat_punch.png")
args = parser.parse_args()


def last_table(directory):
    tables = sorted(glob.glob(os.path.join(directory, "contact-*.csv")))
    if not tables:
        raise SystemExit(f"{directory}: no contact table (contact-*.csv)")
    return [r for r in csv.DictReader(open(tables[-1]))
            if r["active"] == "1"]


def sadowsky(x):
    """Pressure over the mean pressure P / (2 a)."""
    return 2 * A / (math.pi * math.sqrt(A * A - x * x))


def boussinesq(r):
    """Pressure over the mean pressure P / (pi a^2)."""
    return A / (2 * math.sqrt(A * A - r * r))


fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
for ax, runs, closed_form, mean, name in (
        (axes[0], args.plane, sadowsky, lambda P: P / (2 * A),
         "plane strain, Sadowsky"),
        (axes[1], args.axisymmetric, boussinesq,
         lambda P: P / (math.pi * A * A), "axisymmetric, Boussinesq")):
    xs = [-0.999 + 1.998 * k / 400 for k in range(401)]
    if closed_form is boussinesq:
        xs = [x for x in xs if x >= 0]
    ax.plot(xs, [closed_form(x) for x in xs], "k-", lw=1, label=name)
    for marker, directory in zip("oxs^v+", runs):
        rows = last_table(directory)
        P = sum(float(r["r_n"]) for r in rows)
        points = sorted((float(r["X"]), float(r["pressure"]) / mean(P))
                        for r in rows)
        ax.plot([x for x, _ in points], [p for _, p in points], marker,
                ms=4, mfc="none", ls="none",
                label=os.path.basename(os.path.normpath(directory)))
        inside = [abs(p / closed_form(x) - 1) for x, p in points
                  if abs(x) <= 0.5 * A]
        print(f"{directory}: {len(points)} closed nodes, within a / 2 the "
              f"pressure within {max(inside):.4f} of {name.split(', ')[1]}'s")
    ax.set_xlabel("x / a" if closed_form is sadowsky else "r / a")
    ax.set_ylabel("pressure / mean pressure")
    ax.set_ylim(0, 4)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()
save_atomically(fig, args.png, dpi=120)
print(f"wrote {args.png}")
