#!/usr/bin/python3
"""The adhesion figures of docs/validation.md, made with halfspace itself.

1. adhesion_rough.png: the loading-unloading sweep of examples/adhesion_rough.toml
   (an adhesive self-affine surface): total force against approach, loading and
   unloading drawn apart, so the hysteresis shows, with the pull-off force.
2. adhesion_sphere.png: a Maugis-Dugdale sphere at Tabor parameter lambda = 3
   swept in and out, in Maugis's units, against the JKR curve and the JKR and
   DMT pull-off forces.

Prints the numbers quoted in docs/validation.md.

  scripts/adhesion_figures.py [--halfspace build/bin/halfspace]
                              [--out docs/figures/validation] [--work DIR]

Needs Debian's python3 with matplotlib, h5py and numpy (scripts/install-deps.sh).
"""

import argparse
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import halfspace_plot as hp  # noqa: E402  (the project's plotting tool)

plt = hp.plt
import h5py  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(program, work, *arguments):
    """halfspace ARGUMENTS, quietly, in `work`; fails loudly."""
    subprocess.run([program, *arguments, "--quiet", "--threads", "1"], cwd=work, check=True)


def sweep_curve(path):
    """(approach, total force, pull-off force) of a sweep result."""
    with h5py.File(path, "r") as f:
        return f["sweep/approach"][()], f["sweep/total_force"][()], float(f.attrs["pull_off_force"])


def branches(approach, force):
    """The loading part (up to the deepest approach) and the unloading part."""
    deepest = int(np.argmax(approach))
    return (approach[: deepest + 1], force[: deepest + 1]), (approach[deepest:], force[deepest:])


def rough_figure(program, work, out):
    result = os.path.join(work, "adhesion_rough.h5")
    run(program, work, "solve", "--config", os.path.join(ROOT, "examples", "adhesion_rough.toml"), "--output", result)
    approach, force, pull_off = sweep_curve(result)
    (a_in, f_in), (a_out, f_out) = branches(approach, force)
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot(a_in * 1e9, f_in * 1e3, "o-", label="loading")
    ax.plot(a_out * 1e9, f_out * 1e3, "s--", label="unloading")
    ax.axhline(pull_off * 1e3, color="grey", lw=0.8, ls=":", label=f"pull-off {pull_off * 1e3:.3g} mN")
    ax.axhline(0.0, color="black", lw=0.5)
    ax.set_xlabel("approach (nm)")
    ax.set_ylabel("total force (mN)")
    ax.set_title("Adhesive self-affine surface (Maugis-Dugdale), 128 x 128 periodic")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "adhesion_rough.png"), dpi=120)
    print(f"rough: pull-off {pull_off:.4g} N; forces {np.array2string(force, precision=3)}")


def sphere_figure(program, work, out):
    # R = 1 mm, E* = 1 MPa, w = 0.05 J/m^2: ell = (pi w R^2 / K)^(1/3), K = 4E*/3.
    radius, e_star, work_of_adhesion, lam = 1e-3, 1e6, 0.05, 3.0
    k = 4.0 * e_star / 3.0
    ell = (math.pi * work_of_adhesion * radius**2 / k) ** (1.0 / 3.0)
    sigma0 = 0.5 * lam * k * ell / radius
    unit = ell**2 / radius
    cells_per_ell, width = 24, 4.0
    n = int(round(width * cells_per_ell))
    approaches = [0.2, 0.6, 1.0, 0.6, 0.2, 0.0, -0.2, -0.4, -0.5, -0.6, -0.7, -0.8, -0.9, -1.0, -1.1, -1.2]
    result = os.path.join(work, "adhesion_sphere.h5")
    run(program, work, "solve", "--geometry", "sphere", "--radius", str(radius), "--grid", f"{n}x{n}",
        "--size", str(width * ell), "--E-star", str(e_star), "--adhesion", "md",
        "--work-of-adhesion", str(work_of_adhesion), "--adhesion-stress", str(sigma0),
        "--approach=" + ",".join(f"{a * unit:.6g}" for a in approaches), "--output", result)
    approach, force, pull_off = sweep_curve(result)
    force_unit = math.pi * work_of_adhesion * radius
    (a_in, f_in), (a_out, f_out) = branches(approach / unit, force / force_unit)
    # JKR in Maugis's units: P = A^3 - sqrt(6 A^3), Delta = A^2 - (2/3) sqrt(6 A).
    a_bar = np.linspace(0.05, 1.8, 300)
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot(a_bar**2 - (2.0 / 3.0) * np.sqrt(6.0 * a_bar), a_bar**3 - np.sqrt(6.0 * a_bar**3), "k-", lw=1,
            label="JKR")
    ax.plot(a_in, f_in, "o-", label="loading (halfspace)")
    ax.plot(a_out, f_out, "s--", label="unloading (halfspace)")
    ax.axhline(-1.5, color="grey", lw=0.8, ls=":", label="JKR pull-off -3/2")
    ax.axhline(-2.0, color="grey", lw=0.8, ls="-.", label="DMT pull-off -2")
    ax.set_xlabel(r"approach / ($\ell^2/R$)")
    ax.set_ylabel(r"force / ($\pi w R$)")
    ax.set_title(rf"Maugis-Dugdale sphere, $\lambda$ = {lam:g}, {cells_per_ell} cells per $\ell$")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "adhesion_sphere.png"), dpi=120)
    print(f"sphere: pull-off {pull_off / force_unit:.4f} pi w R (Maugis at lambda = 3: -1.517; JKR -1.5)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--halfspace", default=os.path.join(ROOT, "build", "bin", "halfspace"))
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "figures", "validation"))
    parser.add_argument("--work", default=None)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    with tempfile.TemporaryDirectory() as scratch:
        work = args.work or scratch
        rough_figure(args.halfspace, work, args.out)
        sphere_figure(args.halfspace, work, args.out)


if __name__ == "__main__":
    main()
