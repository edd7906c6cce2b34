#!/usr/bin/python3
"""glissade beside GetFEM on the bar hitting a wall (prm/bar_impact.prm):
the time loops alone, side by side.

    /usr/bin/python3 benchmarks/peers/bar_impact_race.py [--refine 1,2,4]
        [--repeats 2] [--kinematics "small strain"] [--glissade build/glissade]
        [--work /tmp/glissade-bar-race]

For each refinement K (100 K x 2 K cells, 300 K steps) the two codes run
in turn, REPEATS rounds, the order alternating. glissade's time is its
run's wall time from summary.txt (set-up excluded), GetFEM's the
perf_counter around its time loop (getfem_bar_impact.py, set-up
excluded). GetFEM's model is small-strain elasticity: glissade runs with
Material/Kinematics = small strain unless --kinematics says otherwise.
Prints one row per K: dofs, each code's times and median, the ratio of
the medians, and each code's energy drift over the run (kinetic plus
strain, end against start). Nothing here is a test: the figures go to
doc/performance.md by hand.
"""

import argparse
import csv
import json
import os
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def run_glissade(binary, k, kinematics, work):
    directory = os.path.join(work, f"glissade_{k}")
    subprocess.run(
        [binary, os.path.join(ROOT, "prm", "bar_impact.prm"),
         "--set", "Output/Progress=false",
         "--set", "Output/VTU interval=0",
         "--set", f"Output/Directory={directory}",
         "--set", f"Body bar/Material/Kinematics={kinematics}",
         "--set", f"Body bar/Mesh/Subdivisions={100 * k}, {2 * k}",
         "--set", f"Load program/Stage increments={300 * k}"],
        check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(directory, "summary.txt")) as f:
        first = f.readline()
    seconds = float(re.search(r"([0-9.e+-]+) s wall", first).group(1))
    dofs = int(re.search(r"([0-9]+) dofs", first).group(1))
    with open(os.path.join(directory, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    energy = [float(r["kinetic_energy"]) + float(r["strain_energy"])
              for r in (rows[0], rows[-1])]
    return seconds, dofs, (energy[1] - energy[0]) / energy[0]


def run_getfem(k):
    out = subprocess.run(
        ["/usr/bin/python3", os.path.join(HERE, "getfem_bar_impact.py"),
         "--refine", str(k)],
        check=True, capture_output=True, text=True).stdout
    figures = json.loads(out.strip().splitlines()[-1])
    return figures["loop_time"], figures["dofs"], figures["energy_drift"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--refine", default="1,2,4")
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--kinematics", default="small strain")
    parser.add_argument("--glissade",
                        default=os.path.join(ROOT, "build", "glissade"))
    parser.add_argument("--work", default="/tmp/glissade-bar-race")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    env_note = os.environ.get("OPENBLAS_NUM_THREADS", "unset")
    print(f"bar impact race, glissade at {args.kinematics}, "
          f"OPENBLAS_NUM_THREADS={env_note}")
    print("K, dofs, glissade times (s), GetFEM times (s), "
          "ratio of medians, energy drift glissade, GetFEM")
    for k in (int(x) for x in args.refine.split(",")):
        ours, theirs = [], []
        for round_ in range(args.repeats):
            order = [0, 1] if round_ % 2 == 0 else [1, 0]
            for which in order:
                if which == 0:
                    seconds, dofs, drift = run_glissade(
                        args.glissade, k, args.kinematics, args.work)
                    ours.append(seconds)
                    our_drift = drift
                else:
                    seconds, _, their_drift = run_getfem(k)
                    theirs.append(seconds)
        ratio = statistics.median(ours) / statistics.median(theirs)
        print(f"{k}, {dofs}, {' '.join(f'{t:.3g}' for t in ours)}, "
              f"{' '.join(f'{t:.3g}' for t in theirs)}, {ratio:.2f}, "
              f"{our_drift:.3g}, {their_drift:.3g}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
