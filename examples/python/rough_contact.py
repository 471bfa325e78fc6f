#!/usr/bin/env python3
"""A rough-contact study from Python: read a measured height map, remove its
tilt, sweep the mean pressure, and plot the contact area against the load
and the pressure map of the largest load.

    python3 examples/python/rough_contact.py OUTPUT_DIR [--height-map FILE] [--steps N]

Without --height-map it reads the AFM crop tests/data/di-5-crop-48x64.h5 of
this repository. Writes OUTPUT_DIR/sweep.h5 and sweep.csv (as `halfspace
solve` does), and, where matplotlib is installed, contact_area.png and
pressure.png.
"""

import argparse
import pathlib

import numpy as np

import halfspace as hs

HERE = pathlib.Path(__file__).resolve().parent
DEFAULT_MAP = HERE.parent.parent / "tests" / "data" / "di-5-crop-48x64.h5"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output_dir", type=pathlib.Path)
    parser.add_argument("--height-map", type=pathlib.Path, default=DEFAULT_MAP)
    parser.add_argument("--steps", type=int, default=8, help="number of loads [8]")
    parser.add_argument("--e-star", type=float, default=1e9, help="composite modulus E* (Pa) [1e9]")
    args = parser.parse_args()
    args.output_dir.mkdir(parents=True, exist_ok=True)

    surface = hs.read_height_map(args.height_map, detrend="plane", invalid="fill")
    stats = surface.statistics()
    print(surface)
    print(f"rms height {stats['rms_height']:.3g} m, rms slope {stats['rms_slope']:.3g}")

    # From a few per mille of contact to most of the surface: p / (E* slope) spans 1e-3 to 1.
    loads = np.geomspace(1e-3, 1.0, args.steps) * args.e_star * stats["rms_slope"]
    sweep = hs.sweep(surface, e_star=args.e_star, mean_pressure=loads, boundary="free", tol=1e-8)
    sweep.save(args.output_dir / "sweep.h5")
    table = sweep.table
    for load, area, iterations in zip(table["load"], table["contact_fraction"], table["iterations"]):
        print(f"p = {load:10.4g} Pa  contact {area:7.4f}  ({int(iterations)} iterations)")

    try:
        import matplotlib
    except ImportError:
        print("matplotlib is not installed: no figures")
        return
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(5, 4))
    axes.loglog(table["load"], table["contact_fraction"], "o-", label="halfspace")
    # Persson's small-load limit A/A0 = 2 sqrt(2) p / (sqrt(pi) E* slope), for reference.
    axes.loglog(table["load"], np.minimum(1.0, 2 * np.sqrt(2 / np.pi) * table["load"] / (args.e_star * stats["rms_slope"])),
                "--", label="linear theory")
    axes.set_xlabel("mean pressure (Pa)")
    axes.set_ylabel("contact area fraction")
    axes.legend()
    figure.tight_layout()
    figure.savefig(args.output_dir / "contact_area.png", dpi=120)

    last = sweep[-1]
    figure, axes = plt.subplots(figsize=(5, 4))
    ny, nx = last.shape
    image = axes.imshow(last.pressure, origin="lower", extent=(0, nx * last.dx, 0, ny * last.dy), cmap="magma")
    figure.colorbar(image, label="pressure (Pa)")
    axes.set_title(f"mean pressure {last.mean_pressure:.3g} Pa")
    axes.set_xlabel("x (m)")
    axes.set_ylabel("y (m)")
    figure.tight_layout()
    figure.savefig(args.output_dir / "pressure.png", dpi=120)
    print(f"wrote {args.output_dir / 'contact_area.png'} and {args.output_dir / 'pressure.png'}")


if __name__ == "__main__":
    main()
