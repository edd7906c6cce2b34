#!/usr/bin/python3
"""The disk packing's figures (prm/disk_packing.prm, issue 53).

Reads the run's history.csv and writes, beside it,
  disk_packing.csv  time, the lid's height, the box's volume fraction (the
                    disks' area over the box's below the lid), the lid's
                    force on the disks, the floor's, the disks' weight and
                    the vertical balance (floor - lid - weight: the disks'
                    inertia and damping, zero at rest);
  disk_packing.png  the lid's force against the volume fraction.
The box and the lid are prm/disk_packing.prm's: the lid comes down from
y = 7.4 at 0.8 from t = 6 to y = 3.9, then at 0.15 (lid_height() below).
The disks' area is that of their cells (polygons of 24 sides), which the
code's weight is.

  /usr/bin/python3 scripts/disk_packing_figures.py output/disk_packing
"""

import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def lid_height(t):
    """prm/disk_packing.prm's Obstacle/Motion of the lid, from y = 7.4."""
    return 7.4 - min(0.8 * max(0.0, t - 6.0), 3.5) - 0.15 * max(0.0, t - 10.375)


def disks_area(radii_and_holes, sides):
    """The area of annuli meshed as polygons of `sides` sides."""
    polygon = 0.5 * sides * math.sin(2.0 * math.pi / sides)
    return sum(polygon * (r * r - h * h) for r, h in radii_and_holes)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory", help="the run's output directory")
    parser.add_argument("--width", type=float, default=6.1)
    parser.add_argument("--lid-time", type=float, default=6.0,
                        help="when the lid starts to come down")
    parser.add_argument("--big", type=int, default=15,
                        help="disks of radius 0.5 (the others 0.35)")
    parser.add_argument("--disks", type=int, default=30)
    parser.add_argument("--gravity", type=float, default=1.0)
    args = parser.parse_args()

    disks = [(0.5, 0.1)] * args.big + [(0.35, 0.07)] * (args.disks - args.big)
    area = disks_area(disks, 24)
    weight = area * args.gravity  # density 1
    with open(os.path.join(args.directory, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    table = []
    for row in rows:
        t = float(row["time"])
        lid = lid_height(t)
        # The forces on the disks: the floor pushes up, the lid down.
        floor = float(row["floor_Fy"])
        lid_force = -float(row["lid_Fy"])
        table.append((t, lid, area / (args.width * lid), lid_force, floor,
                      weight, floor - lid_force - weight))
    out = os.path.join(args.directory, "disk_packing.csv")
    with open(out, "w") as f:
        f.write("time,lid_height,volume_fraction,lid_force,floor_force,"
                "weight,vertical_balance\n")
        for r in table:
            f.write(",".join(repr(v) for v in r) + "\n")
    print("wrote", out)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from atomic_png import save_atomically

    pressed = [r for r in table if r[0] >= args.lid_time]
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot([r[2] for r in pressed], [r[3] / weight for r in pressed], "-",
            label="lid")
    ax.plot([r[2] for r in pressed], [r[4] / weight for r in pressed], "--",
            label="floor")
    ax.set_xlabel("volume fraction of the box below the lid")
    ax.set_ylabel("force / the disks' weight")
    ax.set_title("%d disks of two radii pressed by a lid" % args.disks)
    ax.legend()
    ax.grid(alpha=0.3)
    png = os.path.join(args.directory, "disk_packing.png")
    save_atomically(fig, png, dpi=120)
    print("wrote", png)


if __name__ == "__main__":
    main()
