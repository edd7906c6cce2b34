"""The blade/casing wear study of prm/blade_casing_wear.prm (issue 51): a
blade in its turning frame cutting the abradable coating of its casing,
swept over the rotation speed Omega. Draws the interaction map (the tip's
spectrum against Omega, with the blade's first frequency on Southwell's
line and the engine orders k Omega), the tip's amplitude, the worn
profile's number of lobes against the engine order that meets the blade at
each critical speed, and what changes when the coating cannot wear.

    /usr/bin/python3 scripts/blade_wear_study.py [--glissade build/glissade]
        [--omegas 500:1200:25] [--jobs 2] [--output output/blade_wear_study]
        [--png doc/blade_wear.png]

Every run is glissade itself on the .prm, its entries changed by --set. For
each Omega:
  spin-up: the casing out of reach, the blade spun up to Omega; the
    leading corner's radius once spun up sets the casing's radius (the
    clearance 0.01 and the coating's 0.5 over it), as the .prm's is set
    for Omega_3;
  wear: the .prm at Omega (Angular velocity, the casing's Rotation, the end
    time: spin-up, ten revolutions of incursion, four more); the tip's
    amplitude is half the swing of its tangential displacement over the
    incursion's last five revolutions (its slow drift taken off), its
    spectrum over the same window; the lobes are the worn profile's largest
    Fourier harmonic at the end of the run.
Omega_n = omega_0 / sqrt(n^2 - k), with omega_0 Euler-Bernoulli's and
k = 3.335 Southwell's coefficient for this root radius (the closed forms of
tests/dynamics_turning_frame_test.cc), are the critical speeds. At Omega_3
and Omega_4 the run is repeated with a coating that cannot yield (a rigid
casing at the same incursion). Writes sweep.csv beside the runs.
"""
import argparse
import concurrent.futures
import csv
import math
import os

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic_png import save_atomically  # noqa: E402
from scene_run import run_scene  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
PRM = os.path.join(HERE, "..", "prm", "blade_casing_wear.prm")
# The blade of the .prm: E, rho, thickness h, length L; its leading corner.
E, RHO, H, L = 110000.0, 4.4e-9, 5.0, 100.0
CORNER = (32.5, 300.0)
UX, UY = "blade_ux_32p5_300", "blade_uy_32p5_300"
SPIN_UP = 0.02
CLEARANCE, COATING, INCURSION = 0.01, 0.5, 0.11
DT = 5e-5
SOUTHWELL_K = 1.1933 - 1.0 + 1.5709 * 200.0 / L


def omega_0():
    return 1.8751 ** 2 * H / L ** 2 * math.sqrt(E / (12.0 * RHO))


def critical_speed(n):
    return omega_0() / math.sqrt(n * n - SOUTHWELL_K)


def spin(omega):
    """The turning frame's Angular velocity and the casing's Rotation."""
    s = f"(t/{SPIN_UP})"
    velocity = f"{omega:g}*(t < {SPIN_UP} ? {s}^2*(3 - 2*{s}) : 1)"
    angle = (f"{omega:g}*(t < {SPIN_UP} ? t^3/{SPIN_UP}^2 - "
             f"t^4/(2*{SPIN_UP}^3) : t - {SPIN_UP / 2})")
    return [f"Body blade/Turning frame/Angular velocity={velocity}",
            f"Contact tip/Obstacle/Rotation=-({angle})"]


def run(glissade, directory, settings):
    return run_scene(glissade, PRM, directory, settings, "blade_wear_study")


def spun_up_radius(glissade, output, omega):
    """The leading corner's radius once spun up, the casing out of reach."""
    end = SPIN_UP + 0.005
    rows = run(glissade, os.path.join(output, f"spin_up_{omega:g}"),
               spin(omega) + [
                   "Contact tip/Obstacle/Radius=330",
                   "Body blade/Boundary conditions/Prescribed displacement="
                   "bottom: y: 0",
                   f"Load program/Stage end times={end}",
                   f"Load program/Stage increments={round(end / DT)}"])
    tail = [r for r in rows if float(r["time"]) > SPIN_UP]
    return np.mean([math.hypot(CORNER[0] + float(r[UX]),
                               CORNER[1] + float(r[UY])) for r in tail])


def harmonics(profile):
    """Amplitudes of the worn profile's Fourier harmonics 0, 1, ..."""
    return 2.0 * np.abs(np.fft.rfft(profile - profile.mean())) / len(profile)


def last_profile(directory):
    rows = list(csv.DictReader(open(os.path.join(directory,
                                                 "coating-tip.csv"))))
    last = max(float(r["time"]) for r in rows)
    return np.array([float(r["worn_depth"]) for r in rows
                     if float(r["time"]) == last])


