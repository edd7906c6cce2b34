"""The pictures of any scene (Output/Plots = true), drawn from the files the
run wrote into its output directory:

- history.png: every column of history.csv against the time t, one panel
  per quantity, and the Newton iterations per increment;
- contact-<pair>-pressure.png: the contact pressure along each pair's
  slave boundary (against the arc length of the reference boundary) at up
  to six written increments, from contact-<pair>-NNNNN.csv and the order
  of the nodes along the boundary in contact-<pair>-NNNNN.vtu;
- curves.png: the curves of Output/Plot curves, "x:y" arguments after
  the directory, each a pair of history.csv columns (or time);
- deformed-mesh.png: every body in its last written state, deformed at
  true scale and coloured by the von Mises stress (one colour scale for
  all bodies), over the reference outline, from the <body>.pvd files, and
  the rigid obstacles in their final place (obstacle-<pair>.csv);
- coating-<pair>.png: an abradable coating's worn depth round the casing
  (in its own frame) after each revolution and at the end, from
  coating-<pair>.csv.

Run by glissade with Debian's /usr/bin/python3 (matplotlib); by hand:
/usr/bin/python3 scripts/plot_scene.py <output directory>."""
import csv
import glob
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from atomic_png import save_atomically  # noqa: E402
from vtu_reader import vtu_arrays  # noqa: E402

directory = sys.argv[1]
curves = [tuple(a.split(":", 1)) for a in sys.argv[2:]]


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def plot_history():
    path = os.path.join(directory, "history.csv")
    if not os.path.exists(path):
        return
    rows = read_csv(path)
    if len(rows) < 2:
        return
    columns = [c for c in rows[0] if c not in ("increment", "time", "newton_iterations")]
    t = [number(r["time"]) for r in rows]
    panels = len(columns) + 1
    per_row = 3 if panels > 4 else 2 if panels > 1 else 1
    n_rows = math.ceil(panels / per_row)
    fig, axes = plt.subplots(n_rows, per_row, figsize=(4.2 * per_row, 3.0 * n_rows),
                             squeeze=False)
    flat = [a for row in axes for a in row]
    for axis, column in zip(flat, columns):
        axis.plot(t, [number(r[column]) for r in rows], marker=".", markersize=3)
        axis.set_title(column, fontsize=9)
        axis.set_xlabel("t")
        axis.grid(alpha=0.3)
    axis = flat[len(columns)]
    axis.bar([int(r["increment"]) for r in rows[1:]],
             [int(number(r["newton_iterations"])) for r in rows[1:]], width=0.8)
    axis.set_title("Newton iterations per increment", fontsize=9)
    axis.set_xlabel("increment")
    for axis in flat[panels:]:
        axis.set_visible(False)
    fig.tight_layout()
    save_atomically(fig, os.path.join(directory, "history.png"), dpi=110)
    plt.close(fig)


def boundary_order(vtu_path, n):
    """The nodes in order along the boundary, from the VTU's line cells."""
    with open(vtu_path) as f:
        text = f.read()
    match = re.search(r'Name="connectivity"[^>]*>(.*?)</DataArray>', text, re.S)
    if not match:
        return list(range(n))
    values = [int(v) for v in match.group(1).split()]
    neighbours = {k: [] for k in range(n)}
    for a, b in zip(values[0::2], values[1::2]):
        neighbours[a].append(b)
        neighbours[b].append(a)
    # Start at an end of the chain (or anywhere on a closed one).
    start = next((k for k in range(n) if len(neighbours[k]) == 1), 0)
    order, seen = [start], {start}
    while True:
        following = [k for k in neighbours[order[-1]] if k not in seen]
        if not following:
            break
        order.append(following[0])
        seen.add(following[0])
    order += [k for k in range(n) if k not in seen]
    return order


