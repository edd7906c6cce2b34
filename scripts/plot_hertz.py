"""The contact pressure of an axisymmetric (or plane) contact table against
Hertz's profile p0 sqrt(1 - r^2 / a^2), with Hertz's a and p0 taken at the
load the table carries:

    /usr/bin/python3 scripts/plot_hertz.py contact-<pair>-<n>.csv \\
        --modulus E* --radius R* [--png hertz.png]

E* and R* are the reduced modulus and radius (a sphere of E, nu on a rigid
flat: E / (1 - nu^2) and R). The load is the sum of the active nodes' f_y
(for the full turn). Prints a and p0 measured and Hertz's: a from the
second moment of the nodal forces (sum f r^2 = (2 / 5) a^2 P), p0 the
pressure of the node on the axis (x = 0).
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("table")
parser.add_argument("--modulus", type=float, required=True)
parser.add_argument("--radius", type=float, required=True)
parser.add_argument("--png", default="hertz.png")
args = parser.parse_args()

rows = [r for r in csv.DictReader(open(args.table))
        if r["active"] == "1" and float(r["r_n"]) > 0]
r = [float(row["x"]) for row in rows]
f = [float(row["fy"]) for row in rows]
p = [float(row["pressure"]) for row in rows]
P = sum(f)
a = math.sqrt(2.5 * sum(fk * rk * rk for fk, rk in zip(f, r)) / P)
a_hertz = (3 * P * args.radius / (4 * args.modulus)) ** (1 / 3)
p0_hertz = 3 * P / (2 * math.pi * a_hertz ** 2)
p0 = next(pk for pk, row in zip(p, rows) if float(row["X"]) == 0.0)
print(f"P = {P:.6g}: a = {a:.6g} (Hertz {a_hertz:.6g}, {a / a_hertz - 1:+.2%}), "
      f"p0 = {p0:.6g} (Hertz {p0_hertz:.6g}, {p0 / p0_hertz - 1:+.2%})")

fig, ax = plt.subplots(figsize=(6.5, 4))
s = [i / 200 * 1.2 for i in range(201)]
ax.plot(s, [math.sqrt(max(0.0, 1 - x * x)) for x in s], "k-",
        label="Hertz: p0 sqrt(1 - r^2 / a^2)")
ax.plot([rk / a_hertz for rk in r], [pk / p0_hertz for pk in p], "o",
        markersize=4, label="glissade, each slave node")
ax.set_xlabel("r / a (Hertz's a at the load)")
ax.set_ylabel("p / p0")
ax.set_xlim(0, 1.2)
ax.set_title(f"P = {P:.4g}: a {a / a_hertz - 1:+.2%}, p0 {p0 / p0_hertz - 1:+.2%} from Hertz")
ax.grid(alpha=0.3)
ax.legend()
fig.tight_layout()
save_atomically(fig, args.png, dpi=100)
print(f"wrote {args.png}")
