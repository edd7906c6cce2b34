#!/usr/bin/python3
"""Every scene of prm/ and tests/input/ run with one build of glissade, and
two such runs compared: the check that a refactoring left the figures
alone (issue 38: "every .prm gives the same figures before and after").

    scripts/scene_figures.py run BINARY DIR [--processes N]
    scripts/scene_figures.py compare DIR_A DIR_B [--relative 1e-9]
                                                 [--absolute 1e-12]

`run` writes, per scene, DIR/<scene>/ with its outputs (VTU of the first
and last increments, pictures off), the exit code and the program's last
message; the study drivers (their own Study entry) are left to their ctest
runs. With --processes N every scene runs under `mpirun -np N`. `compare`
takes each scene's exit code, message, history.csv, contact tables (the
other CSV files) and the first line of summary.txt (without the wall
times) and compares them with numdiff at the relative and absolute
tolerances given (a figure passes if within either; default 0: bit for bit
as printed); bit for bit, the VTU files (bodies and
contact surfaces, pieces and records) are compared byte for byte too.
"""
import argparse
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def scenes():
    """The scene files, not the study drivers."""
    for folder in ("prm", "tests/input"):
        for prm in sorted((ROOT / folder).glob("*.prm")):
            study = re.search(r"^\s*set\s+Study\s*=\s*(\S+)", prm.read_text(),
                              re.MULTILINE)
            if study is None or study.group(1) == "simulation":
                yield prm


def run(binary, out, n_processes):
    launcher = [] if n_processes == 1 else [
        "mpirun", "--allow-run-as-root", "--oversubscribe", "-np",
        str(n_processes)]
    for prm in scenes():
        folder = out / f"{prm.parent.name}_{prm.stem}"
        folder.mkdir(parents=True, exist_ok=True)
        print(f"{prm.relative_to(ROOT)} ...", flush=True)
        result = subprocess.run(
            launcher + [binary, str(prm), "--set", "Output/VTU interval=0",
             "--set", "Output/Plots=false", "--set", "Output/Progress=false"],
            cwd=folder, capture_output=True, text=True)
        (folder / "exit_code").write_text(f"{result.returncode}\n")
        lines = (result.stdout + result.stderr).strip().splitlines()
        # (the message names the run's folder: only its last line is kept,
        # without paths)
        message = re.sub(r"\S*/", "", lines[-1]) if lines else ""
        (folder / "message").write_text(message + "\n")


def comparable_summary(path):
    """summary.txt's first line without its times."""
    if not path.exists():
        return ""
    first = path.read_text().splitlines()[0]
    return re.sub(r"[0-9.e+-]+ s\b", "<time>", first)


def compare(a, b, relative, absolute):
    differences = 0
    for folder_a in sorted(p for p in a.iterdir() if p.is_dir()):
        folder_b = b / folder_a.name
        name = folder_a.name
        if not folder_b.is_dir():
            print(f"{name}: missing in {b}")
            differences += 1
            continue
        for item in ("exit_code", "message"):
            if (folder_a / item).read_text() != (folder_b / item).read_text():
                print(f"{name}: {item} differs")
                differences += 1
        histories = sorted(folder_a.rglob("*.csv"))
        for history in histories:
            other = folder_b / history.relative_to(folder_a)
            numdiff = subprocess.run(
                ["numdiff", "-q", "-s", ", \t\n", "-r", str(relative),
                 "-a", str(absolute), str(history), str(other)])
            if numdiff.returncode != 0:
                print(f"{name}: {history.relative_to(folder_a)} differs")
                differences += 1
        for summary in sorted(folder_a.rglob("summary.txt")):
            other = folder_b / summary.relative_to(folder_a)
            if comparable_summary(summary) != comparable_summary(other):
                print(f"{name}: {summary.relative_to(folder_a)} differs:\n"
                      f"  {comparable_summary(summary)}\n"
                      f"  {comparable_summary(other)}")
                differences += 1
        vtus = []
        if relative == 0. and absolute == 0.:
            vtus = sorted(p for suffix in ("*.vtu", "*.pvtu", "*.pvd")
                          for p in folder_a.rglob(suffix))
            for vtu in vtus:
                other = folder_b / vtu.relative_to(folder_a)
                if not other.exists() or \
                        vtu.read_bytes() != other.read_bytes():
                    print(f"{name}: {vtu.relative_to(folder_a)} differs")
                    differences += 1
        print(f"{name}: {len(histories)} CSV files and {len(vtus)} VTU/PVD "
              "files compared")
    print(f"{differences} differences")
    return differences


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    run_parser = sub.add_parser("run")
    run_parser.add_argument("binary")
    run_parser.add_argument("directory", type=pathlib.Path)
    run_parser.add_argument("--processes", type=int, default=1)
    compare_parser = sub.add_parser("compare")
    compare_parser.add_argument("a", type=pathlib.Path)
    compare_parser.add_argument("b", type=pathlib.Path)
    compare_parser.add_argument("--relative", type=float, default=0.)
    compare_parser.add_argument("--absolute", type=float, default=0.)
    args = parser.parse_args()
    if args.command == "run":
        run(args.binary, args.directory.resolve(), args.processes)
        return 0
    return 1 if compare(args.a, args.b, args.relative, args.absolute) else 0


if __name__ == "__main__":
    sys.exit(main())
