"""Case 3 (figs 26-27): spread of the contact forces per increment, the
distribution at the worst increment, and the force on node (1.25, 0)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402

directory = sys.argv[1]
rows = list(csv.DictReader(open(f"{directory}/case3_spread.csv")))
worst = list(csv.DictReader(open(f"{directory}/case3_worst.csv")))
variants = list(dict.fromkeys(r["variant"] for r in rows))
names = {"q4": "Q4", "bspline": "Q4 + B-spline", "hermite": "Hermite (40)"}
for v in variants:
    if v.startswith("hermite") and v not in names:
        names[v] = f"Hermite ({v[len('hermite'):]})"
fig, axes = plt.subplots(1, 3, figsize=(15, 3.8))
for v in variants:
    pts = [r for r in rows if r["variant"] == v]
    axes[0].semilogy([int(r["increment"]) for r in pts if int(r["increment"]) > 10],
                     [max(float(r["spread_percent"]), 1e-12) for r in pts
                      if int(r["increment"]) > 10], label=names[v])
    axes[1].plot([float(r["deviation_percent"]) for r in worst if r["variant"] == v],
                 marker=".", label=names[v])
    axes[2].plot([int(r["increment"]) for r in pts],
                 [float(r["node_force"]) for r in pts], label=names[v])
axes[0].set_title("spread around F_e per increment (%)")
axes[0].set_xlabel("increment")
axes[1].set_title("worst increment: (|f| - F_e) / F_e (%) (fig 26)")
axes[1].set_xlabel("interface node")
axes[2].set_title("contact force on node (1.25, 0) (fig 27)")
axes[2].set_xlabel("increment")
for ax in axes:
    ax.legend()
fig.tight_layout()
save_atomically(fig, f"{directory}/case3.png", dpi=110)
print(f"wrote {directory}/case3.png")
