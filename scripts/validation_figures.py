#!/usr/bin/python3
"""The figures of docs/validation.md, made with halfspace itself.

Runs the `halfspace` program on the analytic cases (Hertz point and line
contact, Westergaard's wave, the 2D wave in full contact, load against
displacement control) and on self-affine surfaces (kappa), reads the result
files with the project's plotting tool (scripts/halfspace_plot.py, imported)
and draws each comparison with the exact solution. Prints the numbers quoted
in docs/validation.md.

  scripts/validation_figures.py [--halfspace build/bin/halfspace]
                                [--out docs/figures/validation] [--work DIR]

Needs Debian's python3 with matplotlib, h5py and numpy (scripts/install-deps.sh).
"""

import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import halfspace_plot as hp  # noqa: E402  (the project's plotting tool)

plt = hp.plt
import h5py  # noqa: E402

E_STAR = 1e11  # Pa, the analytic cases


def run(program, work, *arguments):
    """halfspace ARGUMENTS, quietly, in `work`; fails loudly."""
    command = [program, *arguments, "--quiet"]
    subprocess.run(command, cwd=work, check=True)


def save(fig, out, name):
    path = os.path.join(out, name)
    fig.savefig(path, dpi=hp.DPI)
    plt.close(fig)
    print(f"wrote {path} ({os.path.getsize(path) // 1024} KB)")
    return path


def sweep_table(path):
    with h5py.File(path, "r") as f:
        return {name: f["sweep"][name][...] for name in f["sweep"]}


def hertz_point(program, work, out):
    """Sphere R = 10 mm, F = 10 N: pressure against radius, all cells."""
    radius, force = 0.01, 10.0
    run(program, work, "solve", "--geometry", "sphere", "--radius", str(radius), "--grid", "128x128",
        "--size", "4e-4", "--E-star", str(E_STAR), "--force", str(force), "--output", "hertz_point.h5")
    result = hp.read_result(os.path.join(work, "hertz_point.h5"))
    a = (3 * force * radius / (4 * E_STAR)) ** (1 / 3)
    p0 = 3 * force / (2 * np.pi * a * a)
    ny, nx = result["pressure"].shape
    x = (np.arange(nx) - (nx - 1) / 2) * result["dx"]
    y = (np.arange(ny) - (ny - 1) / 2) * result["dy"]
    r = np.hypot(*np.meshgrid(x, y)).ravel()
    p = result["pressure"].ravel()
    exact = p0 * np.sqrt(np.clip(1 - (r / a) ** 2, 0, None))
    error = np.max(np.abs(p - exact)) / p0
    approach = result["attrs"]["approach"]
    print(f"Hertz point: a = {a:.4e} m, peak {p.max() / p0:.4f} p0, max |p - p_Hertz| = {error:.4f} p0, "
          f"approach {approach / (a * a / radius):.4f} a^2/R")

    fig, axis = plt.subplots(figsize=(6, 4.2), constrained_layout=True)
    rr = np.linspace(0, 1.5 * a, 300)
    axis.plot(rr / a, p0 * np.sqrt(np.clip(1 - (rr / a) ** 2, 0, None)) / p0, "-", color="0.2", label="Hertz")
    axis.plot(r / a, p / p0, ".", ms=2, color="tab:red", alpha=0.5, label="halfspace, every cell")
    axis.set_xlabel("r / a")
    axis.set_ylabel("p / p0")
    axis.set_xlim(0, 1.5)
    axis.set_title(f"Hertz sphere, 128x128 free grid, a = {a / result['dx']:.1f} cells: max error {100 * error:.1f}% of p0",
                   fontsize="small")
    axis.legend()
    axis.grid(True, alpha=0.3)
    return save(fig, out, "hertz_point.png")


