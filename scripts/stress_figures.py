#!/usr/bin/python3
"""The subsurface-stress figures of docs/validation.md, made with halfspace.

Solves a Hertz sphere and a self-affine rough contact, runs `halfspace stress`
on each result and draws: the Hertz cross-section (sigma_zz and von Mises in
the x-z plane through the centre, with Johnson's axis solution), and the
rough contact's von Mises field (the x-z section through its maximum and the
plan view at that depth). Prints the numbers quoted in docs/validation.md.

  scripts/stress_figures.py [--halfspace build/bin/halfspace]
                            [--out docs/figures/validation] [--work DIR]

Needs Debian's python3 with matplotlib, h5py and numpy (scripts/install-deps.sh).
"""

import argparse
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import halfspace_plot as hp  # noqa: E402  (the project's plotting tool)

plt = hp.plt
E_STAR = 1e11  # Pa
NU = 0.3


def run(program, work, *arguments):
    subprocess.run([program, *arguments, "--quiet"], cwd=work, check=True)


def save(fig, out, name):
    path = os.path.join(out, name)
    fig.savefig(path, dpi=hp.DPI)
    plt.close(fig)
    print(f"wrote {path} ({os.path.getsize(path) // 1024} KB)")


def read_stress(path):
    with h5py.File(path, "r") as f:
        fields = {name: f["stress"][name][...] for name in f["stress"]}
        attrs = {key: f.attrs[key] for key in f.attrs}
    return fields, attrs


def hertz_section(program, work, out):
    """Sphere R = 10 mm, F = 10 N on a 128x128 free grid: x-z section."""
    radius, force = 0.01, 10.0
    a = (3 * force * radius / (4 * E_STAR)) ** (1 / 3)
    p0 = 3 * force / (2 * np.pi * a * a)
    run(program, work, "solve", "--geometry", "sphere", "--radius", str(radius), "--grid", "129x129", "--size",
        "4e-4", "--E-star", str(E_STAR), "--force", str(force), "--output", "hertz.h5")
    run(program, work, "stress", "hertz.h5", "--depth-range", f"{0.02 * a}:{2.0 * a}:100", "--nu", str(NU),
        "--output", "hertz_stress.h5")
    s, attrs = read_stress(os.path.join(work, "hertz_stress.h5"))
    nz, ny, nx = s["sigma_zz"].shape
    dx = attrs["dx"]
    x = (np.arange(nx) - (nx - 1) / 2) * dx / a
    z = s["depths"] / a
    row = (ny - 1) // 2
    centre = (nx - 1) // 2
    # Johnson (1985) eq. 3.45 on the axis.
    szz = -1 / (1 + z * z)
    srr = -(1 + NU) * (1 - z * np.arctan(1 / z)) + 0.5 / (1 + z * z)
    axis_error = max(np.max(np.abs(s["sigma_zz"][:, row, centre] / p0 - szz)),
                     np.max(np.abs(s["sigma_xx"][:, row, centre] / p0 - srr)))
    tau = s["max_shear"][:, row, centre] / p0
    k = int(np.argmax(tau))
    print(f"Hertz: a = {a:.4e} m ({a / dx:.1f} cells), axis stresses within {axis_error:.4f} p0 of Johnson; "
          f"max shear {tau[k]:.4f} p0 at z = {z[k]:.3f} a; max von Mises {attrs['max_von_mises'] / p0:.4f} p0 "
          f"at z = {attrs['max_von_mises_z'] / a:.3f} a")

    fig, axes = plt.subplots(1, 3, figsize=(12.5, 3.9), constrained_layout=True,
                             gridspec_kw={"width_ratios": [1, 1, 0.8]})
    extent = [x[0], x[-1], z[-1], z[0]]
    keep = np.abs(x) <= 2.0
    for axis, name, label, cmap in ((axes[0], "sigma_zz", "σzz / p0", "viridis"),
                                     (axes[1], "von_mises", "von Mises / p0", "magma")):
        field = s[name][:, row, :] / p0
        image = axis.imshow(field[:, keep], extent=[x[keep][0], x[keep][-1], z[-1], z[0]], aspect="auto", cmap=cmap)
        axis.contour(x[keep], z, field[:, keep], 8, colors="white", linewidths=0.5, alpha=0.6)
        fig.colorbar(image, ax=axis, label=label)
        axis.set_xlabel("x / a")
        axis.set_ylabel("z / a")
        axis.set_title(f"{label}, section y = 0", fontsize="small")
    del extent
    axis = axes[2]
    axis.plot(szz, z, "-", color="0.2", label="Johnson σz")
    axis.plot(srr, z, "--", color="0.2", label="Johnson σr")
    axis.plot(s["sigma_zz"][::3, row, centre] / p0, z[::3], "o", ms=3, color="tab:blue", label="halfspace σzz")
    axis.plot(s["sigma_xx"][::3, row, centre] / p0, z[::3], "s", ms=3, color="tab:red", label="halfspace σxx")
    axis.plot(tau, z, "-", color="tab:green", label="max shear τ1")
    axis.axhline(0.48, color="0.6", lw=0.6)
    axis.invert_yaxis()
    axis.set_xlabel("stress / p0")
    axis.set_ylabel("z / a")
    axis.set_title(f"on the axis: τ1 max {tau[k]:.3f} p0 at {z[k]:.2f} a", fontsize="small")
    axis.legend(fontsize="x-small")
    axis.grid(True, alpha=0.3)
    fig.suptitle(f"Hertz sphere, 129² free grid, a = {a / dx:.1f} cells, ν = {NU}", fontsize="small")
    save(fig, out, "stress_hertz.png")


