#!/usr/bin/env python3
"""Compares the outputs of one scene run on 1 and on N processes.

usage: compare_processes.py ONE_PROCESS_DIR N_PROCESS_DIR [--statuses]
                           [--tolerance=T]

Every CSV file of the one-process folder (history.csv, the contact tables)
must be in the other folder with the same rows and columns, and:
- numbers agree to 1e-10 (or T) relative to the largest magnitude of their
  kind in the file (lengths: coordinates, gaps, slips, displacements; forces: every
  contact force and reaction; tractions: pressure and shear; momenta;
  energies: kinetic, strain, work, dissipations and their balance; any
  other column: itself), so that
  a quantity that is zero but for round-off (a gap in contact, a
  frictionless tangential force) is judged against the scale of its kind
  (sums in another order round otherwise: no bit-for-bit claim); a field
  left empty (a node without a counterpart has no gap) is empty in both,
- `newton_iterations` agree to within one per increment,
- the active sets (`active`, `*_active_nodes`) are the same, and with
  --statuses the stick/slip statuses too (a frictionless scene's status is
  decided by round-off on a zero tangential force: not compared there).
Each body's VTU output, listed by its PVD index, must cover the same cells
at the same times: on N processes each entry is a .pvtu record whose pieces
exist and whose cell and point counts add up to the one-process file's (each
cell written once, by one process).
Prints each disagreement, then the largest difference found relative to
its kind's scale, and exits 1 if there is any disagreement. (The tests'
scenes have some hundreds of dofs; at a million, round-off alone parts
runs by some 1e-9: one process against itself with one thread instead of
two, 7.9e-10 on the rings' contact forces. benchmarks/processes_rings.sh
compares at 1e-8.)
"""
import csv
import os
import re
import sys

RELATIVE = 1e-10
# The largest difference met: (difference / scale, column, file).
largest = [0., "", ""]


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


FORCE_WORDS = ("r_n", "r_t", "_f_", "Fx", "Fy", "fx", "fy", "_Rx_", "_Ry_",
               "force")
TRACTION_WORDS = ("pressure", "shear")
ENERGY_WORDS = ("energy", "work_of", "dissipation")
MOMENTUM_WORDS = ("_px", "_py")
LENGTH_WORDS = ("gap", "slip", "tributary", "_ux_", "_uy_")


def kind(column):
    if any(w in column for w in TRACTION_WORDS):
        return "traction"
    if any(w in column for w in ENERGY_WORDS):
        return "energy"
    if any(column.endswith(w) for w in MOMENTUM_WORDS):
        return "momentum"
    if any(w in column for w in FORCE_WORDS) or column == "f":
        return "force"
    if column in ("X", "Y", "x", "y") or any(w in column
                                             for w in LENGTH_WORDS):
        return "length"
    return column


def numeric(rows, c):
    """Whether column c holds numbers, some fields left empty (a contact
    table's gap where a node has no counterpart)."""
    return all(number(r[c]) is not None for r in rows if r[c] != "")


def kind_scales(header, rows):
    scales = {}
    for c, column in enumerate(header):
        values = [number(r[c]) for r in rows if r[c] != ""]
        if not numeric(rows, c):
            continue
        k = kind(column)
        scales[k] = max([scales.get(k, 0.)] + [abs(v) for v in values])
    return scales


