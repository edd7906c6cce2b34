"""The speed-accuracy trade: for every measure swept (trade_<measure>.csv),
its error against wall time and against dofs, one line per discretisation,
each point labelled with its mesh parameter n. One PNG per measure."""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402

directory = sys.argv[1]
titles = {
    "geometric_gap": "Geometric study: largest gap error (% of R)",
    "geometric_normal": "Geometric study: largest normal error (degrees)",
    "table1": "Table 1: largest displacement, error against the reference (%)",
    "case1": "Case 1: tip displacement, error against the reference (%)",
    "case2": "Case 2: roughness of the corner's contact force",
    "case3": "Case 3: worst contact-force spread (%)",
    "case3_torque": "Case 3: largest spurious torque (%)",
    "hertz": "Hertz: peak pressure p0, error against the closed form (%)",
}
names = {"q4": "Q4 (faceted)", "q8": "Q8", "q9": "Q9", "q12": "Q12",
         "q16": "Q16", "bspline": "Q4 + B-spline (segment transfer)",
         "bspline-spline": "Q4 + B-spline (spline transfer)",
         "hermite": "Hermite", "mortar": "Q4 mortar (faceted master)",
         # (Hertz: node-to-segment on the flat's top for q4, bspline, hermite)
         # (an error at round-off is drawn at the floor 1e-12)
         "nurbs2": "NURBS p = 2 (exact circle)",
         "nurbs3": "NURBS p = 3 (exact circle)",
         "nurbs2-mortar": "NURBS p = 2, mortar",
         "nurbs3-mortar": "NURBS p = 3, mortar"}
for path in sorted(glob.glob(f"{directory}/trade_*.csv")):
    measure = os.path.basename(path)[len("trade_"):-len(".csv")]
    rows = list(csv.DictReader(open(path)))
    if not rows:
        continue
    # The geometric measures involve no solve: their cost is the dofs.
    keys = ["dofs"] if measure.startswith("geometric") else ["wall_seconds", "dofs"]
    fig, axes = plt.subplots(1, len(keys), figsize=(6 * len(keys), 4.5),
                             squeeze=False)
    for family, label in names.items():
        pts = sorted((r for r in rows if r["discretisation"] == family),
                     key=lambda r: int(r["n"]))
        if not pts:
            continue
        error = [max(float(r["error"]), 1e-12) for r in pts]
        for ax, key in zip(axes[0], keys):
            x = [float(r[key]) for r in pts]
            ax.loglog(x, error, marker="o", label=label)
            for xi, yi, r in zip(x, error, pts):
                ax.annotate(r["n"], (xi, yi), textcoords="offset points",
                            xytext=(4, 4), fontsize=8)
    for ax, key in zip(axes[0], keys):
        ax.set_xlabel("wall time (s, Release)" if key == "wall_seconds"
                      else "dofs")
        ax.set_ylabel("error")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(titles.get(measure, measure) + " (labels: n)")
    fig.tight_layout()
    save_atomically(fig, f"{directory}/trade_{measure}.png", dpi=120)
    plt.close(fig)