def plot_pressure(pair):
    tables = sorted(glob.glob(os.path.join(directory, f"contact-{glob.escape(pair)}-[0-9]*.csv")))
    if not tables:
        return
    # Up to six increments, evenly spread, the last one always.
    if len(tables) > 6:
        step = (len(tables) - 1) / 5
        tables = [tables[round(i * step)] for i in range(6)]
    fig, axis = plt.subplots(figsize=(6.4, 3.8))
    for path in tables:
        rows = read_csv(path)
        if "pressure" not in rows[0]:
            continue
        order = boundary_order(path[:-4] + ".vtu", len(rows))
        s, arc, previous = [], 0.0, None
        for k in order:
            X = (number(rows[k]["X"]), number(rows[k]["Y"]))
            if previous is not None:
                arc += math.dist(X, previous)
            previous = X
            s.append(arc)
        increment = int(re.search(r"-(\d+)\.csv$", path).group(1))
        axis.plot(s, [number(rows[k]["pressure"]) for k in order], marker=".",
                  markersize=3, label=f"increment {increment}")
    axis.set_xlabel("arc length along the slave boundary (reference)")
    axis.set_ylabel("contact pressure")
    axis.set_title(f"pair '{pair}'")
    axis.grid(alpha=0.3)
    axis.legend(fontsize=8)
    fig.tight_layout()
    save_atomically(fig, os.path.join(directory, f"contact-{pair}-pressure.png"), dpi=110)
    plt.close(fig)


def plot_curves():
    """curves.png: one panel per (x, y) pair of history columns."""
    path = os.path.join(directory, "history.csv")
    if not curves or not os.path.exists(path):
        return
    rows = read_csv(path)
    per_row = min(len(curves), 3)
    n_rows = math.ceil(len(curves) / per_row)
    fig, axes = plt.subplots(n_rows, per_row, figsize=(4.2 * per_row, 3.4 * n_rows),
                             squeeze=False)
    flat = [a for row in axes for a in row]
    for axis, (x, y) in zip(flat, curves):
        if rows and x in rows[0] and y in rows[0]:
            axis.plot([number(r[x]) for r in rows], [number(r[y]) for r in rows],
                      marker=".", markersize=3)
        axis.set_xlabel(x)
        axis.set_ylabel(y)
        axis.grid(alpha=0.3)
    for axis in flat[len(curves):]:
        axis.set_visible(False)
    fig.tight_layout()
    save_atomically(fig, os.path.join(directory, "curves.png"), dpi=110)
    plt.close(fig)


def last_dataset(pvd_path):
    with open(pvd_path) as f:
        files = re.findall(r'file="([^"]+)"', f.read())
    return os.path.join(os.path.dirname(pvd_path), files[-1]) if files else None


