"""Figs 9-11 of the paper: the deformed top edge of three elements with a
point force at the middle of each top edge, for Q4, Q8 and Hermite."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402

directory = sys.argv[1]
rows = list(csv.DictReader(open(f"{directory}/top_edges.csv")))
fig, axes = plt.subplots(1, 3, figsize=(13, 3.2), sharey=True)
for ax, (space, title) in zip(axes, [("q1", "Q4"), ("q8", "Q8"),
                                     ("hermite", "Hermite")]):
    pts = [r for r in rows if r["space"] == space]
    for e in range(3):
        seg = pts[21 * e:21 * (e + 1)]
        ax.plot([float(r["x"]) for r in seg], [float(r["y"]) for r in seg],
                lw=1.5)
    for x in (1, 2):
        ax.axvline(x, color="grey", lw=0.5, ls=":")
    ax.set_title(f"{title}: deformed top edge")
    ax.set_xlabel("x")
axes[0].set_ylabel("y")
fig.tight_layout()
save_atomically(fig, f"{directory}/hermite_static_top_edges.png", dpi=110)
print(f"wrote {directory}/hermite_static_top_edges.png")
