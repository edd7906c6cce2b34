#!/usr/bin/python3
"""The rubber block dragged on a rigid flat (prm/rubber_block_drag.prm,
issue 33), glissade beside CalculiX: the force histories F_x / F_y and
F_y against the drag, for the sharp-cornered block and the block with
rounded corners, written as a CSV and a PNG (doc/studies/rubber_block.md).

    /usr/bin/python3 benchmarks/peers/rubber_block.py [--work DIR]
        [--png doc/studies/rubber_block.png]

CalculiX (ccx 2.20, Debian's calculix-ccx) on the same meshes: CPE4 (full
integration), NLGEOM, *HYPERELASTIC, NEO HOOKE with C10 = mu / 2 and D1 =
2 / K for E = 5, nu = 0.45 (ccx's neo-Hooke splits volume and shape, and
glissade's compressible law does not: the two agree to the first order
in the strain), penalty contact on a clamped element as the flat (ccx
has no analytical rigid surface), *FRICTION mu = 0.3 with a stick slope
equal to the penalty, the slave surface the bottom and both sides, one
*STATIC step to press 2 mm (10 increments) and one to drag 10 mm (40),
ccx's own cut-back. Runs:

- sharp corners, SURFACE TO SURFACE, penalty 1e2 and 1e3 (N/mm^3), and
  NODE TO SURFACE, penalty 1e3 (ccx stops where its increments fall
  below their minimum; 1e4 stops in the compression already);
- rounded corners (radius 2 mm), SURFACE TO SURFACE, penalty 1e3.

The leading corner node's displacement is printed for the sharp runs:
how deep the penalty lets it sink into the flat.
"""

import argparse
import csv
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "prm", "meshes"))
import make_rubber_block_mesh  # noqa: E402

E, NU, MU = 5.0, 0.45, 0.3
CCX_RUNS = [  # label, corner radius, contact type, penalty
    ("ccx_sharp_s2s_1e2", 0.0, "SURFACE TO SURFACE", 1e2),
    ("ccx_sharp_s2s_1e3", 0.0, "SURFACE TO SURFACE", 1e3),
    ("ccx_sharp_n2s_1e3", 0.0, "NODE TO SURFACE", 1e3),
    ("ccx_rounded_s2s_1e3", 2.0, "SURFACE TO SURFACE", 1e3),
]
GLISSADE_RUNS = [  # label, overrides
    ("glissade_sharp", []),
    ("glissade_rounded", ["Body block/Mesh/Type=gmsh",
                          "Body block/Mesh/File=meshes/rubber_block_fillet_r2.msh"]),
]


def read_msh(path):
    text = open(path).read()
    nodes = [line.split() for line in re.search(
        r"\$Nodes\n\d+\n(.*?)\$EndNodes", text, re.S).group(1).strip().split("\n")]
    elements = [list(map(int, line.split())) for line in re.search(
        r"\$Elements\n\d+\n(.*?)\$EndElements", text, re.S).group(1).strip().split("\n")]
    return nodes, elements


