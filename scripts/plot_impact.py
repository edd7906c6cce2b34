"""The contact force of two runs of a dynamic scene against time, one
above the other: a scheme beside another (plain Newmark's chatter beside
the redistributed mass's flat pressure), from their history.csv.

    /usr/bin/python3 scripts/plot_impact.py A/history.csv "label A" \\
        B/history.csv "label B" --pair wall --component Fx --png out.png
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("runs", nargs="+", help="history.csv label [...]")
parser.add_argument("--pair", required=True)
parser.add_argument("--component", default="Fx")
parser.add_argument("--png", default="impact.png")
args = parser.parse_args()
if len(args.runs) % 2:
    parser.error("give each history.csv a label")

pairs = list(zip(args.runs[0::2], args.runs[1::2]))
fig, axes = plt.subplots(len(pairs), 1, figsize=(7, 2.6 * len(pairs)),
                         sharex=True, squeeze=False)
column = f"{args.pair}_{args.component}"
for axis, (path, label) in zip(axes[:, 0], pairs):
    rows = list(csv.DictReader(open(path)))
    t = [float(r["time"]) for r in rows]
    f = [abs(float(r[column])) for r in rows]
    axis.plot(t, f, ".-", markersize=3, linewidth=0.8)
    axis.set_title(label, fontsize=9)
    axis.set_ylabel(f"|{args.component}| on '{args.pair}'")
    axis.grid(alpha=0.3)
axes[-1, 0].set_xlabel("t")
fig.tight_layout()
save_atomically(fig, args.png, dpi=100)
print(f"wrote {args.png}")
