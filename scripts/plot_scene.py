"""The pictures of any scene (Output/Plots = true), drawn from the files the
run wrote into its output directory:

- history.png: every column of history.csv against the time t, one panel
  per quantity, and the Newton iterations per increment;
- contact-<pair>-pressure.png: the contact pressure along each pair's
  slave boundary (against the arc length of the reference boundary) at up
  to six written increments, from contact-<pair>-NNNNN.csv and the order
  of the nodes along the boundary in contact-<pair>-NNNNN.vtu.

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

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from atomic_png import save_atomically  # noqa: E402

directory = sys.argv[1]


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


plot_history()
pairs = set()
for path in glob.glob(os.path.join(directory, "contact-*.pvd")):
    pairs.add(os.path.basename(path)[len("contact-"):-len(".pvd")])
for pair in sorted(pairs):
    plot_pressure(pair)
