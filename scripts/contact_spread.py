"""Case 3 (paper section 4.3, fig 26): per increment, the spread of the
contact force norms on the interface around their equilibrium value F_e
(the mean over the interface at that increment), in %; the worst increment
and its distribution. Usage: contact_spread.py <output dir> <pair> [label]"""
import csv
import glob
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402

directory, pair = sys.argv[1], sys.argv[2]
label = sys.argv[3] if len(sys.argv) > 3 else pair
rows = []
for name in sorted(glob.glob(f"{directory}/contact-{pair}-*.csv")):
    increment = int(name.rsplit("-", 1)[1].split(".")[0])
    nodes = [r for r in csv.DictReader(open(name)) if r["active"] == "1"]
    forces = [(float(r["fx"]) ** 2 + float(r["fy"]) ** 2) ** 0.5 for r in nodes]
    if not forces or sum(forces) == 0:
        continue
    mean = sum(forces) / len(forces)
    spread = max(abs(f - mean) for f in forces) / mean * 100
    rows.append((increment, mean, spread, forces))
with open(f"{directory}/spread-{pair}.csv", "w") as out:
    out.write("increment,F_e,spread_percent\n")
    for increment, mean, spread, _ in rows:
        out.write(f"{increment},{mean},{spread}\n")
rotation = [r for r in rows if r[0] > 10]
worst = max(rotation or rows, key=lambda r: r[2])
print(f"{label}: worst spread {worst[2]:.4g} % at increment {worst[0]} "
      f"(F_e = {worst[1]:.6g} N), over {len(rotation)} rotation increments")
fig, axes = plt.subplots(1, 2, figsize=(11, 3.6))
axes[0].plot([r[0] for r in rows], [r[2] for r in rows])
axes[0].set_xlabel("increment")
axes[0].set_ylabel("spread around F_e (%)")
axes[0].set_title(f"{label}: spread per increment")
axes[1].plot([100 * (f / worst[1] - 1) for f in worst[3]], marker=".")
axes[1].set_xlabel("interface node")
axes[1].set_ylabel("(|F| - F_e) / F_e (%)")
axes[1].set_title(f"worst increment {worst[0]} (fig 26)")
fig.tight_layout()
save_atomically(fig, f"{directory}/spread-{pair}.png", dpi=110)
