#!/usr/bin/python3
"""glissade, GetFEM and CalculiX on the same problems, timed side by side.

Every row is one problem at one size. The three programs run in turn,
REPEATS times, the order rotating from one round to the next so that none
always runs first (a cold cache) or last; the time of a run is the wall
time of the whole process. A row reports the median of each program's
times, glissade's median divided by each peer's, and each one's error
against the closed form (Lame for the rings, Hertz for the disk).

    /usr/bin/python3 benchmarks/peers/run_peers.py [--problems rings,hertz]
        [--rings 40,80,160] [--hertz 0.01,0.005,0.0025,0.00125]
        (--problems sphere: Hertz's sphere, axisymmetric, on the --hertz
        meshes; --problems patch: the contact patch test, two blocks on
        non-matching meshes, [--patch 5x8,7x13] [--patch-order K])
        [--repeats 3] [--codes glissade,getfem,calculix]
        [--kinematics "small strain"]
        [--masters bspline,faceted,hermite] [--plot peers.png]
        [--glissade build/glissade] [--work /tmp/glissade-peers]

Every row also goes to WORK/peers.csv; --plot draws the times and the
ratios against the dofs as a PNG (Debian's matplotlib). The patch test's
rows also go to WORK/patch.csv, with each program's deviations.

It needs the peers (README.md): GetFEM's Python module and gmsh's live in
Debian's /usr/bin/python3, CalculiX is `ccx`. Nothing here is a test: the
figures go to doc/performance.md by hand, with the date and the commit.
"""

import argparse
import csv
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import problems  # noqa: E402  (the shared meshes and closed forms)

PYTHON = "/usr/bin/python3"


# Every program may use both cores: CalculiX's SPOOLES solver and its
# element loops run on one thread unless told otherwise.
BOTH_CORES = dict(os.environ, OMP_NUM_THREADS="2",
                  CCX_NPROC_EQUATION_SOLVER="2", CCX_NPROC_RESULTS="2",
                  CCX_NPROC_STIFFNESS="2")


def timed(command, cwd, log):
    """Wall time of one whole process; its output goes to log."""
    with open(log, "w") as out:
        start = time.perf_counter()
        result = subprocess.run(command, cwd=cwd, stdout=out,
                                stderr=subprocess.STDOUT, env=BOTH_CORES)
        elapsed = time.perf_counter() - start
    if result.returncode != 0:
        sys.exit(f"{' '.join(command)} failed (exit {result.returncode}); "
                 f"see {log}")
    return elapsed


def last_json(log):
    with open(log) as f:
        lines = [line for line in f.read().splitlines() if line.strip()]
    return json.loads(lines[-1])


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return rows


# ----------------------------------------------------------------- glissade
def glissade_rings_command(glissade, n, out, master="bspline"):
    """The rings with the outer ring's inner edge as a `master` surface:
    bspline or faceted over Q4 nodes, or hermite (the outer ring of C1
    Hermite elements)."""
    load = problems.ring_nodal_force(n)
    command = [glissade, os.path.join(HERE, "glissade_rings.prm"),
               "--set", f"Body inner/Mesh/Subdivisions={n}, {n // 10}",
               "--set", f"Body outer/Mesh/Subdivisions={n}, {n // 10}",
               "--set", "Body outer/Boundary conditions/Nodal loads=outer: "
                        f"-{load!r}*x/sqrt(x^2+y^2)*t, -{load!r}*y/sqrt(x^2+y^2)*t",
               "--set", f"Contact interface/Surface={master}",
               "--set", f"Output/Directory={out}"]
    if master == "hermite":
        command += ["--set", "Body outer/Element/Space=hermite"]
    return command


def glissade_hertz_command(glissade, mesh, out, kinematics):
    """The peers solve Hertz's problems at small strain, as Hertz's closed
    form does: glissade too unless --kinematics says otherwise (at large
    strain its a is 0.4-0.5 % wider at a / R = 0.05, an effect of order
    a / R that is not the discretisation's)."""
    return [glissade, os.path.join(HERE, "glissade_hertz.prm"),
            "--set", f"Body disk/Mesh/File={mesh}",
            "--set", f"Output/Directory={out}",
            "--set", f"Body disk/Material/Kinematics={kinematics}"]


