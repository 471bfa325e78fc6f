#!/usr/bin/env python3
"""The gallery's pictures that `halfspace solve --plot` does not draw
(docs/gallery.md), from the result files alone (h5py, matplotlib, numpy).

  draw.py hardness ELASTIC.h5 CAPPED.h5 --out PNG
  draw.py adhesion SWEEP.h5 --out PNG
  draw.py coated COATED.h5 HOMOGENEOUS.h5 --out PNG
  draw.py von-mises STRESS.h5 --out PNG
"""

import argparse

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

UM = 1e6


def centre_row(path, field="pressure"):
    """x (m, from the centre) and the field along the middle row."""
    with h5py.File(path) as f:
        values = f[field][()]
        dx = f.attrs["dx"]
    row = values[values.shape[0] // 2]
    x = (np.arange(row.size) - (row.size - 1) / 2) * dx
    return x, row


def hardness(args):
    fig, ax = plt.subplots(figsize=(5.5, 3.4))
    x, elastic = centre_row(args.files[0])
    _, capped = centre_row(args.files[1])
    with h5py.File(args.files[1]) as f:
        cap = f.attrs["hardness"]
        plastic = f["plastic"][()][f["plastic"].shape[0] // 2].astype(bool)
    ax.plot(x * UM, elastic / 1e9, color="0.5", label="elastic (Hertz)")
    ax.plot(x * UM, capped / 1e9, color="tab:red", label="hardness cap")
    ax.fill_between(x * UM, 0, capped / 1e9, where=plastic, color="tab:red", alpha=0.2, label="plastic cells")
    ax.axhline(cap / 1e9, color="tab:red", lw=0.6, ls=":")
    ax.set(xlabel="x (µm)", ylabel="pressure (GPa)", title="same force, pressure capped at H")
    ax.legend(frameon=False, fontsize=8)
    save(fig, args.out)


def adhesion(args):
    with h5py.File(args.files[0]) as f:
        approach = f["sweep/approach"][()]
        force = f["sweep/total_force"][()]
        pull_off = f.attrs["pull_off_force"]
    turn = int(np.argmax(approach))
    fig, ax = plt.subplots(figsize=(5.5, 3.4))
    ax.plot(approach[: turn + 1] * UM, force[: turn + 1] * 1e3, "o-", color="tab:blue", ms=3, label="loading")
    ax.plot(approach[turn:] * UM, force[turn:] * 1e3, "s--", color="tab:orange", ms=3, label="unloading")
    ax.axhline(0, color="0.7", lw=0.6)
    if np.isfinite(pull_off):
        ax.axhline(pull_off * 1e3, color="tab:orange", lw=0.6, ls=":", label=f"pull-off {pull_off * 1e3:.3g} mN")
    ax.set(xlabel="approach (µm)", ylabel="force (mN)", title="Maugis–Dugdale sphere")
    ax.legend(frameon=False, fontsize=8)
    save(fig, args.out)


def coated(args):
    fig, ax = plt.subplots(figsize=(5.5, 3.4))
    for path, label, colour in ((args.files[0], "20 µm polymer on steel", "tab:purple"),
                                (args.files[1], "polymer alone", "0.5")):
        x, p = centre_row(path)
        ax.plot(x * UM, p / 1e6, color=colour, label=label)
    ax.set(xlabel="x (µm)", ylabel="pressure (MPa)", title="rigid ball, same force")
    ax.legend(frameon=False, fontsize=8)
    save(fig, args.out)


def von_mises(args):
    with h5py.File(args.files[0]) as f:
        depths = f["stress/depths"][()]
        vm = f["stress/von_mises"][()]
        pressure = f["pressure"][()]
        dx = f.attrs["dx"]
        peak_z = f.attrs["max_von_mises_z"]
    j = vm.shape[1] // 2
    section = vm[:, j, :]
    x = (np.arange(section.shape[1]) - (section.shape[1] - 1) / 2) * dx
    p0 = pressure.max()
    fig, ax = plt.subplots(figsize=(5.5, 3.4))
    mesh = ax.pcolormesh(x * UM, depths * UM, section / p0, shading="nearest", cmap="magma")
    ax.axhline(peak_z * UM, color="w", lw=0.6, ls=":")
    ax.invert_yaxis()
    ax.set(xlabel="x (µm)", ylabel="depth z (µm)", title="von Mises stress in the x–z plane through the centre")
    fig.colorbar(mesh, ax=ax, label="σ_vM / p0")
    save(fig, args.out)


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    print(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("kind", choices=["hardness", "adhesion", "coated", "von-mises"])
    parser.add_argument("files", nargs="+")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    {"hardness": hardness, "adhesion": adhesion, "coated": coated, "von-mises": von_mises}[args.kind](args)


if __name__ == "__main__":
    main()
