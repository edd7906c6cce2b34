"""The speed-accuracy trade on case 3: worst contact-force spread against
wall time (and against dofs), one line per discretisation of the interface,
each point labelled with its number of elements around."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402

directory = sys.argv[1]
rows = list(csv.DictReader(open(f"{directory}/trade_case3.csv")))
names = {"q4": "Q4 (faceted)", "bspline": "Q4 + B-spline", "hermite": "Hermite"}
fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
for family, label in names.items():
    pts = sorted((r for r in rows if r["discretisation"] == family),
                 key=lambda r: int(r["elements"]))
    if not pts:
        continue
    spread = [max(float(r["worst_spread_percent"]), 1e-6) for r in pts]
    for ax, key in zip(axes, ["wall_seconds", "dofs"]):
        x = [float(r[key]) for r in pts]
        ax.loglog(x, spread, marker="o", label=label)
        for xi, yi, r in zip(x, spread, pts):
            ax.annotate(r["elements"], (xi, yi), textcoords="offset points",
                        xytext=(4, 4), fontsize=8)
axes[0].set_xlabel("wall time (s, Release)")
axes[1].set_xlabel("dofs")
for ax in axes:
    ax.set_ylabel("worst contact-force spread (%)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
fig.suptitle("Case 3: accuracy against cost (labels: elements around the ring)")
fig.tight_layout()
save_atomically(fig, f"{directory}/trade_case3.png", dpi=120)
