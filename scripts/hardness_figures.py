#!/usr/bin/python3
"""The hardness cap on a rough surface (docs/validation.md, "Hardness cap").

Solves the load sweep of examples/hardness_rough.toml twice with the
`halfspace` program, with the hardness cap and without it, and draws the
contact area and the plastic area against the mean pressure next to the
elastic contact area and the rigid-plastic limit F / (H A); a second panel
shows the pressure, the plastic cells and the plastic displacement at the
largest load. Prints the numbers quoted in docs/validation.md.

  scripts/hardness_figures.py [--halfspace build/bin/halfspace]
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

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CONFIG = os.path.join(ROOT, "examples", "hardness_rough.toml")
HARDNESS = 2e7  # Pa, as in the example
LOADS = "5e5:1e7:8"  # Pa: up to half the hardness


def sweep(program, work, name, *extra):
    """The example's sweep over LOADS, with `extra` options; the summary table and the last step."""
    path = os.path.join(work, name)
    subprocess.run([program, "solve", "--config", CONFIG, "--mean-pressure", LOADS, "--output", path, "--quiet",
                    *extra], cwd=work, check=True)
    with h5py.File(path, "r") as f:
        table = {key: f["sweep"][key][...] for key in f["sweep"]}
        last = sorted(f["steps"])[-1]
        fields = {key: f["steps"][last][key][...] for key in f["steps"][last] if key != "cluster_sizes"}
    return table, fields


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--halfspace", default=os.path.join(ROOT, "build", "bin", "halfspace"))
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "figures", "validation"))
    parser.add_argument("--work", default=None, help="directory for the result files [a temporary one]")
    args = parser.parse_args()
    args.halfspace = os.path.abspath(args.halfspace)
    work = args.work or tempfile.mkdtemp(prefix="hardness_figures_")
    os.makedirs(args.out, exist_ok=True)

    capped, fields = sweep(args.halfspace, work, "capped.h5")
    # The elastic sweep: the same config with the cap lifted far above every pressure.
    elastic, _ = sweep(args.halfspace, work, "elastic.h5", "--hardness", "1e13")
    load = capped["mean_pressure"]
    bearing = load / HARDNESS
    print("mean pressure (MPa), contact elastic, contact capped, plastic, F/(H A)")
    for k in range(len(load)):
        print(f"  {load[k] / 1e6:6.2f}  {elastic['contact_fraction'][k]:.4f}  {capped['contact_fraction'][k]:.4f}"
              f"  {capped['plastic_fraction'][k]:.4f}  {bearing[k]:.4f}"
              f"  ({int(elastic['iterations'][k])} / {int(capped['iterations'][k])} iterations)")

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.3))
    mpa = load / 1e6
    left.plot(mpa, elastic["contact_fraction"], "o-", label="contact, elastic")
    left.plot(mpa, capped["contact_fraction"], "s-", label=f"contact, hardness {HARDNESS / 1e6:g} MPa")
    left.plot(mpa, capped["plastic_fraction"], "^-", label="plastic (at the cap)")
    left.plot(mpa, bearing, "k--", label="rigid-plastic limit F / (H A)")
    left.set_xlabel("mean pressure (MPa)")
    left.set_ylabel("area fraction")
    left.set_title("Self-affine surface, E* = 1 GPa, H / E* = 0.02")
    left.grid(True, alpha=0.3)
    left.legend(fontsize=8)

    displacement = fields["plastic_displacement"] * 1e9
    image = right.imshow(np.where(fields["plastic"] > 0, displacement, np.nan), origin="lower", cmap="viridis")
    right.contour(fields["contact"], levels=[0.5], colors="0.6", linewidths=0.5)
    fig.colorbar(image, ax=right, label="plastic displacement (nm)")
    right.set_title(f"plastic cells at {mpa[-1]:g} MPa (grey: contact edge)")
    right.set_xlabel("x (cells)")
    right.set_ylabel("y (cells)")
    fig.tight_layout()
    path = os.path.join(args.out, "hardness_rough.png")
    fig.savefig(path, dpi=hp.DPI)
    plt.close(fig)
    print(f"wrote {path} ({os.path.getsize(path) // 1024} KB)")


if __name__ == "__main__":
    main()