def glissade_sphere_command(glissade, mesh, out, kinematics):
    """The same quarter disk as the meridian of a sphere (x = r)."""
    return glissade_hertz_command(glissade, mesh, out, kinematics) + [
        "--set", "Body disk/Material/Hypothesis=axisymmetric",
        "--set", "Body disk/Boundary conditions/Prescribed displacement="
                 f"top: y: -{problems.SPHERE_DRIVE!r}*t"]


def glissade_sphere_result(out):
    table = read_csv(last_contact_table(out, "flat"))
    p0, a, P = problems.sphere_figures_from_ring_forces(
        [float(row["X"]) for row in table], [float(row["Y"]) for row in table],
        [float(row["fy"]) for row in table])
    return {"dofs": glissade_dofs(out), "P": P, "p0": p0, "a": a}


def glissade_dofs(out):
    """The dof count of the summary's first line ("..., 10880 dofs, ...")."""
    with open(os.path.join(out, "summary.txt")) as f:
        words = f.readline().replace(",", " ").split()
    return int(words[words.index("dofs") - 1])


def glissade_rings_result(out):
    last = read_csv(os.path.join(out, "history.csv"))[-1]
    # u_r at the four supported nodes of r = 2 (the field is axisymmetric).
    u_r = (float(last["outer_ux_2_0"]) + float(last["outer_uy_0_2"])
           - float(last["outer_ux_m2_0"]) - float(last["outer_uy_0_m2"])) / 4
    table = read_csv(last_contact_table(out, "interface"))
    normal = sum(float(row["r_n"]) for row in table)
    return {"dofs": glissade_dofs(out), "u_r2": u_r,
            "interface_pressure": normal / (2 * math.pi * 1.25)}


def last_contact_table(out, pair):
    tables = sorted(f for f in os.listdir(out)
                    if f.startswith(f"contact-{pair}-") and f.endswith(".csv"))
    return os.path.join(out, tables[-1])


def glissade_hertz_result(out):
    table = read_csv(last_contact_table(out, "flat"))
    x = [float(row["X"]) for row in table]
    force = [float(row["r_n"]) for row in table]
    p0, a, P = problems.hertz_figures_from_nodal_forces(x, force)
    return {"dofs": glissade_dofs(out), "P": P, "p0": p0, "a": a}


PATCH_MOTION = (f"xy: {problems.PATCH_SHEAR!r}*y*t, "
                f"-{problems.PATCH_DRIVE!r}*y*t")


def glissade_patch_command(glissade, case, discretisation, out):
    """glissade_patch.prm for one case (upper cells, lower cells, slave
    body, friction): the meshes, the slave side and, with friction, the
    homogeneous motion of every outer side instead of the frictionless
    supports."""
    upper, lower, slave, friction = case
    master = "lower" if slave == "upper" else "upper"
    side = {"upper": "bottom", "lower": "top"}
    command = [glissade, os.path.join(HERE, "glissade_patch.prm"),
               "--set", "Body upper/Mesh/Subdivisions="
                        f"{upper}, {problems.PATCH_LAYERS['upper']}",
               "--set", "Body lower/Mesh/Subdivisions="
                        f"{lower}, {problems.PATCH_LAYERS['lower']}",
               "--set", f"Contact interface/Slave body={slave}",
               "--set", f"Contact interface/Slave boundary={side[slave]}",
               "--set", f"Contact interface/Master body={master}",
               "--set", f"Contact interface/Master boundary={side[master]}",
               "--set", f"Contact interface/Discretisation={discretisation}",
               "--set", f"Output/Directory={out}"]
    if friction:
        for body, held in (("upper", "top"), ("lower", "bottom")):
            conditions = f"Body {body}/Boundary conditions/"
            command += ["--set", conditions + "Fixed=",
                        "--set", conditions + "Prescribed displacement=" +
                        "; ".join(f"{s}: {PATCH_MOTION}"
                                  for s in (held, "left", "right"))]
        command += ["--set", "Contact interface/Friction coefficient="
                             f"{problems.PATCH_MU!r}"]
    return command


