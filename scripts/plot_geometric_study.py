"""Figures 13 and 14 of the paper from output/geometric_study/*.csv:
gap error and normal-orientation error along the two edges around
theta = pi/2, one panel per discretisation, darker lines for larger n_e."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402

directory = sys.argv[1]
rows = list(csv.DictReader(open(f"{directory}/geometric_study.csv")))
methods = list(dict.fromkeys(r["method"] for r in rows))
counts = sorted({int(r["n_e"]) for r in rows})
titles = {"q4": "Q4", "q8": "Q8", "q12": "Q12", "bspline": "Q4 + B-spline",
          "hermite": "Hermite", "nurbs2": "NURBS p = 2 (exact)",
          "nurbs3": "NURBS p = 3 (exact)"}

for column, label, name in [
        ("gap_error_percent", "gap error g (% of R)", "fig13_gap_error.png"),
        ("normal_error_degrees", "normal error (degrees)",
         "fig14_normal_error.png")]:
    fig, axes = plt.subplots(1, len(methods), figsize=(4 * len(methods), 3.6))
    if len(methods) == 1:
        axes = [axes]
    for ax, method in zip(axes, methods):
        for k, n_e in enumerate(counts):
            pts = [r for r in rows if r["method"] == method and int(r["n_e"]) == n_e]
            # Edge 1 on [-2, 0], edge 2 on [0, 2]: theta = pi/2 at 0.
            x = [float(r["xi"]) + (-1 if r["edge"] == "1" else 1) for r in pts]
            y = [float(r[column]) for r in pts]
            shade = 0.8 - 0.8 * k / max(1, len(counts) - 1)
            ax.plot(x, y, color=(shade, shade, shade), lw=1)
        ax.axvline(0, color="tab:red", lw=0.5, ls=":")
        ax.set_title(titles.get(method, method))
        ax.set_xlabel("local coordinate (theta = pi/2 at 0)")
        ax.ticklabel_format(axis="y", style="sci", scilimits=(-2, 2))
    axes[0].set_ylabel(label)
    fig.suptitle(f"{label}, n_e = {counts[0]} ... {counts[-1]} (darker: larger n_e)")
    fig.tight_layout()
    save_atomically(fig, f"{directory}/{name}", dpi=110)
    print(f"wrote {directory}/{name}")