def ccx_deck(mesh, contact, penalty):
    """The deck of one run; the leading corner is node 21 (20, 0)."""
    nodes, elements = read_msh(mesh)
    quads = [e[-4:] for e in elements if e[1] == 3]
    lines = [e for e in elements if e[1] == 1]
    n, m = len(nodes), len(quads)
    out = ["*HEADING", "rubber block dragged on a rigid flat", "*NODE, NSET=NALL"]
    out += [f"{v[0]}, {v[1]}, {v[2]}" for v in nodes]
    for k, (x, y) in enumerate([(-30, -5), (60, -5), (60, 0), (-30, 0)]):
        out.append(f"{n + 1 + k}, {x}, {y}")
    out.append("*ELEMENT, TYPE=CPE4, ELSET=BLOCK")
    out += [f"{k + 1}, " + ", ".join(map(str, q)) for k, q in enumerate(quads)]
    out += ["*ELEMENT, TYPE=CPE4, ELSET=FLAT", f"{m + 1}, {n + 1}, {n + 2}, {n + 3}, {n + 4}"]
    faces = []  # the slave faces: bottom (1), right (2), left (4)
    for line in lines:
        if line[3] in (1, 2, 4):
            ends = set(line[-2:])
            for k, q in enumerate(quads):
                for f in range(4):
                    if {q[f], q[(f + 1) % 4]} == ends:
                        faces.append(f"{k + 1}, S{f + 1}")
    top = sorted({v for line in lines if line[3] == 3 for v in line[-2:]})
    out.append("*NSET, NSET=TOP")
    out += [", ".join(map(str, top[k:k + 10])) for k in range(0, len(top), 10)]
    out += ["*NSET, NSET=CORNER", "21", "*NSET, NSET=FLATN",
            ", ".join(str(n + 1 + k) for k in range(4)),
            "*SURFACE, NAME=SLAVE, TYPE=ELEMENT"] + faces
    out += ["*SURFACE, NAME=MASTER, TYPE=ELEMENT", f"{m + 1}, S3"]
    shear, bulk = E / (2 * (1 + NU)), E / (3 * (1 - 2 * NU))
    law = f"{penalty:g}" + (", 1e-4" if contact == "NODE TO SURFACE" else "")
    out += ["*MATERIAL, NAME=RUBBER", "*HYPERELASTIC, NEO HOOKE",
            f"{shear / 2:.12g}, {2 / bulk:.12g}",
            "*MATERIAL, NAME=FLAT", "*ELASTIC", "2e5, 0.3",
            "*SOLID SECTION, ELSET=BLOCK, MATERIAL=RUBBER", "1.",
            "*SOLID SECTION, ELSET=FLAT, MATERIAL=FLAT", "1.",
            "*SURFACE INTERACTION, NAME=SI",
            "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", law,
            "*FRICTION", f"{MU}, {penalty:g}",
            f"*CONTACT PAIR, INTERACTION=SI, TYPE={contact}", "SLAVE, MASTER",
            "*BOUNDARY", "FLATN, 1, 2"]
    for end, increment, x in ((1000, 0.1, 0.0), (10000, 0.025, 10.0)):
        out += [f"*STEP, NLGEOM, INC={end}", "*STATIC", f"{increment}, 1., 1e-6, {increment}",
                "*BOUNDARY", f"TOP, 1, 1, {x}", "TOP, 2, 2, -2.",
                "*NODE PRINT, NSET=TOP, TOTALS=ONLY", "RF",
                "*NODE PRINT, NSET=CORNER", "U", "*END STEP"]
    return "\n".join(out) + "\n"


def read_ccx(directory):
    """[(drag, F_x, F_y, corner u_x, corner u_y)] of the drag step."""
    text = open(os.path.join(directory, "job.dat")).read()
    forces = re.findall(r"total force \(fx,fy,fz\) for set TOP and time\s+(\S+)\s+(\S+)\s+(\S+)", text)
    corner = re.findall(r"displacements \(vx,vy,vz\) for set CORNER and time\s+(\S+)\s+21\s+(\S+)\s+(\S+)", text)
    # (ccx prints the time from the start of the analysis: the drag step
    # runs from t = 1 to 2, and the drag is 10 (t - 1))
    rows = []
    for (t, fx, fy), (_, ux, uy) in zip(forces, corner):
        if float(t) > 1.0 + 1e-9:
            rows.append((10 * (float(t) - 1.0), -float(fx), -float(fy), float(ux), float(uy)))
    return rows


def read_ccx_all_corner(directory):
    """[(ux, uy)] of the leading corner over both steps."""
    text = open(os.path.join(directory, "job.dat")).read()
    return [(float(ux), float(uy)) for _, ux, uy in re.findall(
        r"displacements \(vx,vy,vz\) for set CORNER and time\s+(\S+)\s+21\s+(\S+)\s+(\S+)", text)]