def hertz_line(program, work, out):
    """Cylinder R = 10 mm, P' = 1000 N/m on a 1D free grid."""
    radius, load = 0.01, 1000.0
    run(program, work, "solve", "--geometry", "cylinder", "--radius", str(radius), "--grid", "1024",
        "--size", "2e-4", "--E-star", str(E_STAR), "--force", str(load), "--output", "hertz_line.h5")
    result = hp.read_result(os.path.join(work, "hertz_line.h5"))
    b = np.sqrt(4 * load * radius / (np.pi * E_STAR))
    p0 = 2 * load / (np.pi * b)
    n = result["pressure"].size
    x = (np.arange(n) - (n - 1) / 2) * result["dx"]
    exact = p0 * np.sqrt(np.clip(1 - (x / b) ** 2, 0, None))
    error = np.max(np.abs(result["pressure"] - exact)) / p0
    print(f"Hertz line: b = {b:.4e} m, max |p - p_Hertz| = {error:.4f} p0")
    fig, axis = plt.subplots(figsize=(6, 4.2), constrained_layout=True)
    axis.plot(x / b, exact / p0, "-", color="0.2", label="Hertz")
    axis.plot(x / b, result["pressure"] / p0, ".", ms=3, color="tab:red", label="halfspace")
    axis.set_xlim(-1.5, 1.5)
    axis.set_xlabel("x / b")
    axis.set_ylabel("p / p0")
    axis.set_title(f"Hertz line contact, 1024 cells, b = {b / result['dx']:.0f} cells: "
                   f"max error {100 * error:.2f}% of p0", fontsize="small")
    axis.legend()
    axis.grid(True, alpha=0.3)
    return save(fig, out, "hertz_line.png")


def westergaard(program, work, out):
    """1D periodic wave: contact half-width against mean pressure, a load sweep."""
    wavelength, amplitude, e_star = 1e-4, 1e-6, 2e9
    p_star = np.pi * e_star * amplitude / wavelength
    fractions = [0.02, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95]
    loads = ",".join(f"{f * p_star:.6g}" for f in fractions)
    run(program, work, "solve", "--geometry", "wavy", "--wavelength", str(wavelength), "--amplitude",
        str(amplitude), "--grid", "4096", "--size", str(wavelength), "--boundary", "periodic", "--E-star",
        str(e_star), "--mean-pressure", loads, "--output", "westergaard.h5")
    table = sweep_table(os.path.join(work, "westergaard.h5"))
    half_width = 0.5 * table["contact_fraction"] * wavelength
    exact = wavelength / np.pi * np.arcsin(np.sqrt(table["mean_pressure"] / p_star))
    error = np.max(np.abs(half_width - exact) / exact)
    print(f"Westergaard: {len(fractions)} loads, max relative half-width error {error:.4f}")
    fig, axis = plt.subplots(figsize=(6, 4.2), constrained_layout=True)
    s = np.linspace(0, 1, 200)
    axis.plot(s, np.arcsin(np.sqrt(s)) / np.pi * 2, "-", color="0.2", label="Westergaard: p = p* sin²(πa/λ)")
    axis.plot(table["mean_pressure"] / p_star, 2 * half_width / wavelength, "o", color="tab:red", ms=4,
              label="halfspace sweep, 4096 cells")
    axis.set_xlabel("mean pressure p / p*")
    axis.set_ylabel("contact fraction 2a / λ")
    axis.set_title(f"Westergaard's wave, one warm-started sweep: max error {100 * error:.2f}%", fontsize="small")
    axis.legend()
    axis.grid(True, alpha=0.3)
    return save(fig, out, "westergaard.png")