def glissade_patch_result(out, slave):
    """The patch test's figures as tests/mortar_test.cc reads them: each
    active slave node's force over its tributary length (the contact
    table) against the top support's force over the top's current width
    (history.csv), minus it on the upper block's bottom."""
    last = read_csv(os.path.join(out, "history.csv"))[-1]
    width = 1 + float(last["upper_ux_1_1"]) - float(last["upper_ux_0_1"])
    sign = -1 if slave == "upper" else 1
    applied = [sign * float(last["upper_Rx_top"]) / width,
               sign * float(last["upper_Ry_top"]) / width]
    table = read_csv(last_contact_table(out, "interface"))
    error, interior, n = problems.patch_figures(
        [float(row["X"]) for row in table],
        [(float(row["fx"]), float(row["fy"])) for row in table],
        [float(row["tributary_length"]) for row in table], applied,
        [row["active"] == "1" for row in table])
    return {"dofs": glissade_dofs(out), "applied": applied, "error": error,
            "error_interior": interior, "n_checked": n,
            "n_slave": len(table)}


# -------------------------------------------------------------------- rows
def fresh_folder(args, name):
    work = os.path.join(args.work, name)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    return work


def run_and_read(args, work, runs, readers):
    """Race the selected programs, then read each one's figures."""
    runs = {code: run for code, run in runs.items() if code in args.codes}
    times = race(runs, args.repeats, work)
    return times, {code: read() for code, read in readers.items()
                   if code in runs}


def rings_row(args, n):
    """The peers and glissade with each of args.masters, in one race: the
    first master runs as "glissade", the others as "glissade-<master>"."""
    work = fresh_folder(args, f"rings-{n}")
    ccx_dir = os.path.join(work, "calculix")
    subprocess.run([PYTHON, os.path.join(HERE, "calculix.py"), "rings",
                    str(n), ccx_dir], check=True)
    runs = {
        "getfem": ([PYTHON, os.path.join(HERE, "getfem_rings.py"), str(n),
                    "--out", os.path.join(work, "getfem")], work),
        "calculix": (["ccx", "-i", "job"], ccx_dir),
    }
    readers = {
        "getfem": lambda: last_json(os.path.join(work, "getfem.log")),
        "calculix": lambda: read_calculix(["rings", str(n), ccx_dir]),
    }
    for k, master in enumerate(args.masters):
        code = "glissade" if k == 0 else f"glissade-{master}"
        out = os.path.join(work, code)
        runs[code] = (glissade_rings_command(args.glissade, n, out, master),
                      work)
        readers[code] = lambda out=out: glissade_rings_result(out)
        if "glissade" in args.codes and code not in args.codes:
            args.codes.append(code)
    times, results = run_and_read(args, work, runs, readers)
    u_lame = problems.lame_u_r2()
    p_lame = problems.lame_interface_pressure()
    errors = {code: ((r["u_r2"] - u_lame) / abs(u_lame),
                     (r["interface_pressure"] - p_lame) / p_lame)
              for code, r in results.items()}
    return (f"rings {n}x{n // 10} (glissade: {args.masters[0]} master)",
            times, results, errors)


def hertz_row(args, h):
    work = fresh_folder(args, f"hertz-{h}")
    mesh = os.path.join(work, "hertz.msh")
    problems.hertz_mesh(h, mesh)
    ccx_dir = os.path.join(work, "calculix")
    subprocess.run([PYTHON, os.path.join(HERE, "calculix.py"), "hertz",
                    str(h), ccx_dir, "--mesh", mesh], check=True)
    # Beside each code's nodal contact, the weak (integral) forms: glissade's
    # mortar and GetFEM's integral contact brick.
    for code, variant in (("glissade", "glissade-mortar"),
                          ("getfem", "getfem-integral")):
        if code in args.codes and variant not in args.codes:
            args.codes.append(variant)
    runs = {
        "glissade": (glissade_hertz_command(args.glissade, mesh,
                                            os.path.join(work, "glissade"),
                                            args.kinematics),
                     work),
        "glissade-mortar": (glissade_hertz_command(
            args.glissade, mesh, os.path.join(work, "glissade-mortar"),
            args.kinematics) +
            ["--set", "Contact flat/Discretisation=mortar"], work),
        "getfem": ([PYTHON, os.path.join(HERE, "getfem_hertz.py"), str(h),
                    "--mesh", mesh, "--out", os.path.join(work, "getfem")],
                   work),
        "getfem-integral": ([PYTHON, os.path.join(HERE, "getfem_hertz.py"),
                             str(h), "--mesh", mesh, "--contact", "integral",
                             "--out", os.path.join(work, "getfem-integral")],
                            work),
        "calculix": (["ccx", "-i", "job"], ccx_dir),
    }
    times, results = run_and_read(args, work, runs, {
        "glissade": lambda: glissade_hertz_result(os.path.join(work, "glissade")),
        "glissade-mortar": lambda: glissade_hertz_result(
            os.path.join(work, "glissade-mortar")),
        "getfem": lambda: last_json(os.path.join(work, "getfem.log")),
        "getfem-integral": lambda: last_json(
            os.path.join(work, "getfem-integral.log")),
        "calculix": lambda: read_calculix(["hertz", str(h), ccx_dir]),
    })
    errors = {}
    for code, r in results.items():
        p0, a = problems.hertz_reference(r["P"])
        errors[code] = ((r["p0"] - p0) / p0, (r["a"] - a) / a)
    return f"hertz h={h}", times, results, errors