def read_glissade(path):
    rows = []
    with open(path) as f:
        for row in csv.DictReader(f):
            t = float(row["time"])
            if t > 1.0:
                rows.append((10 * (t - 1.0), float(row["floor_Fx"]), float(row["floor_Fy"])))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--work", default="/tmp/glissade-rubber-block")
    parser.add_argument("--png", default=os.path.join(ROOT, "doc", "studies", "rubber_block.png"))
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    series = {}
    for label, overrides in GLISSADE_RUNS:
        directory = os.path.join(args.work, label)
        command = [os.path.join(ROOT, "build", "glissade"), os.path.join(ROOT, "prm", "rubber_block_drag.prm"),
                   "--set", f"Output/Directory={directory}", "--set", "Output/Progress=false",
                   "--set", "Output/Plots=false", "--set", "Output/VTU interval=0"]
        for o in overrides:
            command += ["--set", o]
        result = subprocess.run(command, capture_output=True, text=True)
        stop = [line for line in result.stderr.split("\n") if "stopped" in line]
        print(f"{label}: exit {result.returncode}" + (f", {stop[0][:110]}..." if stop else ""))
        series[label] = read_glissade(os.path.join(directory, "history.csv"))
    for label, radius, contact, penalty in CCX_RUNS:
        directory = os.path.join(args.work, label)
        os.makedirs(directory, exist_ok=True)
        mesh = os.path.join(directory, "block.msh")
        sys.argv = ["", "20", "10", str(radius), mesh]
        make_rubber_block_mesh.main()
        with open(os.path.join(directory, "job.inp"), "w") as f:
            f.write(ccx_deck(mesh, contact, penalty))
        with open(os.path.join(directory, "ccx.log"), "w") as log:
            subprocess.run(["ccx", "-i", "job"], cwd=directory, stdout=log, stderr=log,
                           env=dict(os.environ, OMP_NUM_THREADS="1"))
        rows = read_ccx(directory)
        series[label] = [r[:3] for r in rows]
        sink = min((uy for _, uy in read_ccx_all_corner(directory)), default=0.0)
        print(f"{label}: {len(rows)} increments of the drag, to {rows[-1][0] if rows else 0:.3f} mm; "
              f"the leading corner down to u_y = {sink:.4f} mm")
    with open(os.path.join(args.work, "rubber_block.csv"), "w") as f:
        f.write("run,drag_mm,Fx,Fy,Fx_over_Fy\n")
        for label, rows in series.items():
            for drag, fx, fy in rows:
                f.write(f"{label},{drag:.6g},{fx:.8g},{fy:.8g},{abs(fx / fy) if fy else 0:.8g}\n")
    for label, rows in series.items():
        full = [d for d, fx, fy in rows if fy and abs(fx / fy) >= 0.297]
        last = rows[-1] if rows else (0, 0, 1)
        print(f"  {label:24s} last {last[0]:6.3f} mm, F_x / F_y {abs(last[1] / last[2]):.4f}; "
              f">= 0.297 from {full[0]:.3f} mm" if full else
              f"  {label:24s} last {last[0]:6.3f} mm, F_x / F_y {abs(last[1] / last[2]):.4f}; never >= 0.297")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    sys.path.insert(0, os.path.join(ROOT, "scripts"))
    from atomic_png import save_atomically
    style = {"glissade_sharp": ("k", "-", "glissade, sharp corners (stops: the corner folds)"),
             "glissade_rounded": ("b", "-", "glissade, corners rounded (R = 2 mm)"),
             "ccx_sharp_s2s_1e2": ("r", ":", "CalculiX s2s, sharp, penalty 1e2"),
             "ccx_sharp_s2s_1e3": ("r", "--", "CalculiX s2s, sharp, penalty 1e3"),
             "ccx_sharp_n2s_1e3": ("m", "-.", "CalculiX n2s, sharp, penalty 1e3"),
             "ccx_rounded_s2s_1e3": ("c", "--", "CalculiX s2s, rounded, penalty 1e3")}
    figure, (left, right) = plt.subplots(1, 2, figsize=(12, 4.8))
    for label, rows in series.items():
        if not rows:
            continue
        colour, line, name = style[label]
        drag = [r[0] for r in rows]
        left.plot(drag, [abs(r[1] / r[2]) for r in rows], color=colour, linestyle=line, label=name)
        right.plot(drag, [abs(r[2]) for r in rows], color=colour, linestyle=line, label=name)
    left.axhline(MU, color="grey", linewidth=0.5)
    left.set_xlabel("drag of the top (mm)")
    left.set_ylabel("F_x / F_y")
    left.set_title("friction ratio (mu = 0.3)")
    right.set_xlabel("drag of the top (mm)")
    right.set_ylabel("F_y (N per mm of thickness)")
    right.set_title("normal force")
    left.legend(fontsize=7)
    figure.tight_layout()
    save_atomically(figure, args.png)
    print(f"wrote {args.png} and {os.path.join(args.work, 'rubber_block.csv')}")


if __name__ == "__main__":
    main()
