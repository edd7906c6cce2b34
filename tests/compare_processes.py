#!/usr/bin/env python3
"""Compares the outputs of one scene run on 1 and on N processes.

usage: compare_processes.py ONE_PROCESS_DIR N_PROCESS_DIR [--statuses]

Every CSV file of the one-process folder (history.csv, the contact tables)
must be in the other folder with the same rows and columns, and:
- numbers agree to 1e-10 relative to the largest magnitude of their kind in
  the file (lengths: coordinates, gaps, slips, displacements; forces: every
  contact force and reaction; tractions: pressure and shear; momenta;
  energies: kinetic, strain, work, dissipations and their balance; any
  other column: itself), so that
  a quantity that is zero but for round-off (a gap in contact, a
  frictionless tangential force) is judged against the scale of its kind
  (sums in another order round otherwise: no bit-for-bit claim),
- `newton_iterations` agree to within one per increment,
- the active sets (`active`, `*_active_nodes`) are the same, and with
  --statuses the stick/slip statuses too (a frictionless scene's status is
  decided by round-off on a zero tangential force: not compared there).
Prints each disagreement and exits 1 if there is any.
"""
import csv
import os
import sys

RELATIVE = 1e-10


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


def kind_scales(header, rows):
    scales = {}
    for c, column in enumerate(header):
        values = [number(r[c]) for r in rows]
        if None in values:
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
        if column == "status" or None in values:
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
            if column == "newton_iterations":
                wrong = abs(a - b) > 1
            elif exact:
                wrong = a != b
            else:
                wrong = abs(a - b) > RELATIVE * scale
            if wrong:
                problems.append(f"{name} row {k + 1} {column}: {a!r} against "
                                f"{b!r} (scale of its kind {scale:.3g})")
    return problems


def main():
    arguments = [a for a in sys.argv[1:] if not a.startswith("--")]
    statuses = "--statuses" in sys.argv
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
    for p in problems[:40]:
        print(p)
    print(f"{len(names)} files compared, {len(problems)} disagreements")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
