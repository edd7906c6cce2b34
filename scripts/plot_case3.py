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
names = {"q4": "Q4", "q4-closest": "Q4, closest point",
         "q4-vertex": "Q4, vertex normal", "bspline": "Q4 + B-spline",
         "hermite": "Hermite (40)"}
for v in variants:
    if v.startswith("hermite") and v not in names:
        names[v] = f"Hermite ({v[len('hermite'):]})"
    names.setdefault(v, v)
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

# Fig 28: the master curve near node (1.25, 0) at increments i1 (the node at
# mid-element) and i2 (the largest Hermite/B-spline difference on it).
try:
    profile = list(csv.DictReader(open(f"{directory}/case3_fig28.csv")))
except FileNotFoundError:
    profile = []
if profile:
    fig, axes = plt.subplots(1, 2, figsize=(12, 4), sharey=True)
    for ax, role in zip(axes, ["i1", "i2"]):
        rows = [r for r in profile if r["role"] == role]
        for v, colour in [("bspline", "tab:orange"), ("hermite", "tab:green")]:
            pts = [r for r in rows if r["variant"] == v]
            ax.plot([float(r["angle"]) for r in pts],
                    [1e3 * (float(r["radius"]) - 1.25) for r in pts],
                    color=colour, label=names.get(v, v))
        lo = min(float(r["angle"]) for r in rows)
        hi = max(float(r["angle"]) for r in rows)
        for k in range(int(lo // 9) - 1, int(hi // 9) + 2):
            if lo <= 9 * k <= hi:
                ax.axvline(9 * k, color="0.85", linewidth=0.8)
        ax.axvline(float(rows[0]["node_angle"]), color="k", linestyle="--",
                   linewidth=0.8, label="slave node (1.25, 0)")
        ax.set_title(f"increment {rows[0]['increment']} ({role}): master "
                     "curve, radius - 1.25 (mm)")
        ax.set_xlabel("angle (degrees); grey: master nodes")
        ax.legend(fontsize=8)
    fig.tight_layout()
    save_atomically(fig, f"{directory}/case3_fig28.png", dpi=110)
    print(f"wrote {directory}/case3_fig28.png")