def compare(name, one, many, statuses):
    header, rows = one
    header_n, rows_n = many
    problems = []
    scales = kind_scales(header, rows)
    if header != header_n or len(rows) != len(rows_n):
        return [f"{name}: columns or row counts differ "
                f"({len(rows)} rows against {len(rows_n)})"]
    for c, column in enumerate(header):
        values = [number(r[c]) for r in rows]
        # (an empty field must be empty in both)
        for k, (a, b) in enumerate(zip(rows, rows_n)):
            if (a[c] == "") != (b[c] == ""):
                problems.append(f"{name} row {k + 1} {column}: "
                                f"'{a[c]}' against '{b[c]}'")
        if column == "status" or not numeric(rows, c):
            if column == "status" and not statuses:
                continue
            for k, (a, b) in enumerate(zip(rows, rows_n)):
                if a[c] != b[c]:
                    problems.append(f"{name} row {k + 1} {column}: "
                                    f"'{a[c]}' against '{b[c]}'")
            continue
        values_n = [number(r[c]) for r in rows_n]
        exact = column == "active" or column.endswith("_active_nodes")
        scale = scales[kind(column)]
        for k, (a, b) in enumerate(zip(values, values_n)):
            if a is None or b is None:
                continue
            if column == "newton_iterations":
                wrong = abs(a - b) > 1
            elif exact:
                wrong = a != b
            else:
                wrong = abs(a - b) > RELATIVE * scale
                if scale > 0. and abs(a - b) / scale > largest[0]:
                    largest[:] = [abs(a - b) / scale, column, name]
            if wrong:
                problems.append(f"{name} row {k + 1} {column}: {a!r} against "
                                f"{b!r} (scale of its kind {scale:.3g})")
    return problems


def pvd_entries(path):
    """(time, file) of each data set of a PVD index."""
    with open(path) as f:
        return re.findall(r'timestep="([^"]*)"[^>]*file="([^"]*)"', f.read())


def piece_counts(path):
    """(points, cells) written in one .vtu file."""
    with open(path, errors="replace") as f:
        head = f.read(4096)
    found = re.search(r'NumberOfPoints="(\d+)" NumberOfCells="(\d+)"', head)
    return (int(found.group(1)), int(found.group(2))) if found else None


def compare_vtu(one, many):
    """The bodies' VTU of the N-process run against the one-process run."""
    problems = []
    indices = sorted(f for f in os.listdir(one)
                     if f.endswith(".pvd") and not f.startswith("contact-"))
    for index in indices:
        if not os.path.exists(os.path.join(many, index)):
            problems.append(f"{index}: not written by the run on N processes")
            continue
        entries_one = pvd_entries(os.path.join(one, index))
        entries_many = pvd_entries(os.path.join(many, index))
        if [t for t, _ in entries_one] != [t for t, _ in entries_many]:
            problems.append(f"{index}: other times than the one-process run")
            continue
        for (t, file_one), (_, file_many) in zip(entries_one, entries_many):
            counts_one = piece_counts(os.path.join(one, file_one))
            if file_many.endswith(".pvtu"):
                with open(os.path.join(many, file_many)) as f:
                    pieces = re.findall(r'Piece Source="([^"]*)"', f.read())
            else:
                pieces = [file_many]
            counts = [piece_counts(os.path.join(many, p))
                      if os.path.exists(os.path.join(many, p)) else None
                      for p in pieces]
            if None in counts or not pieces:
                problems.append(f"{file_many}: a piece is missing")
                continue
            total = tuple(map(sum, zip(*counts)))
            if total != counts_one:
                problems.append(f"{file_many}: {total} points and cells in "
                                f"its pieces, {counts_one} in {file_one}")
    return problems, len(indices)


def main():
    global RELATIVE
    arguments = [a for a in sys.argv[1:] if not a.startswith("--")]
    statuses = "--statuses" in sys.argv
    for option in sys.argv[1:]:
        if option.startswith("--tolerance="):
            RELATIVE = float(option.split("=", 1)[1])
    if len(arguments) != 2:
        sys.exit(__doc__)
    one, many = arguments
    names = sorted(f for f in os.listdir(one) if f.endswith(".csv"))
    if "history.csv" not in names:
        sys.exit(f"{one} has no history.csv: nothing to compare")
    problems = []
    for name in names:
        path = os.path.join(many, name)
        if not os.path.exists(path):
            problems.append(f"{name}: not written by the run on N processes")
            continue
        problems += compare(name, read(os.path.join(one, name)), read(path),
                            statuses)
    vtu_problems, n_indices = compare_vtu(one, many)
    problems += vtu_problems
    for p in problems[:40]:
        print(p)
    print(f"{len(names)} files and {n_indices} VTU indices compared, "
          f"{len(problems)} disagreements at {RELATIVE:g} (largest "
          f"difference {largest[0]:.2g} of its kind's scale"
          + (f", {largest[1]} in {largest[2]})" if largest[1] else ")"))
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
