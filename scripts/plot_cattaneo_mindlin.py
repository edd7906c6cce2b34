"""The shear of prm/cattaneo_mindlin.prm's contact tables against Cattaneo
and Mindlin's partial slip, at several tangential loads:

    build/glissade prm/cattaneo_mindlin.prm
    /usr/bin/python3 scripts/plot_cattaneo_mindlin.py cattaneo_mindlin \\
        [--png cattaneo_mindlin.png] [--increments 12,16,20]

For each table it takes the loads the contact carries (P = sum f_y,
Q = -sum f_x over the closed nodes), Hertz's a and p0 at P (plane strain,
two bodies of E = 200, nu = 0.3: E* = E / (2 (1 - nu^2)), R = 1) and
Cattaneo's c = a sqrt(1 - Q / (mu P)), and plots each closed node's shear
(r_t over its tributary length, counted against the pull), sticking and
slipping nodes apart, beside the closed form; x from the centre of the
normal reactions. Prints c against the stick zone's edges.
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402

MU, E, NU, R = 0.3, 200.0, 0.3, 1.0
E_STAR = E / (2 * (1 - NU * NU))

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("directory", help="the scene's output directory")
parser.add_argument("--png", default="cattaneo_mindlin.png")
parser.add_argument("--increments", default="12,16,20")
args = parser.parse_args()


def closed_form(x, a, p0, c):
    """Cattaneo's shear at x (from the centre)."""
    q = MU * p0 * math.sqrt(max(0.0, 1 - x * x / (a * a)))
    if abs(x) < c:
        q -= MU * p0 * c / a * math.sqrt(1 - x * x / (c * c))
    return q


fig, ax = plt.subplots(figsize=(7, 4.5))
colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
for colour, increment in zip(colours, args.increments.split(",")):
    table = os.path.join(args.directory,
                         f"contact-touch-{int(increment):05d}.csv")
    rows = [r for r in csv.DictReader(open(table))
            if r["status"] in ("stick", "slip")]
    P = sum(float(r["fy"]) for r in rows)
    Q = -sum(float(r["fx"]) for r in rows)
    centre = (sum(float(r["r_n"]) * float(r["x"]) for r in rows)
              / sum(float(r["r_n"]) for r in rows))
    a = math.sqrt(4 * P * R / (math.pi * E_STAR))
    p0 = 2 * P / (math.pi * a)
    c = a * math.sqrt(max(0.0, 1 - Q / (MU * P)))
    points = sorted((float(r["x"]) - centre, abs(float(r["shear"])),
                     r["status"]) for r in rows)
    stick = [x for x, _, s in points if s == "stick"]
    print(f"increment {increment}: Q / (mu P) = {Q / (MU * P):.3f}, "
          f"c / a = {c / a:.3f}; sticking nodes from {min(stick) / a:.3f} "
          f"to {max(stick) / a:.3f} (x / a)")
    s = [i / 200 * 1.2 - 0.6 for i in range(201)]
    label = f"Q / (mu P) = {Q / (MU * P):.2f}"
    ax.plot([x * 2 for x in s],
            [closed_form(x * 2 * a, a, p0, c) / (MU * p0) for x in s],
            "-", color=colour, label=label)
    for status, marker in (("stick", "o"), ("slip", "x")):
        ax.plot([x / a for x, _, st in points if st == status],
                [q / (MU * p0) for _, q, st in points if st == status],
                marker, color=colour, markersize=4, linestyle="none")
for status, marker in (("stick", "o"), ("slip", "x")):
    ax.plot([], [], marker, color="grey", linestyle="none",
            label=f"glissade, a node that {status}s")
ax.set_xlabel("x / a (from the contact's centre)")
ax.set_ylabel("shear / (mu p0)")
ax.set_xlim(-1.2, 1.2)
ax.set_title("A cylinder pressed on a block, then pulled: partial slip\n"
             "(lines: Cattaneo-Mindlin at the load the contact carries)")
ax.grid(alpha=0.3)
ax.set_ylim(-0.2, 1.0)
ax.legend(fontsize=7, ncol=3, loc="lower center")
fig.tight_layout()
save_atomically(fig, args.png, dpi=100)
print(f"wrote {args.png}")