def wave_2d(program, work, out):
    """2D wave: contact fraction up to full contact at p*, and the exact field above it."""
    wavelength, amplitude = 1e-3, 1e-6
    p_star = np.sqrt(2) * np.pi * E_STAR * amplitude / wavelength
    fractions = [0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1]
    loads = ",".join(f"{f * p_star:.6g}" for f in fractions)
    run(program, work, "solve", "--geometry", "wavy", "--wavelength", str(wavelength), "--amplitude",
        str(amplitude), "--grid", "64x64", "--size", str(wavelength), "--boundary", "periodic", "--E-star",
        str(E_STAR), "--mean-pressure", loads, "--output", "wave2d.h5")
    path = os.path.join(work, "wave2d.h5")
    table = sweep_table(path)
    last = hp.read_result(path)  # the last step, 1.1 p*
    n = last["pressure"].shape[0]
    x = (np.arange(n) - (n - 1) / 2) * last["dx"]
    k = 2 * np.pi / wavelength
    exact = 1.1 * p_star + p_star * np.outer(np.cos(k * x), np.cos(k * x))
    error = np.max(np.abs(last["pressure"] - exact)) / p_star
    print(f"2D wave: contact fraction at p* {table['contact_fraction'][-2]:.4f}, at 1.1 p* "
          f"{table['contact_fraction'][-1]:.4f}; max |p - exact| at 1.1 p* = {error:.2e} p*")
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    left.plot(table["mean_pressure"] / p_star, table["contact_fraction"], "o-", color="tab:red", ms=4)
    left.axvline(1.0, color="0.5", ls="--", lw=1)
    left.set_xlabel("mean pressure p / p*")
    left.set_ylabel("contact fraction A/A0")
    left.set_title("sweep to full contact at p* = √2 π E* Δ / λ", fontsize="small")
    left.grid(True, alpha=0.3)
    row = n // 2
    right.plot(x / wavelength, exact[row] / p_star, "-", color="0.2", label="exact: p̄ + p* cos cos")
    right.plot(x / wavelength, last["pressure"][row] / p_star, ".", color="tab:red", ms=4, label="halfspace")
    right.set_xlabel("x / λ (middle row)")
    right.set_ylabel("p / p*")
    right.set_title(f"p̄ = 1.1 p*, full contact: max error {error:.1e} p*", fontsize="small")
    right.legend()
    right.grid(True, alpha=0.3)
    return save(fig, out, "wave_2d.png")


def control_modes(program, work, out):
    """Hertz sphere: force against approach, by displacement control and by load control."""
    radius = 0.01
    run(program, work, "solve", "--geometry", "sphere", "--radius", str(radius), "--grid", "128x128", "--size",
        "4e-4", "--E-star", str(E_STAR), "--approach", "2e-7:2e-6:6", "--output", "approach.h5")
    run(program, work, "solve", "--geometry", "sphere", "--radius", str(radius), "--grid", "128x128", "--size",
        "4e-4", "--E-star", str(E_STAR), "--force", "0.3:30:6", "--output", "force.h5")
    by_approach = sweep_table(os.path.join(work, "approach.h5"))
    by_force = sweep_table(os.path.join(work, "force.h5"))
    hertz = lambda d: 4 / 3 * E_STAR * np.sqrt(radius) * d ** 1.5  # noqa: E731
    error_a = np.max(np.abs(by_approach["total_force"] - hertz(by_approach["load"])) / hertz(by_approach["load"]))
    error_f = np.max(np.abs(by_force["load"] - hertz(by_force["approach"])) / by_force["load"])
    print(f"control: displacement control max force error {error_a:.4f}, load control {error_f:.4f}")
    fig, axis = plt.subplots(figsize=(6, 4.2), constrained_layout=True)
    d = np.geomspace(6e-8, 2.5e-6, 100)
    axis.loglog(d * 1e6, hertz(d), "-", color="0.2", label="Hertz: F = 4/3 E* R^½ δ^3/2")
    axis.loglog(by_approach["load"] * 1e6, by_approach["total_force"], "o", color="tab:red", ms=6, mfc="none",
                label=f"approach imposed (max error {100 * error_a:.1f}%)")
    axis.loglog(by_force["approach"] * 1e6, by_force["load"], "s", color="tab:blue", ms=4,
                label=f"force imposed (max error {100 * error_f:.1f}%)")
    axis.set_xlabel("approach δ (µm)")
    axis.set_ylabel("force F (N)")
    axis.set_title("Hertz sphere, 128x128 free grid: both controls, two sweeps", fontsize="small")
    axis.legend(fontsize="small")
    axis.grid(True, which="both", alpha=0.3)
    return save(fig, out, "control_modes.png")


