#!/usr/bin/python3
"""The subsurface-stress figures of docs/validation.md, made with halfspace.

Solves a Hertz sphere and a self-affine rough contact, runs `halfspace stress`
on each result and draws: the Hertz cross-section (sigma_zz and von Mises in
the x-z plane through the centre, with Johnson's axis solution), the rough
contact's von Mises field (the x-z section through its maximum and the plan
view at that depth), a sphere on a hard coating (the interface stresses) and
a sliding cylinder (gross sliding, q = mu p added to the result as a friction
solve writes it: the surface stress against McEwen and the von Mises field).
Prints the numbers quoted in docs/validation.md.

  scripts/stress_figures.py [--halfspace build/bin/halfspace]
                            [--out docs/figures/validation] [--work DIR]
                            [--only hertz|rough|coated|sliding]

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
import matplotlib.colors  # noqa: E402

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

    fig, axes = plt.subplots(1, 3, figsize=(11.5, 3.6), constrained_layout=True,
                             gridspec_kw={"width_ratios": [1, 1, 0.8]})
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
    run(program, work, "stress", "rough_result.h5", "--depth-range", "0.25e-6:30e-6:60", "--nu", str(NU),
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
    # A square-root colour scale: the hot spots under the asperities are an
    # order of magnitude above the field that spreads between them.
    norm = matplotlib.colors.PowerNorm(0.5, vmin=0.0, vmax=float(vm.max()))
    image = axes[0].imshow(vm[:, row, :], extent=[x[0], x[-1], s["depths"][-1] * 1e6, s["depths"][0] * 1e6],
                           aspect="auto", cmap="magma", norm=norm)
    axes[0].plot(xmax * 1e6, zmax * 1e6, "c+", ms=10)
    fig.colorbar(image, ax=axes[0], label="von Mises (MPa)")
    axes[0].set_xlabel("x (μm)")
    axes[0].set_ylabel("z (μm)")
    axes[0].set_title(f"section y = {ymax * 1e6:.0f} μm through the maximum", fontsize="small")
    image = axes[1].imshow(vm[k], origin="lower", extent=[0, nx * dx * 1e6, 0, ny * dy * 1e6], cmap="magma",
                           norm=norm)
    axes[1].contour(np.arange(nx) * dx * 1e6, np.arange(ny) * dy * 1e6, pressure > 0, [0.5], colors="c",
                    linewidths=0.4)
    fig.colorbar(image, ax=axes[1], label="von Mises (MPa)")
    axes[1].set_xlabel("x (μm)")
    axes[1].set_ylabel("y (μm)")
    axes[1].set_title(f"plan view at z = {s['depths'][k] * 1e6:.2f} μm (cyan: contact patches)", fontsize="small")
    fig.suptitle("self-affine surface, H = 0.8, 256² periodic, p = 2 MPa = 0.02 E* h'rms, ν = 0.3", fontsize="small")
    save(fig, out, "stress_rough.png")


def coated_section(program, work, out):
    """Sphere R = 10 mm, F = 2 N on a hard coating (E1 = 3 E2, t = 20 um) over
    steel, on a 256² periodic grid of period 10 a: the interface stresses."""
    radius, force, t = 0.01, 2.0, 20e-6
    e1, nu1, e2, nu2 = 630e9, 0.25, 210e9, 0.3
    e_substrate = e2 / (1 - nu2 * nu2)
    a_h = (3 * force * radius / (4 * e_substrate)) ** (1 / 3)  # the uncoated substrate's Hertz radius
    p0_h = 3 * force / (2 * np.pi * a_h * a_h)
    depths = np.concatenate([np.linspace(0.5e-6, t, 40), np.linspace(t * (1 + 1e-9), 80e-6, 80)])
    run(program, work, "solve", "--geometry", "sphere", "--radius", str(radius), "--grid", "256x256", "--size",
        "4e-4", "--boundary", "periodic", "--force", str(force), "--layer-thickness", str(t), "--layer-E", str(e1),
        "--layer-nu", str(nu1), "--substrate-E", str(e2), "--substrate-nu", str(nu2), "--output", "coated.h5")
    run(program, work, "stress", "coated.h5", "--depths", ",".join(f"{z:.17g}" for z in depths), "--output",
        "coated_stress.h5")
    s, attrs = read_stress(os.path.join(work, "coated_stress.h5"))
    with h5py.File(os.path.join(work, "coated.h5"), "r") as f:
        pressure = f["pressure"][...]
    nz, ny, nx = s["sigma_zz"].shape
    dx = attrs["dx"]
    # The axis: the cell of largest pressure.
    row, centre = np.unravel_index(int(np.argmax(pressure)), pressure.shape)
    z = s["depths"]
    layer = s["in_layer"].astype(bool)
    above, below = np.flatnonzero(layer)[-1], np.flatnonzero(~layer)[0]
    axis = {name: s[name][:, row, centre] / p0_h for name in ("sigma_xx", "sigma_zz", "von_mises", "max_shear")}
    jump = axis["sigma_xx"][above] - axis["sigma_xx"][below]
    # The in-plane strain is continuous: eps_xx = (sxx - nu (syy + szz)) / E on both sides.
    strain = [(s["sigma_xx"][k, row, centre] - n * (s["sigma_yy"][k, row, centre] + s["sigma_zz"][k, row, centre])) / e
              for k, e, n in ((above, e1, nu1), (below, e2, nu2))]
    k_max = int(np.argmax(axis["von_mises"]))
    print(f"coated: Hertz radius of the substrate a_H = {a_h:.4e} m, p0_H = {p0_h / 1e9:.3f} GPa; peak pressure "
          f"{pressure.max() / p0_h:.3f} p0_H; at the interface on the axis sigma_zz {axis['sigma_zz'][above]:.4f} "
          f"(layer) / {axis['sigma_zz'][below]:.4f} (substrate) p0_H, sigma_xx {axis['sigma_xx'][above]:.4f} / "
          f"{axis['sigma_xx'][below]:.4f} p0_H (jump {jump:.4f}), eps_xx {strain[0]:.4e} / {strain[1]:.4e}; "
          f"max von Mises on the axis {axis['von_mises'][k_max]:.4f} p0_H at z = {z[k_max] * 1e6:.2f} um; in the "
          f"volume {attrs['max_von_mises'] / p0_h:.4f} p0_H at z = {attrs['max_von_mises_z'] * 1e6:.2f} um")

    fig, axes = plt.subplots(1, 3, figsize=(11.5, 3.8), constrained_layout=True,
                             gridspec_kw={"width_ratios": [1, 1, 0.8]})
    x = (np.arange(nx) - centre) * dx / a_h
    keep = np.abs(x) <= 2.5
    zs = z / a_h
    for panel, name, label, cmap in ((axes[0], "sigma_xx", "σxx / p0_H", "RdBu_r"),
                                      (axes[1], "von_mises", "von Mises / p0_H", "magma")):
        field = s[name][:, row, :][:, keep] / p0_h
        if cmap == "RdBu_r":
            limit = float(np.max(np.abs(field)))
            image = panel.pcolormesh(x[keep], zs, field, cmap=cmap, vmin=-limit, vmax=limit, shading="nearest")
        else:
            image = panel.pcolormesh(x[keep], zs, field, cmap=cmap, shading="nearest")
        panel.axhline(t / a_h, color="c", lw=0.8, ls="--")
        panel.invert_yaxis()
        fig.colorbar(image, ax=panel, label=label)
        panel.set_xlabel("x / a_H")
        panel.set_ylabel("z / a_H")
        panel.set_title(f"{label}, section through the centre (cyan: interface)", fontsize="small")
    panel = axes[2]
    panel.plot(axis["sigma_zz"], zs, "-", color="tab:blue", label="σzz (continuous)")
    panel.plot(axis["sigma_xx"], zs, "-", color="tab:red", label="σxx (jumps)")
    panel.plot(axis["von_mises"], zs, "-", color="0.2", label="von Mises")
    zeta = np.linspace(0.01, zs[-1], 200)
    panel.plot(-1 / (1 + zeta ** 2), zeta, ":", color="tab:blue", label="σz uncoated (Johnson)")
    panel.axhline(t / a_h, color="c", lw=0.8, ls="--")
    panel.invert_yaxis()
    panel.set_xlabel("stress / p0_H")
    panel.set_ylabel("z / a_H")
    panel.set_title("on the axis", fontsize="small")
    panel.legend(fontsize="x-small")
    panel.grid(True, alpha=0.3)
    fig.suptitle(f"sphere on a hard coating: E1 = 3 E2, ν1 = {nu1}, ν2 = {nu2}, t = {t / a_h:.2f} a_H, 256² periodic "
                 f"(a_H, p0_H: Hertz on the uncoated substrate)", fontsize="small")
    save(fig, out, "stress_coated.png")


def mcewen_surface_sigma_x(x, mu):
    """McEwen (1949): sigma_x / p0 on the surface of a sliding cylinder, x in
    units of b, the traction mu p along +x on the body."""
    inside = np.abs(x) < 1
    root = np.sqrt(np.abs(x * x - 1))
    normal = np.where(inside, -root, 0.0)
    tangential = np.where(inside, -2 * mu * x, -2 * mu * (x - np.sign(x) * root))
    return normal + tangential


def sliding_section(program, work, out):
    """Cylinder R = 10 mm, P' = 1e5 N/m on a 1D free grid of 256 cells per
    half-width; the result's /shear_x set to mu p (gross sliding along +x)."""
    radius, load, cells = 0.01, 1e5, 256
    b = np.sqrt(4 * load * radius / (np.pi * E_STAR))
    p0 = 2 * load / (np.pi * b)
    n = 4 * cells + 1
    run(program, work, "solve", "--geometry", "cylinder", "--radius", str(radius), "--grid", str(n), "--size",
        repr(n * b / cells), "--E-star", str(E_STAR), "--force", str(load), "--output", "cylinder.h5")
    depths = np.concatenate([[0.01 * b / cells], np.linspace(0.01 * b, 1.2 * b, 120)])
    fields = {}
    for mu in (0.0, 0.2, 0.4):
        name = f"sliding_{mu:.1f}"
        with h5py.File(os.path.join(work, "cylinder.h5"), "r") as source:
            pressure = source["pressure"][...]
        subprocess.run(["cp", os.path.join(work, "cylinder.h5"), os.path.join(work, name + ".h5")], check=True)
        with h5py.File(os.path.join(work, name + ".h5"), "r+") as f:
            f["shear_x"] = mu * pressure
            f["shear_y"] = np.zeros_like(pressure)
        run(program, work, "stress", name + ".h5", "--depths", ",".join(f"{z:.17g}" for z in depths), "--nu",
            str(NU), "--output", name + "_stress.h5")
        fields[mu] = read_stress(os.path.join(work, name + "_stress.h5"))
    dx = fields[0.0][1]["dx"]
    x = (np.arange(n) - (n - 1) / 2) * dx / b
    z = depths / b
    fig, axes = plt.subplots(1, 4, figsize=(14, 3.6), constrained_layout=True)
    keep = np.abs(x) <= 2.0
    vmax = max(float(fields[mu][0]["von_mises"][:, keep].max()) for mu in fields) / p0
    for panel, mu in zip(axes[:3], fields):
        s, attrs = fields[mu]
        vm = s["von_mises"][1:, keep] / p0
        image = panel.pcolormesh(x[keep], z[1:], vm, cmap="magma", vmin=0, vmax=vmax, shading="nearest")
        panel.contour(x[keep], z[1:], vm, 8, colors="white", linewidths=0.4, alpha=0.6)
        xm = attrs["max_von_mises_x"] / b - (n - 1) / 2 * dx / b
        zm = attrs["max_von_mises_z"] / b
        panel.plot(xm, max(zm, z[1]), "c+", ms=10)
        panel.invert_yaxis()
        panel.set_xlabel("x / b")
        panel.set_ylabel("z / b")
        panel.set_title(f"von Mises / p0, μ = {mu}: max {attrs['max_von_mises'] / p0:.3f} at z = {zm:.3f} b",
                        fontsize="small")
        print(f"sliding cylinder, mu = {mu}: max von Mises {attrs['max_von_mises'] / p0:.4f} p0 at x = {xm:.3f} b, "
              f"z = {zm:.4f} b; trailing-edge surface sigma_x "
              f"{s['sigma_xx'][0, np.argmin(np.abs(x + 1))] / p0:.4f} p0 (McEwen {2 * mu:.4f})")
    fig.colorbar(image, ax=axes[2], label="von Mises / p0")
    panel = axes[3]
    xs = np.linspace(-2, 2, 801)
    for mu, colour in ((0.2, "tab:blue"), (0.4, "tab:red")):
        panel.plot(xs, mcewen_surface_sigma_x(xs, mu), "-", color=colour, lw=0.8, label=f"McEwen, μ = {mu}")
        panel.plot(x[keep][::8], fields[mu][0]["sigma_xx"][0, keep][::8] / p0, "o", ms=2.5, color=colour,
                   label=f"halfspace, μ = {mu}")
    panel.axvline(-1, color="0.6", lw=0.6)
    panel.set_xlabel("x / b")
    panel.set_ylabel("σxx / p0 at the surface")
    panel.set_title("surface stress: 2 μ p0 at the trailing edge", fontsize="small")
    panel.legend(fontsize="x-small")
    panel.grid(True, alpha=0.3)
    fig.suptitle(f"sliding cylinder (gross sliding, q = μ p along +x), 1D free grid, b = {cells} cells, ν = {NU}",
                 fontsize="small")
    save(fig, out, "stress_sliding.png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--halfspace", default="build/bin/halfspace")
    parser.add_argument("--out", default="docs/figures/validation")
    parser.add_argument("--work", default=None)
    parser.add_argument("--only", choices=("hertz", "rough", "coated", "sliding"), default=None)
    args = parser.parse_args()
    program = os.path.abspath(args.halfspace)
    os.makedirs(args.out, exist_ok=True)
    with tempfile.TemporaryDirectory() as temporary:
        work = args.work or temporary
        os.makedirs(work, exist_ok=True)
        for name, figure in (("hertz", hertz_section), ("rough", rough_section), ("coated", coated_section),
                             ("sliding", sliding_section)):
            if args.only in (None, name):
                figure(program, work, args.out)


if __name__ == "__main__":
    main()
