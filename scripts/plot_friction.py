"""Friction study: the normal and tangential contact forces per increment
for every master and friction coefficient, and the stick-slip pattern of
each run (the status of every slave node at every increment)."""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from atomic_png import save_atomically  # noqa: E402

directory = sys.argv[1]
history = list(csv.DictReader(open(f"{directory}/friction_history.csv")))
statuses = list(csv.DictReader(open(f"{directory}/friction_status.csv")))
nodes = list(csv.DictReader(open(f"{directory}/friction_nodes.csv")))
runs = list(dict.fromkeys((r["variant"], r["friction"]) for r in history))
names = {"q4": "Q4", "bspline": "B-spline", "hermite": "Hermite",
         "mortar": "mortar"}

# Forces: sum r_n and sum r_t against time, one colour per master, one
# line style per friction coefficient.
colours = {"q4": "tab:blue", "bspline": "tab:orange", "hermite": "tab:green",
           "mortar": "tab:red"}
styles = ["-", "--", ":", "-."]
coefficients = list(dict.fromkeys(mu for _, mu in runs))
fig, axes = plt.subplots(1, 3, figsize=(15, 4))
for variant, mu in runs:
    rows = [r for r in history if (r["variant"], r["friction"]) == (variant, mu)]
    t = [float(r["time"]) for r in rows]
    n = [float(r["normal_force"]) for r in rows]
    tt = [float(r["tangential_force"]) for r in rows]
    style = dict(color=colours.get(variant, "k"),
                 linestyle=styles[coefficients.index(mu) % len(styles)],
                 label=f"{names.get(variant, variant)}, mu = {mu}")
    axes[0].plot(t, n, **style)
    axes[1].plot(t, tt, **style)
    axes[2].plot(t, [int(r["sticking"]) for r in rows], **style)
axes[0].set_title("sum of the normal contact forces r_n (N)")
axes[1].set_title("sum of |r_t|, the tangential contact forces (N)")
axes[2].set_title("sticking slave nodes")
for ax in axes:
    ax.set_xlabel("load time t")
    ax.grid(alpha=0.3)
axes[0].legend(fontsize=7)
fig.tight_layout()
save_atomically(fig, f"{directory}/friction_forces.png", dpi=110)
print(f"wrote {directory}/friction_forces.png")

# The stick-slip pattern: slave nodes ordered along the interface (by angle
# about their centroid if they go round it, else along their main
# direction), increments across.
def along_interface(members):
    """The nodes of one pair in their order along the interface: by angle
    about their centroid if they go round it, else along their main
    direction."""
    x = [float(nodes[k]["x"]) for k in members]
    y = [float(nodes[k]["y"]) for k in members]
    cx, cy = sum(x) / len(x), sum(y) / len(y)
    angles = [math.atan2(b - cy, a - cx) for a, b in zip(x, y)]
    sxx = sum((a - cx) ** 2 for a in x)
    syy = sum((b - cy) ** 2 for b in y)
    if max(angles) - min(angles) > 1.5 * math.pi and min(sxx, syy) > 0.1 * max(sxx, syy):
        key = angles
    else:
        key = x if sxx > syy else y
    return [members[i] for i in sorted(range(len(members)), key=lambda i: key[i])]


pairs = list(dict.fromkeys(r["pair"] for r in nodes))
order, boundaries = [], []
for pair in pairs:
    order += along_interface([k for k, r in enumerate(nodes) if r["pair"] == pair])
    boundaries.append(len(order))
label = "slave node along the interface" + (
    " (pairs: " + ", ".join(pairs) + ")" if len(pairs) > 1 else "")
frictional = [run for run in runs if float(run[1]) > 0.]
if frictional:
    columns = min(3, len(frictional))
    lines = (len(frictional) + columns - 1) // columns
    fig, axes = plt.subplots(lines, columns, figsize=(5 * columns, 3.6 * lines),
                             squeeze=False)
    colour_map = ListedColormap(["white", "tab:blue", "tab:red"])
    for ax, (variant, mu) in zip(axes.flat, frictional):
        rows = [r for r in statuses if (r["variant"], r["friction"]) == (variant, mu)]
        code = {"o": 0, "t": 1, "s": 2}
        image = [[code[r["status"][k]] for r in rows] for k in order]
        ax.imshow(image, aspect="auto", interpolation="nearest", origin="lower",
                  cmap=colour_map, vmin=0, vmax=2,
                  extent=(0.5, len(rows) + 0.5, -0.5, len(order) - 0.5))
        ax.set_title(f"{names.get(variant, variant)}, mu = {mu}: "
                     "stick (blue), slip (red), open (white)", fontsize=9)
        for b in boundaries[:-1]:
            ax.axhline(b - 0.5, color="k", linewidth=0.8)
        ax.set_xlabel("increment")
        ax.set_ylabel(label, fontsize=8)
    for ax in list(axes.flat)[len(frictional):]:
        ax.axis("off")
    fig.tight_layout()
    save_atomically(fig, f"{directory}/friction_stick_slip.png", dpi=110)
    print(f"wrote {directory}/friction_stick_slip.png")