def sphere_row(args, h):
    """Hertz's sphere, axisymmetric: glissade and CalculiX's CAX4 on the
    same meridian mesh (GetFEM's Python scripts here are plane)."""
    work = fresh_folder(args, f"sphere-{h}")
    mesh = os.path.join(work, "hertz.msh")
    problems.hertz_mesh(h, mesh)
    ccx_dir = os.path.join(work, "calculix")
    subprocess.run([PYTHON, os.path.join(HERE, "calculix.py"), "sphere",
                    str(h), ccx_dir, "--mesh", mesh], check=True)
    runs = {
        "glissade": (glissade_sphere_command(args.glissade, mesh,
                                             os.path.join(work, "glissade"),
                                             args.kinematics),
                     work),
        "calculix": (["ccx", "-i", "job"], ccx_dir),
    }
    times, results = run_and_read(args, work, runs, {
        "glissade": lambda: glissade_sphere_result(os.path.join(work, "glissade")),
        "calculix": lambda: read_calculix(["sphere", str(h), ccx_dir]),
    })
    errors = {}
    for code, r in results.items():
        p0, a = problems.sphere_reference(r["P"])
        errors[code] = ((r["p0"] - p0) / p0, (r["a"] - a) / a)
    return f"sphere h={h}", times, results, errors


def patch_row(args, case):
    """The contact patch test, one mesh pair, slave side and contact law:
    glissade's node-to-segment and mortar, GetFEM's nodal and integral
    contact between non-matching meshes (CalculiX has no row here)."""
    upper, lower, slave, friction = case
    law = "friction" if friction else "frictionless"
    work = fresh_folder(args, f"patch-{upper}x{lower}-{slave}-{law}")
    for code, variant in (("glissade", "glissade-mortar"),
                          ("getfem", "getfem-integral")):
        if code in args.codes and variant not in args.codes:
            args.codes.append(variant)
    getfem = [PYTHON, os.path.join(HERE, "getfem_patch.py"), str(upper),
              str(lower), "--slave", slave]
    if friction:
        getfem.append("--friction")
    runs = {
        "glissade": (glissade_patch_command(
            args.glissade, case, "node-to-segment",
            os.path.join(work, "glissade")), work),
        "glissade-mortar": (glissade_patch_command(
            args.glissade, case, "mortar",
            os.path.join(work, "glissade-mortar")), work),
        "getfem": (getfem + ["--contact", "nodal", "--out",
                             os.path.join(work, "getfem")], work),
        "getfem-integral": (getfem + ["--out",
                                      os.path.join(work, "getfem-integral")],
                            work),
    }
    readers = {
        "glissade": lambda: glissade_patch_result(
            os.path.join(work, "glissade"), slave),
        "glissade-mortar": lambda: glissade_patch_result(
            os.path.join(work, "glissade-mortar"), slave),
        "getfem": lambda: last_json(os.path.join(work, "getfem.log")),
        "getfem-integral": lambda: last_json(
            os.path.join(work, "getfem-integral.log")),
    }
    # The integral brick with a finer rule on the slave faces: its kinked
    # projected master functions integrated more exactly.
    for order in args.patch_order:
        code = f"getfem-integral-o{order}"
        runs[code] = (getfem + ["--contact-order", str(order), "--out",
                                os.path.join(work, code)], work)
        readers[code] = lambda code=code: last_json(
            os.path.join(work, f"{code}.log"))
        if "getfem" in args.codes and code not in args.codes:
            args.codes.append(code)
    times, results = run_and_read(args, work, runs, readers)
    errors = {code: (r["error"], r["error_interior"])
              for code, r in results.items()}
    return (f"patch {upper} on {lower}, slave {slave}, {law}", times,
            results, errors)