def wear_run(glissade, output, omega, rigid=False):
    radius = spun_up_radius(glissade, output, omega)
    revolution = 2.0 * math.pi / omega
    incursion_time = 10.0 * revolution
    end = SPIN_UP + 14.0 * revolution
    name = f"{'rigid' if rigid else 'wear'}_{omega:g}"
    directory = os.path.join(output, name)
    settings = spin(omega) + [
        f"Contact tip/Obstacle/Radius={radius + CLEARANCE + COATING}",
        "Body blade/Boundary conditions/Prescribed displacement=bottom: y: "
        f"{INCURSION}*min(max(t - {SPIN_UP}, 0)/{incursion_time}, 1)",
        f"Load program/Stage end times={end}",
        f"Load program/Stage increments={round(end / DT)}"]
    if rigid:
        settings.append("Contact tip/Obstacle/Coating yield pressure=1e6")
    rows = run(glissade, directory, settings)
    t = np.array([float(r["time"]) for r in rows])
    ux = np.array([float(r[UX]) for r in rows])
    force = np.array([float(r["tip_Fy"]) for r in rows])
    window = (t > SPIN_UP + 5.0 * revolution) & (
        t <= SPIN_UP + incursion_time)
    swing = ux[window] - np.polyval(np.polyfit(t[window], ux[window], 1),
                                    t[window])
    spectrum = np.abs(np.fft.rfft(swing * np.hanning(len(swing))))
    frequency = 2.0 * math.pi * np.fft.rfftfreq(len(swing), DT)
    profile = last_profile(directory)
    amplitudes = harmonics(profile)
    lobes = int(np.argmax(amplitudes[1:60])) + 1
    others = np.delete(amplitudes[1:60], lobes - 1)
    return dict(omega=omega, rigid=rigid,
                amplitude=0.5 * (swing.max() - swing.min()),
                mean_force=-force[window].mean(), lobes=lobes,
                lobe_amplitude=amplitudes[lobes],
                next_harmonic=others.max(), worn_depth=profile.max(),
                profile=profile, frequency=frequency, spectrum=spectrum)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--glissade", default="build/glissade")
    parser.add_argument("--omegas", default="500:1200:25",
                        help="first:last:step in rad/s")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--output", default="output/blade_wear_study")
    parser.add_argument("--png", default="doc/blade_wear.png")
    args = parser.parse_args()
    first, last, step = (float(v) for v in args.omegas.split(":"))
    critical = {n: critical_speed(n) for n in (3, 4, 5)}
    omegas = sorted(set(list(np.arange(first, last + 0.5 * step, step))
                        + [round(w, 1) for w in critical.values()
                           if first <= w <= last]))
    jobs = [(w, False) for w in omegas] + [(critical[n], True)
                                             for n in (3, 4)]
    results = []
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(wear_run, args.glissade, args.output,
                               round(w, 1), rigid) for w, rigid in jobs]
        for k, future in enumerate(concurrent.futures.as_completed(futures)):
            r = future.result()
            print(f"  [{k + 1}/{len(jobs)}] Omega = {r['omega']:g} rad/s"
                  f"{' (rigid casing)' if r['rigid'] else ''}: tip amplitude "
                  f"{r['amplitude']:.4g} mm, mean force {r['mean_force']:.3g}"
                  f" N/mm, {r['lobes']} lobes of {r['lobe_amplitude']:.3g} "
                  f"mm (next harmonic {r['next_harmonic']:.2g})", flush=True)
            results.append(r)
    sweep = sorted((r for r in results if not r["rigid"]),
                   key=lambda r: r["omega"])
    rigid = {round(r["omega"], 1): r for r in results if r["rigid"]}
    os.makedirs(args.output, exist_ok=True)
    with open(os.path.join(args.output, "sweep.csv"), "w") as f:
        f.write("omega,rigid,tip_amplitude,mean_contact_force,lobes,"
                "lobe_amplitude,next_harmonic,worn_depth\n")
        for r in sweep + list(rigid.values()):
            f.write(f"{r['omega']},{int(r['rigid'])},{r['amplitude']},"
                    f"{r['mean_force']},{r['lobes']},{r['lobe_amplitude']},"
                    f"{r['next_harmonic']},{r['worn_depth']}\n")
    for n, w in critical.items():
        at = [r for r in sweep if abs(r["omega"] - round(w, 1)) < 1e-6]
        if at:
            r = at[0]
            print(f"Omega_{n} = {w:.1f} rad/s: {r['lobes']} lobes "
                  f"(engine order {n}), {r['lobe_amplitude']:.3g} mm, next "
                  f"harmonic {r['next_harmonic']:.2g} mm")
            if round(w, 1) in rigid:
                q = rigid[round(w, 1)]
                print(f"  coating that cannot wear: tip amplitude "
                      f"{q['amplitude']:.4g} mm against {r['amplitude']:.4g},"
                      f" mean contact force {q['mean_force']:.3g} against "
                      f"{r['mean_force']:.3g} N/mm")

    fig, axes = plt.subplots(2, 2, figsize=(12, 8.5))
    (spectra, amplitude), (lobes, profiles) = axes
    w = np.array([r["omega"] for r in sweep])
    top = 6.0 * w.max()
    grid = np.linspace(0.0, top, 400)
    image = np.zeros((len(grid), len(sweep)))
    for j, r in enumerate(sweep):
        s = np.interp(grid, r["frequency"], r["spectrum"])
        image[:, j] = np.log10(s / r["spectrum"].max() + 1e-6)
    spectra.pcolormesh(w, grid, image, shading="nearest", cmap="viridis",
                       vmin=-3, vmax=0)
    line = np.linspace(w.min(), w.max(), 100)
    spectra.plot(line, np.sqrt(omega_0() ** 2 + SOUTHWELL_K * line ** 2),
                 color="white", linewidth=1.5,
                 label="$\\omega_1(\\Omega)$, Southwell")
    for k in range(2, 7):
        spectra.plot(line, k * line, color="tab:red", linewidth=0.8,
                     linestyle="--", label="k $\\Omega$, k = 2 ... 6 (from "
                     "below)" if k == 2 else None)
    spectra.set_ylim(0, top)
    spectra.set_xlabel("$\\Omega$ (rad/s)")
    spectra.set_ylabel("frequency (rad/s)")
    spectra.set_title("interaction map: spectrum of the tip's tangential "
                      "motion (log, scaled per $\\Omega$)", fontsize=9)
    spectra.legend(fontsize=8, loc="lower right")

    amplitude.semilogy(w, [r["amplitude"] for r in sweep], "o-",
                       markersize=4, label="coating wears")
    for omega, q in rigid.items():
        amplitude.semilogy([omega], [q["amplitude"]], "s", color="tab:red",
                           label="coating cannot wear" if omega ==
                           min(rigid) else None)
    lobes.plot(w, [r["lobes"] for r in sweep], "o", markersize=5,
               label="lobes of the worn profile")
    for n, omega in critical.items():
        for ax in (amplitude, lobes):
            ax.axvline(omega, color="tab:red", alpha=0.4, linestyle="--")
        lobes.plot([omega], [n], "x", color="tab:red", markersize=10,
                   label="engine order n at $\\Omega_n$" if n == 3 else None)
    amplitude.set_xlabel("$\\Omega$ (rad/s)")
    amplitude.set_ylabel("tip amplitude, tangential (mm)")
    amplitude.set_title("tip amplitude over the incursion (dashed: "
                        "$\\Omega_n$ = $\\omega_0 / \\sqrt{n^2 - k}$)",
                        fontsize=9)
    amplitude.legend(fontsize=8)
    amplitude.grid(alpha=0.3, which="both")
    lobes.set_ylim(0, 12)
    lobes.set_xlabel("$\\Omega$ (rad/s)")
    lobes.set_ylabel("largest harmonic of the worn profile")
    lobes.set_title("lobes of the worn coating after 14 revolutions",
                    fontsize=9)
    lobes.legend(fontsize=8)
    lobes.grid(alpha=0.3)

    for n in (3, 4):
        at = [r for r in sweep if abs(r["omega"] - round(critical[n], 1))
              < 1e-6]
        if at:
            p = at[0]["profile"]
            angle = np.linspace(0.0, 360.0, len(p), endpoint=False)
            profiles.plot(angle, 1000.0 * (p - p.mean()), linewidth=1.0,
                          label=f"$\\Omega_{n}$ = {critical[n]:.0f} rad/s")
    profiles.set_xlabel("angle round the casing (degrees)")
    profiles.set_ylabel("worn depth - mean (micrometres)")
    profiles.set_title("worn profiles at the critical speeds", fontsize=9)
    profiles.legend(fontsize=8)
    profiles.grid(alpha=0.3)
    fig.tight_layout()
    save_atomically(fig, args.png, dpi=100)
    print(f"wrote {args.png} and {os.path.join(args.output, 'sweep.csv')}")


if __name__ == "__main__":
    main()
