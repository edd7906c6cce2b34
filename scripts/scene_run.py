"""One glissade run of a .prm for the study scripts: its entries changed by
--set, its history.csv read back.

    rows = run_scene(glissade, prm, directory, settings, who)

Several runs go side by side (a thread pool), so each runs on one thread
(BLAS's and deal.II's threads would otherwise fight over the cores). VTU
files and the progress lines are off. A run that fails stops the study
with glissade's last words.
"""
import csv
import os
import subprocess
import sys


def run_scene(glissade, prm, directory, settings, who):
    command = [glissade, prm, "--set", f"Output/Directory={directory}",
               "--set", "Output/VTU interval=0", "--set",
               "Output/Progress=false"]
    for setting in settings:
        command += ["--set", setting]
    environment = dict(os.environ, OPENBLAS_NUM_THREADS="1",
                       DEAL_II_NUM_THREADS="1")
    result = subprocess.run(command, capture_output=True, text=True,
                            env=environment)
    if result.returncode != 0:
        sys.exit(f"{who}: glissade failed in {directory}:\n"
                 + result.stdout[-2000:] + result.stderr[-2000:])
    with open(os.path.join(directory, "history.csv")) as f:
        return list(csv.DictReader(f))
