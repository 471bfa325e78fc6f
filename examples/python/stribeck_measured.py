#!/usr/bin/env python3
"""A Stribeck curve on a measured surface from Python, as
examples/stribeck_measured.sh does it with the program: a steel roller
(R = 0.5 mm, E* = 113 GPa) at 2 kN/m and 20 % slide-to-roll on a flat whose
profile is a stylus scan, oil-lubricated (eta0 = 0.04 Pa s, Roelands with
alpha = 2.27e-8 1/Pa, limiting shear stress 0.05 p; Coulomb mu = 0.1 on
contacts), swept from full film into boundary lubrication.

    python3 examples/python/stribeck_measured.py OUTPUT_DIR [--profile FILE] [--quick]

The profile is ../shared/data/topography/dektak-1.h5 beside the project root
if present, else the original Dektak export tests/data/dektak-1.csv (the same
scan); a 240-point window (37.5 um) at the scan's own spacing, its tilt
removed. Writes OUTPUT_DIR/stribeck.csv (the columns of `halfspace lubricate
--stribeck`) and, where matplotlib is installed, stribeck.png (mu and the
contact share against the Hersey number) and transition.png (the fluid and
contact pressures of the first film in the mixed regime).
"""

import argparse
import csv
import pathlib

import numpy as np

import halfspace as hs

ROOT = pathlib.Path(__file__).resolve().parents[2]
SHARED_PROFILE = ROOT.parent / "shared" / "data" / "topography" / "dektak-1.h5"
COPY = ROOT / "tests" / "data" / "dektak-1.csv"
SPEEDS = [3, 1, 0.3, 0.1, 0.03, 0.01, 0.003, 0.001, 7e-4, 5e-4, 4e-4, 3e-4, 2e-4, 1e-4, 3e-5]
QUICK_SPEEDS = [1, 0.01, 0.001, 7e-4, 1e-4]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output_dir", type=pathlib.Path)
    parser.add_argument("--profile", type=pathlib.Path, default=SHARED_PROFILE if SHARED_PROFILE.is_file() else COPY)
    parser.add_argument("--quick", action="store_true", help="five speeds")
    args = parser.parse_args()
    args.output_dir.mkdir(parents=True, exist_ok=True)

    scan = hs.read_height_map(args.profile).prepare(window=(3000, 240), detrend="plane")
    roller = hs.generate.cylinder(grid=scan.shape[-1], size=scan.shape[-1] * scan.dx, radius=5e-4)
    print(f"{scan}: rms roughness {scan.heights.std():.3g} m")
    curve = hs.stribeck(scan.heights + roller.heights, QUICK_SPEEDS if args.quick else SPEEDS, dx=scan.dx,
                        e_star=1.13e11, force=2e3, viscosity=0.04, pressure_viscosity=2.27e-8,
                        piezoviscosity="roelands", limiting_shear_slope=0.05, contact_friction=0.1,
                        entrainment_velocity=1.0, sliding_velocity=0.2)
    with open(args.output_dir / "stribeck.csv", "w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(curve.COLUMNS)
        writer.writerows(zip(*(curve.table[name] for name in curve.COLUMNS)))
    print(f"{'U (m/s)':>10} {'Hersey':>10} {'mu':>8} {'contact':>8} {'h_c (m)':>10}")
    for k in range(len(curve)):
        print(f"{curve.entrainment_speed[k]:10.3g} {curve.hersey_number[k]:10.3g} "
              f"{curve.friction_coefficient[k]:8.4f} {curve.contact_load_fraction[k]:8.3f} "
              f"{curve.central_film_thickness[k]:10.3g} {'' if curve.films[k].converged else curve.status[k]}")
    if not curve.converged:
        print("warning: some speeds did not converge (status column)")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed: no figures")
        return
    fig, axis = plt.subplots(figsize=(6.5, 4.2), constrained_layout=True)
    axis.semilogx(curve.hersey_number, curve.friction_coefficient, "o-", color="tab:red", ms=4)
    axis.set_xlabel("Hersey number eta0 U / w'")
    axis.set_ylabel("friction coefficient mu", color="tab:red")
    twin = axis.twinx()
    twin.semilogx(curve.hersey_number, curve.contact_load_fraction, "s--", color="tab:blue", ms=3)
    twin.set_ylabel("contact share of the load", color="tab:blue")
    axis.grid(True, alpha=0.3, which="both")
    fig.savefig(args.output_dir / "stribeck.png", dpi=110)
    plt.close(fig)

    mixed = [film for film in curve.films if 0.0 < film.contact_load_fraction < 0.9]
    film = mixed[0] if mixed else curve.films[-1]
    x = np.arange(film.pressure.size) * scan.dx * 1e6
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 5.5), constrained_layout=True)
    top.plot(x, film.fluid_pressure / 1e6, color="tab:blue", label="fluid")
    top.plot(x, film.contact_pressure / 1e6, color="tab:red", label="contact")
    top.set_ylabel("pressure (MPa)")
    top.legend()
    top.set_title(f"U = {film.entrainment_speed:.3g} m/s: contact carries {100 * film.contact_load_fraction:.0f} %",
                  fontsize="small")
    bottom.plot(x, film.film * 1e9, color="tab:blue")
    bottom.set_ylabel("film thickness (nm)")
    bottom.set_xlabel("x (um)")
    fig.savefig(args.output_dir / "transition.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