def read_calculix(arguments):
    output = subprocess.run([PYTHON, os.path.join(HERE, "calculix.py"),
                             "read"] + arguments, check=True,
                            capture_output=True, text=True).stdout
    return json.loads(output.strip().splitlines()[-1])


def race(runs, repeats, work):
    """Each program REPEATS times, the order rotating every round."""
    names = list(runs)
    times = {name: [] for name in names}
    for k in range(repeats):
        order = names[k % len(names):] + names[:k % len(names)]
        for name in order:
            command, cwd = runs[name]
            times[name].append(timed(command, cwd,
                                     os.path.join(work, f"{name}.log")))
    return {name: statistics.median(t) for name, t in times.items()}


RECORDS = []  # (problem, row label, program, dofs, median wall time)
PATCH_RECORDS = []  # the patch rows: (label, times, results, errors)


def print_row(label, times, results, errors, problem):
    for code in times:
        RECORDS.append((problem, label, code, results[code]["dofs"],
                        times[code]))
    print(f"\n{label}")
    for code in times:
        error = errors[code]
        if problem == "rings":
            figure = (f"u_r(2) {100 * error[0]:+.3f} %, interface pressure "
                      f"{100 * error[1]:+.3f} %")
        elif problem == "patch":
            figure = (f"largest deviation {100 * error[0]:.2g} % "
                      f"({results[code]['n_checked']} of "
                      f"{results[code]['n_slave']} slave nodes), without "
                      f"the two ends {100 * error[1]:.2g} %")
        else:
            figure = (f"P {results[code]['P']:.4f}, p0 {100 * error[0]:+.2f} %,"
                      f" a {100 * error[1]:+.2f} %")
        print(f"  {code:16s} {times[code]:7.2f} s  dofs "
              f"{results[code]['dofs']}  {figure}")
    names = {"getfem": "GetFEM", "calculix": "CalculiX"}
    for code in times:
        if code.startswith("glissade"):
            print("  " + ", ".join(
                f"{code} / {names[peer]} {times[code] / times[peer]:.2f}"
                for peer in ("getfem", "calculix") if peer in times))
    sys.stdout.flush()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--problems", default="rings,hertz",
                        help="rings, hertz (plane strain), sphere (Hertz's "
                             "sphere, axisymmetric: glissade and CalculiX), "
                             "patch (the contact patch test: glissade and "
                             "GetFEM)")
    parser.add_argument("--rings", default="40,80,160")
    parser.add_argument("--hertz", default="0.01,0.005,0.0025,0.00125")
    parser.add_argument("--patch", default=",".join(
                            f"{upper}x{lower}"
                            for upper, lower in problems.PATCH_MESHES),
                        help="the patch test's meshes, upper x lower cells "
                             "along the interface; each is run with either "
                             "block as slave, frictionless and sticking")
    parser.add_argument("--patch-order", default="",
                        help="also GetFEM's integral brick with these Gauss "
                             "orders on the contact faces (e.g. 9,19)")
    parser.add_argument("--kinematics", default="small strain",
                        help="glissade's Material/Kinematics on Hertz's "
                             "problems (the peers' and the closed form's "
                             "model: small strain)")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--codes", default="glissade,getfem,calculix",
                        help="the programs to run (GetFEM takes more than "
                             "half an hour on the 1600 rings)")
    parser.add_argument("--glissade",
                        default=os.path.join(ROOT, "build", "glissade"))
    parser.add_argument("--masters", default="bspline",
                        help="glissade's master surfaces on the rings, each "
                             "run in the same race (bspline,faceted,hermite)")
    parser.add_argument("--work", default="/tmp/glissade-peers")
    parser.add_argument("--plot", default=None,
                        help="draw the times and ratios as this PNG")
    args = parser.parse_args()
    args.glissade = os.path.abspath(args.glissade)
    args.codes = args.codes.split(",")
    args.masters = args.masters.split(",")
    args.patch_order = [int(v) for v in args.patch_order.split(",") if v]
    if "calculix" in args.codes and not shutil.which("ccx"):
        sys.exit("ccx not found: apt-get install calculix-ccx (README.md)")
    selected = args.problems.split(",")
    print(f"median of {args.repeats} runs each, whole process, wall time")
    if "rings" in selected:
        for n in (int(v) for v in args.rings.split(",")):
            print_row(*rings_row(args, n), "rings")
    if "hertz" in selected:
        for h in (float(v) for v in args.hertz.split(",")):
            print_row(*hertz_row(args, h), "hertz")
    if "sphere" in selected:
        for h in (float(v) for v in args.hertz.split(",")):
            print_row(*sphere_row(args, h), "sphere")
    if "patch" in selected:
        for meshes in args.patch.split(","):
            upper, lower = (int(v) for v in meshes.split("x"))
            for slave in ("upper", "lower"):
                for friction in (False, True):
                    row = patch_row(args, (upper, lower, slave, friction))
                    print_row(*row, "patch")
                    PATCH_RECORDS.append(row)
    os.makedirs(args.work, exist_ok=True)
    write_records(os.path.join(args.work, "peers.csv"))
    if PATCH_RECORDS:
        write_patch_records(os.path.join(args.work, "patch.csv"))
    if args.plot:
        plot_records(os.path.abspath(args.plot))


