"""Cases 1 and 2 (figs 16-23): the deformed meshes with the contact forces
(figs 16, 17, 18b), the crowns' vertical displacement (fig 19) and the
history of the square's corner node (figs 20-23), from the CSVs that
ContactCaseStudy writes."""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

directory = sys.argv[1]
names = {"q4": "Q4", "bspline": "Q4 + B-spline", "hermite": "Hermite",
         "mortar": "Q4, mortar"}
colours = {"q4": "tab:blue", "bspline": "tab:orange", "hermite": "tab:green",
           "mortar": "tab:red"}


def deformed_meshes(scene):
    files = sorted(glob.glob(f"{directory}/{scene}_*_deformed.csv"))
    variants = [os.path.basename(f)[len(scene) + 1:-len("_deformed.csv")] for f in files]
    if not files:
        return
    fig, axes = plt.subplots(1, len(files), figsize=(5.5 * len(files), 5), squeeze=False)
    for ax, f, v in zip(axes[0], files, variants):
        rows = list(csv.DictReader(open(f)))
        bodies = list(dict.fromkeys(r["body"] for r in rows))
        for i, body in enumerate(bodies):
            polygons = [[(float(r[f"x{k}"]), float(r[f"y{k}"])) for k in range(4)]
                        for r in rows if r["body"] == body]
            ax.add_collection(PolyCollection(polygons, facecolors=f"C{i}", alpha=0.25,
                                             edgecolors="k", linewidths=0.15))
        forces = list(csv.DictReader(open(f"{directory}/{scene}_{v}_forces.csv")))
        if forces:
            largest = max((float(r["fx"]) ** 2 + float(r["fy"]) ** 2) ** 0.5 for r in forces)
            ax.quiver([float(r["x"]) for r in forces], [float(r["y"]) for r in forces],
                      [float(r["fx"]) / largest for r in forces],
                      [float(r["fy"]) / largest for r in forces], color="r",
                      angles="xy", scale=12, width=0.004, label="contact force on slave")
            ax.legend(loc="lower left", fontsize=8)
        ax.autoscale()
        if scene.startswith("case2"):
            ax.set_xlim(-0.07, 0.07)  # the square and the rings around it
            ax.set_ylim(-0.03, 0.14)
        ax.set_aspect("equal")
        ax.set_title(f"{scene}: {names.get(v, v)}, final state")
    fig.tight_layout()
    save_atomically(fig, f"{directory}/{scene}_deformed.png", dpi=130)
    plt.close(fig)


def history(scene):
    path = f"{directory}/{scene}_history.csv"
    if not os.path.exists(path):
        return []
    return list(csv.DictReader(open(path)))


for path in glob.glob(f"{directory}/*_history.csv"):
    scene = os.path.basename(path)[:-len("_history.csv")]
    deformed_meshes(scene)
    rows = history(scene)
    variants = list(dict.fromkeys(r["variant"] for r in rows))
    if rows and rows[0]["corner_force"] != "":
        # Fig 19: the crowns of the two rings; figs 20-23: the corner node.
        fig, axes = plt.subplots(1, 3, figsize=(16, 4))
        for v in variants:
            pts = [r for r in rows if r["variant"] == v]
            n = [int(r["increment"]) for r in pts]
            axes[0].plot(n, [float(r["crown_left_uy"]) for r in pts], color=colours[v],
                         label=f"{names[v]}, left crown")
            axes[0].plot(n, [float(r["crown_right_uy"]) for r in pts], "--", color="k",
                         linewidth=0.8, label=f"{names[v]}, right crown" if v == variants[0] else None)
            axes[1].plot(n, [float(r["corner_ux"]) for r in pts], color=colours[v], label=names[v])
            axes[2].plot(n, [float(r["corner_force"]) for r in pts], color=colours[v], label=names[v])
        axes[0].set_title("u_y of the rings' crowns (fig 19)")
        axes[1].set_title("u_x of the square's lower left corner (figs 20-21)")
        axes[2].set_title("|contact force| on that corner (figs 22-23)")
        for ax in axes:
            ax.set_xlabel("increment")
            ax.legend(fontsize=8)
        fig.tight_layout()
        save_atomically(fig, f"{directory}/{scene}_histories.png", dpi=130)
        plt.close(fig)
        # Zoom on the contact phase, as the paper's figs 21 and 23.
        fig, axes = plt.subplots(1, 2, figsize=(12, 4))
        for v in variants:
            pts = [r for r in rows if r["variant"] == v and float(r["corner_force"]) > 0]
            if len(pts) < 10:
                continue
            zoom = pts[len(pts) // 3: len(pts) // 3 + max(len(pts) // 4, 10)]
            n = [int(r["increment"]) for r in zoom]
            axes[0].plot(n, [float(r["corner_ux"]) for r in zoom], ".-", color=colours[v],
                         label=names[v], markersize=3)
            axes[1].plot(n, [float(r["corner_force"]) for r in zoom], ".-", color=colours[v],
                         label=names[v], markersize=3)
        axes[0].set_title("zoom: corner u_x in contact (fig 21)")
        axes[1].set_title("zoom: corner |contact force| (fig 23)")
        for ax in axes:
            ax.set_xlabel("increment")
            ax.legend(fontsize=8)
        fig.tight_layout()
        save_atomically(fig, f"{directory}/{scene}_corner_zoom.png", dpi=130)
        plt.close(fig)
    elif rows and rows[0]["min_obstacle_distance"] != "":
        fig, ax = plt.subplots(figsize=(6, 4))
        for v in variants:
            pts = [r for r in rows if r["variant"] == v]
            ax.plot([int(r["increment"]) for r in pts],
                    [float(r["min_obstacle_distance"]) for r in pts], color=colours[v],
                    label=names[v])
        ax.axhline(0., color="k", linewidth=0.6)
        ax.set_title("smallest distance of a beam node to the rigid circle")
        ax.set_xlabel("increment")
        ax.set_ylabel("m (negative: penetration)")
        ax.legend(fontsize=8)
        fig.tight_layout()
        save_atomically(fig, f"{directory}/{scene}_distance.png", dpi=130)
        plt.close(fig)
print(f"pictures written to {directory}")