def plot_deformed_mesh():
    """deformed-mesh.png: each body's last written state, von Mises colour."""
    bodies = []
    for pvd in sorted(glob.glob(os.path.join(directory, "*.pvd"))):
        name = os.path.basename(pvd)[:-4]
        if name.startswith("contact-"):
            continue
        vtu = last_dataset(pvd)
        if vtu is None or not os.path.exists(vtu):
            continue
        a = vtu_arrays(vtu)
        if not {"Points", "connectivity", "offsets", "displacement",
                "von_Mises"} <= a.keys():
            print(f"plot_scene.py: deformed-mesh.png leaves out {name}: "
                  f"{os.path.basename(vtu)} holds no displacement and "
                  "von_Mises (Output/VTU fields = displacement, stress)")
            continue
        X, u = a["Points"], a["displacement"]
        reference = [(X[3 * i], X[3 * i + 1]) for i in range(len(X) // 3)]
        current = [(x + u[3 * i], y + u[3 * i + 1]) for i, (x, y) in enumerate(reference)]
        cells, start = [], 0
        for end in a["offsets"]:
            cells.append([int(k) for k in a["connectivity"][start:int(end)]])
            start = int(end)
        # deal.II's quadrilateral patches list their corners as
        # (0, 0), (1, 0), (1, 1), (0, 1): a polygon in that order.
        stress = [sum(a["von_Mises"][k] for k in c) / len(c) for c in cells]
        increment = re.search(r"-(\d+)\.vtu$", vtu)
        bodies.append((name, reference, current, cells, stress,
                       int(increment.group(1)) if increment else None))
    if not bodies:
        return
    highest = max(max(b[4]) for b in bodies)
    fig, axis = plt.subplots(figsize=(6.4, 5.2))
    collection = None
    for name, reference, current, cells, stress, increment in bodies:
        axis.add_collection(PolyCollection(
            [[reference[k] for k in c] for c in cells], facecolors="none",
            edgecolors="0.75", linewidths=0.3))
        collection = PolyCollection(
            [[current[k] for k in c] for c in cells], array=stress,
            cmap="viridis", edgecolors="k", linewidths=0.15)
        collection.set_clim(0.0, highest if highest > 0 else 1.0)
        axis.add_collection(collection)
    # The rigid obstacles the run wrote (obstacle-<pair>.csv), in their
    # final place, as thick grey curves.
    for path in sorted(glob.glob(os.path.join(directory, "obstacle-*.csv"))):
        rows = read_csv(path)
        axis.plot([float(r["x"]) for r in rows], [float(r["y"]) for r in rows],
                  color="0.35", linewidth=2.0, solid_capstyle="butt",
                  label=os.path.basename(path)[9:-4])
    points = [p for b in bodies for p in b[1] + b[2]]
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    margin = 0.03 * max(max(xs) - min(xs), max(ys) - min(ys))
    axis.set_xlim(min(xs) - margin, max(xs) + margin)
    axis.set_ylim(min(ys) - margin, max(ys) + margin)
    axis.set_aspect("equal")
    fig.colorbar(collection, ax=axis, label="von Mises stress", shrink=0.8)
    increments = sorted({b[5] for b in bodies if b[5] is not None})
    axis.set_title("deformed (true scale), reference in grey" +
                   (f"; increment {increments[-1]}" if increments else ""),
                   fontsize=9)
    fig.tight_layout()
    save_atomically(fig, os.path.join(directory, "deformed-mesh.png"), dpi=110)
    plt.close(fig)


def plot_coating(path):
    """coating-<pair>.png: the worn depth against the casing's angle, one
    curve per revolution recorded (the last one darkest)."""
    rows = read_csv(path)
    if not rows:
        return
    by_revolution = {}
    for r in rows:
        key = (int(r["revolution"]), number(r["time"]))
        by_revolution.setdefault(key, []).append(
            (number(r["angle"]), number(r["worn_depth"])))
    fig, axis = plt.subplots(figsize=(7, 3.4))
    keys = sorted(by_revolution)
    for i, key in enumerate(keys):
        points = by_revolution[key]
        shade = 0.25 + 0.75 * (i + 1) / len(keys)
        axis.plot([p[0] for p in points], [p[1] for p in points],
                  color=(0.1, 0.2, 0.6, shade), linewidth=1,
                  label=f"revolution {key[0]} (t = {key[1]:.4g})"
                  if i >= len(keys) - 4 else None)
    axis.set_xlabel("angle in the casing's frame (degrees)")
    axis.set_ylabel("worn depth")
    axis.set_xlim(0, 360)
    axis.grid(alpha=0.3)
    axis.legend(fontsize=7)
    name = os.path.basename(path)[:-len(".csv")]
    axis.set_title(f"{name}: the abradable coating's wear", fontsize=9)
    fig.tight_layout()
    save_atomically(fig, os.path.join(directory, name + ".png"), dpi=110)
    plt.close(fig)


plot_history()
plot_curves()
for coating_path in sorted(glob.glob(os.path.join(directory, "coating-*.csv"))):
    plot_coating(coating_path)
pairs = set()
for path in glob.glob(os.path.join(directory, "contact-*.pvd")):
    pairs.add(os.path.basename(path)[len("contact-"):-len(".pvd")])
for pair in sorted(pairs):
    plot_pressure(pair)
plot_deformed_mesh()