def write_records(path):
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["problem", "row", "program", "dofs", "wall_s"])
        for record in RECORDS:
            out.writerow(record)


def write_patch_records(path):
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["row", "program", "dofs", "wall_s", "n_checked",
                      "n_slave", "largest_deviation",
                      "largest_deviation_without_ends"])
        for label, times, results, errors in PATCH_RECORDS:
            for code in times:
                out.writerow([label, code, results[code]["dofs"],
                              times[code], results[code]["n_checked"],
                              results[code]["n_slave"], *errors[code]])


def plot_records(path):
    """Per problem: each program's time against the dofs, and glissade's
    ratios to each peer with the issue's target, 0.5."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    problems_run = [p for p in ("rings", "hertz", "sphere")
                    if any(r[0] == p for r in RECORDS)]
    fig, axes = plt.subplots(2, len(problems_run), squeeze=False,
                             figsize=(5.2 * len(problems_run), 7.2))
    names = {"getfem": "GetFEM", "calculix": "CalculiX"}
    # One colour per program in every panel; the peer by the line's style.
    colours = {"getfem": "C1", "calculix": "C3", "glissade": "C0",
               "glissade-faceted": "C2", "glissade-hermite": "C4",
               "glissade-bspline": "C9"}
    styles = {"getfem": "-", "calculix": ":"}
    for column, problem in enumerate(problems_run):
        records = [r for r in RECORDS if r[0] == problem]
        codes = list(dict.fromkeys(r[2] for r in records))
        top, bottom = axes[0][column], axes[1][column]
        for code in codes:
            points = sorted((r[3], r[4]) for r in records if r[2] == code)
            top.loglog(*zip(*points), "o-", color=colours.get(code),
                       label=names.get(code, code))
        for code in (c for c in codes if c.startswith("glissade")):
            for peer in ("getfem", "calculix"):
                ratio = []
                for row in dict.fromkeys(r[1] for r in records):
                    mine = [r for r in records if r[1] == row and r[2] == code]
                    theirs = [r for r in records
                              if r[1] == row and r[2] == peer]
                    if mine and theirs:
                        ratio.append((mine[0][3], mine[0][4] / theirs[0][4]))
                if ratio:
                    bottom.semilogx(*zip(*sorted(ratio)), "o",
                                    linestyle=styles[peer],
                                    color=colours.get(code),
                                    label=f"{code} / {names[peer]}")
        bottom.axhline(0.5, color="k", linestyle="--", linewidth=0.8,
                       label="target 0.5")
        top.set_title(f"{problem}: whole process, median wall time")
        top.set_xlabel("dofs")
        top.set_ylabel("s")
        bottom.set_xlabel("dofs")
        bottom.set_ylabel("glissade's time / the peer's")
        top.legend(fontsize=7)
        bottom.legend(fontsize=6)
        for axis in (top, bottom):
            axis.grid(True, which="both", linewidth=0.3)
    fig.tight_layout()
    temporary = path + ".tmp.png"
    fig.savefig(temporary, dpi=110)
    os.replace(temporary, path)
    print(f"\nwrote {path}")


if __name__ == "__main__":
    main()