def kappa(program, work, out, seeds=(1, 2, 3, 4, 5)):
    """Self-affine surfaces (H = 0.8): A/A0 against p / (E* h'rms)."""
    fig, axis = plt.subplots(figsize=(6.4, 4.6), constrained_layout=True)
    reduced = np.array([0.005, 0.01, 0.02, 0.035, 0.05])
    xs, areas = [], []
    for seed in seeds:
        name = f"rough{seed}.h5"
        run(program, work, "generate", "--kind", "self-affine", "--grid", "512x512", "--size", "512e-6", "--hurst",
            "0.8", "--cutoff-short", "8e-6", "--rms-slope", "0.1", "--seed", str(seed), "--output", name)
        loads = ",".join(f"{x * 1e9 * 0.1:.6g}" for x in reduced)
        run(program, work, "solve", "--height-map", name, "--boundary", "periodic", "--E-star", "1e9",
            "--mean-pressure", loads, "--output", f"sweep{seed}.h5")
        table = sweep_table(os.path.join(work, f"sweep{seed}.h5"))
        x = table["mean_pressure"] / (1e9 * 0.1)
        xs.append(x)
        areas.append(table["contact_fraction"])
        axis.plot(x, table["contact_fraction"], "o", ms=4, alpha=0.8, label=f"seed {seed}")
    x, area = np.concatenate(xs), np.concatenate(areas)
    fitted = np.sum(area * x) / np.sum(x * x)
    print(f"kappa: fitted {fitted:.3f}; per seed " +
          ", ".join(f"{np.sum(a * s) / np.sum(s * s):.3f}" for s, a in zip(xs, areas)))
    line = np.linspace(0, 0.055, 10)
    axis.fill_between(line, 1.8 * line, 2.3 * line, color="0.85", label="BEM literature, κ = 1.8–2.3")
    axis.plot(line, np.sqrt(8 / np.pi) * line, ":", color="0.3", label="Persson, κ = √(8/π) = 1.60")
    axis.plot(line, np.sqrt(2 * np.pi) * line, "--", color="0.3", label="Bush et al., κ = √(2π) = 2.51")
    axis.plot(line, fitted * line, "-", color="tab:red", label=f"fit through the origin, κ = {fitted:.2f}")
    axis.set_xlim(0, 0.055)
    axis.set_ylim(0, 0.14)
    axis.set_xlabel("p / (E* h'rms)")
    axis.set_ylabel("contact fraction A/A0")
    axis.set_title("self-affine, H = 0.8, 512², λs = 8 cells, 5 seeds", fontsize="small")
    axis.legend(fontsize="small", loc="upper left")
    axis.grid(True, alpha=0.3)
    save(fig, out, "kappa.png")
    # The standard maps of one rough contact, drawn by the plotting tool itself.
    written = hp.plot_maps(os.path.join(work, "sweep1.h5"), out=os.path.join(out, "rough_contact_maps.png"), step=2)
    print(f"wrote {written[0]} ({os.path.getsize(written[0]) // 1024} KB)")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser.add_argument("--halfspace", default=os.path.join(root, "build", "bin", "halfspace"))
    parser.add_argument("--out", default=os.path.join(root, "docs", "figures", "validation"))
    parser.add_argument("--work", help="directory for the result files [a temporary one]")
    args = parser.parse_args(argv)
    program = os.path.abspath(args.halfspace)
    os.makedirs(args.out, exist_ok=True)
    with tempfile.TemporaryDirectory() as scratch:
        work = args.work or scratch
        os.makedirs(work, exist_ok=True)
        for figure in (hertz_point, hertz_line, westergaard, wave_2d, control_modes, kappa):
            figure(program, work, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
