#!/usr/bin/python3
"""The coated half-space figure of docs/validation.md.

A rigid sphere on a soft coating (polymer on steel) and on a hard one (TiN on
aluminium): peak pressure and contact radius, relative to the layer's own
Hertz contact, against a/t. Curves: an independent axisymmetric solution
(rings of uniform pressure; the influence of a ring is the layer's
half-space in closed form, with complete elliptic integrals, plus the
bonded-layer correction by numerical Hankel transform). Markers: `halfspace
solve --layer-*` on a free 128 x 128 grid. Prints the numbers quoted in
docs/validation.md.

  scripts/layered_figures.py [--halfspace build/bin/halfspace]
                             [--out docs/figures/validation] [--work DIR]

Needs Debian's python3 with matplotlib, h5py, numpy and scipy
(scripts/install-deps.sh).
"""

import argparse
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np
from scipy.special import ellipe, ellipk, j0, j1

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import halfspace_plot as hp  # noqa: E402  (the project's plotting tool)

plt = hp.plt

SPHERE_RADIUS = 5e-3  # m
LAYER_HERTZ_RADIUS = 50e-6  # m: the force is chosen so that the layer alone gives this
COATINGS = [
    # name, (E1, nu1), (E2, nu2), domain side / layer Hertz radius
    ("soft: polymer on steel", (3e9, 0.35), (2.1e11, 0.29), 2.5),
    ("hard: TiN on aluminium", (4e11, 0.25), (7e10, 0.33), 4.0),
]


def plane_strain(e, nu):
    return e / (1 - nu * nu)


def compliance_factor(s, layer, substrate):
    """M(q t) of the bonded layer (Stanley & Kato 1997, O'Sullivan & King 1988)."""
    (e1, nu1), (e2, nu2) = layer, substrate
    g = (e1 / (1 + nu1)) / (e2 / (1 + nu2))
    kappa = (g - 1) / (g + 3 - 4 * nu1)
    lam = 1 - 4 * (1 - nu1) / (1 + g * (3 - 4 * nu2))
    e = np.exp(-2 * s)
    return (1 + 4 * kappa * s * e - lam * kappa * e * e) / (
        1 - (lam + kappa + 4 * kappa * s * s) * e + lam * kappa * e * e)


def disk_displacement(b, r, e_star):
    """Layer half-space displacement at r under 1 Pa on a disk of radius b (Johnson 1985)."""
    r = np.asarray(r, dtype=float)
    out = np.zeros_like(r)
    if b == 0:
        return out
    inside = r <= b
    out[inside] = 4 * b * ellipe((r[inside] / b) ** 2) / (np.pi * e_star)
    k = b / r[~inside]
    out[~inside] = 4 * r[~inside] * (ellipe(k * k) - (1 - k * k) * ellipk(k * k)) / (np.pi * e_star)
    return out


def axisymmetric_contact(t, layer, substrate, force, r_max, rings=200):
    """Contact radius and peak pressure of the sphere on the coating, by rings."""
    e1 = plane_strain(*layer)
    h = r_max / rings
    edges = np.arange(rings + 1) * h
    mids = (np.arange(rings) + 0.5) * h
    a = np.stack([disk_displacement(edges[j + 1], mids, e1) - disk_displacement(edges[j], mids, e1)
                  for j in range(rings)], axis=1)
    k_max = 40 / t
    dk = min(0.02 / t, 0.2 / r_max)
    n = 2 * int(np.ceil(0.5 * k_max / dk))
    k = np.linspace(0, k_max, n + 1)
    w = np.full(n + 1, 2.0)
    w[1::2] = 4.0
    w[0] = w[-1] = 1.0
    w *= (k[1] - k[0]) / 3
    correction = np.zeros_like(k)
    correction[1:] = compliance_factor(k[1:] * t, layer, substrate) - 1
    correction[0] = plane_strain(*layer) / plane_strain(*substrate) - 1
    disk = np.empty((n + 1, rings + 1))
    disk[0] = 0.5 * edges ** 2
    disk[1:] = edges[None, :] * j1(k[1:, None] * edges[None, :]) / k[1:, None]
    ring = np.diff(disk, axis=1)  # (k, ring)
    a += (2 / e1) * (j0(k[:, None] * mids[None, :]).T * (w * correction)) @ ring
    def pressures(m):  # the first m rings in contact: their pressures (the approach dropped)
        system = np.zeros((m + 1, m + 1))
        system[:m, :m] = a[:m, :m]
        system[:m, m] = -1
        system[m, :m] = np.pi * (edges[1:m + 1] ** 2 - edges[:m] ** 2)
        rhs = np.append(-mids[:m] ** 2 / (2 * SPHERE_RADIUS), force)
        return np.linalg.solve(system, rhs)[:m]

    # The outer ring's pressure changes sign once, at the contact's edge:
    # bisect for the largest m where it is still positive.
    low, high = 1, rings
    while high - low > 1:
        middle = (low + high) // 2
        if pressures(middle)[-1] > 0:
            low = middle
        else:
            high = middle
    return edges[low], pressures(low)[0]