def rough_section(program, work, out):
    """Self-affine surface (H = 0.8) on a 256² periodic grid: von Mises."""
    run(program, work, "generate", "--kind", "self-affine", "--grid", "256x256", "--size", "256e-6", "--hurst",
        "0.8", "--cutoff-short", "4e-6", "--rms-slope", "0.1", "--seed", "3", "--output", "rough.h5")
    run(program, work, "solve", "--height-map", "rough.h5", "--boundary", "periodic", "--E-star", "1e9",
        "--mean-pressure", "2e6", "--output", "rough_result.h5")
    run(program, work, "stress", "rough_result.h5", "--depth-range", "0.25e-6:40e-6:80", "--nu", str(NU),
        "--output", "rough_stress.h5")
    s, attrs = read_stress(os.path.join(work, "rough_stress.h5"))
    nz, ny, nx = s["von_mises"].shape
    dx, dy = attrs["dx"], attrs["dy"]
    with h5py.File(os.path.join(work, "rough_result.h5"), "r") as f:
        pressure = f["pressure"][...]
    vm = s["von_mises"] / 1e6
    zmax, xmax, ymax = attrs["max_von_mises_z"], attrs["max_von_mises_x"], attrs["max_von_mises_y"]
    row = int(round(ymax / dy))
    k = int(np.argmin(np.abs(s["depths"] - zmax)))
    mean_vm = vm.reshape(nz, -1).mean(axis=1)
    print(f"rough: max von Mises {attrs['max_von_mises'] / 1e6:.1f} MPa at z = {zmax * 1e6:.2f} um; "
          f"max pressure {pressure.max() / 1e6:.1f} MPa; mean von Mises {mean_vm[0]:.2f} MPa at "
          f"{s['depths'][0] * 1e6:.2f} um, {mean_vm[-1]:.2f} MPa at {s['depths'][-1] * 1e6:.0f} um")

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.4), constrained_layout=True)
    x = np.arange(nx) * dx * 1e6
    image = axes[0].imshow(vm[:, row, :], extent=[x[0], x[-1], s["depths"][-1] * 1e6, s["depths"][0] * 1e6],
                           aspect="auto", cmap="magma")
    axes[0].plot(xmax * 1e6, zmax * 1e6, "c+", ms=10)
    fig.colorbar(image, ax=axes[0], label="von Mises (MPa)")
    axes[0].set_xlabel("x (μm)")
    axes[0].set_ylabel("z (μm)")
    axes[0].set_title(f"section y = {ymax * 1e6:.0f} μm through the maximum", fontsize="small")
    image = axes[1].imshow(vm[k], origin="lower", extent=[0, nx * dx * 1e6, 0, ny * dy * 1e6], cmap="magma")
    axes[1].contour(np.arange(nx) * dx * 1e6, np.arange(ny) * dy * 1e6, pressure > 0, [0.5], colors="c",
                    linewidths=0.4)
    fig.colorbar(image, ax=axes[1], label="von Mises (MPa)")
    axes[1].set_xlabel("x (μm)")
    axes[1].set_ylabel("y (μm)")
    axes[1].set_title(f"plan view at z = {s['depths'][k] * 1e6:.2f} μm (cyan: contact patches)", fontsize="small")
    fig.suptitle("self-affine surface, H = 0.8, 256² periodic, p = 2 MPa = 0.02 E* h'rms, ν = 0.3", fontsize="small")
    save(fig, out, "stress_rough.png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--halfspace", default="build/bin/halfspace")
    parser.add_argument("--out", default="docs/figures/validation")
    parser.add_argument("--work", default=None)
    args = parser.parse_args()
    program = os.path.abspath(args.halfspace)
    os.makedirs(args.out, exist_ok=True)
    with tempfile.TemporaryDirectory() as temporary:
        work = args.work or temporary
        os.makedirs(work, exist_ok=True)
        hertz_section(program, work, args.out)
        rough_section(program, work, args.out)


if __name__ == "__main__":
    main()
