"""The blade/casing study of prm/blade_casing.prm (issue 35): the blade's
first bending frequency from a free-vibration run, then a sweep of the
rotation speed Omega, and a picture of the tip amplitude against Omega
with the contact force's spectrum at the strongest interaction.

    /usr/bin/python3 scripts/blade_casing_study.py [--glissade build/glissade]
        [--omegas 350:1600:50] [--jobs 2] [--output output/blade_casing_study]
        [--png doc/blade_casing.png]

Every run is glissade itself on the .prm, its entries changed by --set:
  free vibration: the casing moved out of reach (Radius 320, no lobes), no
    damping, the blade started with the velocity of Euler-Bernoulli's first
    mode; the frequency from the tip's zero crossings over ten periods;
  sweep: Rotation = -Omega*t for each Omega; the tip amplitude is the
    largest |u_x| of the tip's centre over the last quarter of the run.
The lobes excite the blade at 2 Omega and its harmonics (4 Omega, ...): the
picture marks Omega = omega_1 / 2, omega_1 / 4, omega_1 / 6 with the
measured omega_1. Writes sweep.csv beside the runs.
"""
import argparse
import concurrent.futures
import math
import os

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402
from scene_run import run_scene  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
PRM = os.path.join(HERE, "..", "prm", "blade_casing.prm")
# The blade of the .prm: E, rho, thickness h, length L, root radius.
E, RHO, H, L, ROOT = 110000.0, 4.4e-9, 5.0, 100.0, 200.0
TIP = "blade_ux_0_300"


def euler_bernoulli_omega_1():
    return 1.8751 ** 2 * H / L ** 2 * math.sqrt(E / (12.0 * RHO))


def run(glissade, directory, settings):
    return run_scene(glissade, PRM, directory, settings, "blade_casing_study")


def free_vibration(glissade, output):
    omega = euler_bernoulli_omega_1()
    b = f"1.8751*(y-{ROOT})/{L}"
    mode = (f"100*(cosh({b})-cos({b})-0.7341*(sinh({b})-sin({b})))")
    period = 2.0 * math.pi / omega
    rows = run(glissade, os.path.join(output, "free_vibration"), [
        "Contact tip/Obstacle/Lobe depth=0",
        "Contact tip/Obstacle/Radius=320",
        f"Body blade/Initial velocity={mode}, 0",
        "Time integration/Mass damping=0",
        f"Load program/Stage end times={10.5 * period}",
        "Load program/Stage increments=420"])
    t = np.array([float(r["time"]) for r in rows])
    u = np.array([float(r[TIP]) for r in rows])
    crossings = [t[i - 1] + (t[i] - t[i - 1]) * u[i - 1] / (u[i - 1] - u[i])
                 for i in range(1, len(u))
                 if (u[i - 1] < 0.0) != (u[i] < 0.0)]
    measured = math.pi * (len(crossings) - 1) / (crossings[-1] - crossings[0])
    print(f"first bending frequency: glissade {measured:.1f} rad/s, "
          f"Euler-Bernoulli {omega:.1f} rad/s, ratio {measured / omega:.4f}")
    return measured


def sweep_point(glissade, output, omega):
    rows = run(glissade, os.path.join(output, f"omega_{omega:g}"),
               [f"Contact tip/Obstacle/Rotation=-{omega:g}*t"])
    last = rows[3 * len(rows) // 4:]
    amplitude = max(abs(float(r[TIP])) for r in last)
    return omega, amplitude, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--glissade", default="build/glissade")
    parser.add_argument("--omegas", default="350:1600:50",
                        help="first:last:step in rad/s")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--output", default="output/blade_casing_study")
    parser.add_argument("--png", default="doc/blade_casing.png")
    args = parser.parse_args()
    first, last, step = (float(v) for v in args.omegas.split(":"))
    omegas = list(np.arange(first, last + 0.5 * step, step))

    omega_1 = free_vibration(args.glissade, args.output)
    results = []
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(sweep_point, args.glissade, args.output, w)
                   for w in omegas]
        for k, future in enumerate(concurrent.futures.as_completed(futures)):
            result = future.result()
            print(f"  [{k + 1}/{len(omegas)}] Omega = {result[0]:g} rad/s: "
                  f"tip amplitude {result[1]:.4g} mm", flush=True)
            results.append(result)
    results.sort(key=lambda r: r[0])
    with open(os.path.join(args.output, "sweep.csv"), "w") as f:
        f.write("omega,omega_over_omega_1,tip_amplitude\n")
        for omega, amplitude, _ in results:
            f.write(f"{omega},{omega / omega_1},{amplitude}\n")

    peak = max(results, key=lambda r: r[1])
    print(f"largest amplitude {peak[1]:.4g} mm at Omega = {peak[0]:g} rad/s "
          f"(2 Omega / omega_1 = {2 * peak[0] / omega_1:.3f})")

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
    left.semilogy([r[0] for r in results], [r[1] for r in results], "o-",
                  markersize=4)
    for n in (2, 4, 6):
        left.axvline(omega_1 / n, color="tab:red", alpha=0.4, linestyle="--")
        left.text(omega_1 / n, left.get_ylim()[1], f" {n}$\\Omega$ = "
                  "$\\omega_1$", color="tab:red", fontsize=8, va="top")
    left.set_xlabel("$\\Omega$ (rad/s)")
    left.set_ylabel("tip amplitude, last quarter (mm)")
    left.set_title("blade tip against the rotation speed "
                   f"($\\omega_1$ = {omega_1:.0f} rad/s)", fontsize=9)
    left.grid(alpha=0.3, which="both")

    rows = peak[2]
    t = np.array([float(r["time"]) for r in rows])
    force = np.array([abs(float(r["tip_Fy"])) for r in rows])
    tail = slice(len(t) // 4, None)
    dt = t[1] - t[0]
    spectrum = np.abs(np.fft.rfft(force[tail] - force[tail].mean()))
    frequency = 2.0 * math.pi * np.fft.rfftfreq(len(force[tail]), dt)
    right.plot(frequency / peak[0], spectrum / spectrum.max(), linewidth=0.8)
    right.axvline(omega_1 / peak[0], color="tab:red", alpha=0.4,
                  linestyle="--")
    right.set_xlim(0, 12)
    right.set_xlabel("frequency / $\\Omega$")
    right.set_ylabel("|FFT| of the radial contact force (scaled)")
    right.set_title(f"contact force spectrum at $\\Omega$ = {peak[0]:g} rad/s"
                    " (dashed: $\\omega_1$)", fontsize=9)
    right.grid(alpha=0.3)
    fig.tight_layout()
    save_atomically(fig, args.png, dpi=100)
    print(f"wrote {args.png} and {os.path.join(args.output, 'sweep.csv')}")


if __name__ == "__main__":
    main()