def halfspace_contact(program, work, t, layer, substrate, force, side):
    path = os.path.join(work, f"coated_{t:.3e}.h5")
    subprocess.run([program, "solve", "--geometry", "sphere", "--radius", str(SPHERE_RADIUS), "--grid", "128x128",
                    "--size", str(side), "--force", str(force), "--layer-thickness", str(t),
                    "--layer-E", str(layer[0]), "--layer-nu", str(layer[1]), "--substrate-E", str(substrate[0]),
                    "--substrate-nu", str(substrate[1]), "--output", path, "--quiet"], cwd=work, check=True)
    with h5py.File(path, "r") as f:
        radius = np.sqrt(f.attrs["contact_fraction"] * side * side / np.pi)
        return radius, f.attrs["max_pressure"]


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--halfspace", default=os.path.join(root, "build", "bin", "halfspace"))
    parser.add_argument("--out", default=os.path.join(root, "docs", "figures", "validation"))
    parser.add_argument("--work", default=None)
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="halfspace_layered_")
    os.makedirs(args.out, exist_ok=True)

    fig, (ax_p, ax_a) = plt.subplots(1, 2, figsize=(9, 3.6))
    for (name, layer, substrate, side_factor), colour in zip(COATINGS, ["C0", "C3"]):
        e1 = plane_strain(*layer)
        force = 4 * e1 * LAYER_HERTZ_RADIUS ** 3 / (3 * SPHERE_RADIUS)
        hertz_peak = 3 * force / (2 * np.pi * LAYER_HERTZ_RADIUS ** 2)
        side = side_factor * LAYER_HERTZ_RADIUS
        r_max = 0.45 * side
        ratios = np.logspace(-1.3, 1.3, 27)  # layer Hertz radius / t
        curve = np.array([axisymmetric_contact(LAYER_HERTZ_RADIUS / x, layer, substrate, force, r_max)
                          for x in ratios])
        ax_p.semilogx(curve[:, 0] / (LAYER_HERTZ_RADIUS / ratios), curve[:, 1] / hertz_peak, color=colour,
                      label=f"{name} (rings)")
        ax_a.semilogx(curve[:, 0] / (LAYER_HERTZ_RADIUS / ratios), curve[:, 0] / LAYER_HERTZ_RADIUS, color=colour)
        print(f"{name}: F = {force:.4g} N, layer Hertz a = {LAYER_HERTZ_RADIUS * 1e6:.0f} um, "
              f"p0 = {hertz_peak:.4g} Pa, domain {side * 1e6:.0f} um")
        print("   a_H1/t    a/t   rings a/a_H1  halfspace   rings p0/p0_H1  halfspace   peak difference")
        for x in np.logspace(-1, 1, 7):
            t = LAYER_HERTZ_RADIUS / x
            ring_radius, ring_peak = axisymmetric_contact(t, layer, substrate, force, r_max)
            radius, peak = halfspace_contact(args.halfspace, work, t, layer, substrate, force, side)
            ax_p.plot(radius / t, peak / hertz_peak, "o", color=colour, mfc="none")
            ax_a.plot(radius / t, radius / LAYER_HERTZ_RADIUS, "o", color=colour, mfc="none")
            print(f"  {x:7.3f} {ring_radius / t:7.3f}   {ring_radius / LAYER_HERTZ_RADIUS:8.4f}  "
                  f"{radius / LAYER_HERTZ_RADIUS:8.4f}   {ring_peak / hertz_peak:10.4f}   {peak / hertz_peak:9.4f}"
                  f"   {(peak - ring_peak) / ring_peak:+.2%}")
    ax_p.plot([], [], "ko", mfc="none", label="halfspace, free 128 x 128")
    ax_p.set_xlabel("contact radius / layer thickness, a/t")
    ax_p.set_ylabel("peak pressure / layer's Hertz p0")
    ax_a.set_xlabel("contact radius / layer thickness, a/t")
    ax_a.set_ylabel("contact radius / layer's Hertz a")
    ax_p.legend(fontsize=8)
    for ax in (ax_p, ax_a):
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle("Rigid sphere on a coated half-space", fontsize=10)
    fig.tight_layout()
    path = os.path.join(args.out, "coated_sphere.png")
    fig.savefig(path, dpi=hp.DPI)
    print(f"wrote {path} ({os.path.getsize(path) // 1024} KB)")


if __name__ == "__main__":
    main()
