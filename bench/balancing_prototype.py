#!/usr/bin/python3
"""Research prototype, not part of halfspace: pk-fourier with a balancing
coarse correction, in numpy, to count iterations before building it in C++.

The loop is halfspace's preconditioned Polonsky-Keer under load control with
the projected-gradient search set S = {p > 0} | {g < 0} (docs/theory.md),
Powell restarts, a cold start from the uniform pressure and halfspace's
residual; with `--preconditioner fourier` it takes the iterations of
`halfspace solve --solver pk-fourier` (29 and 37 on the 256^2 and 512^2
growing-domain surfaces of docs/performance.md). `--preconditioner balancing`
replaces z = P_S M^-1 P_S r by

  z = Q r + (I - Q K_SS) P_S M^-1 P_S (I - K_SS Q) r,  Q = Z (Z^T K_SS Z)^-1 Z^T,

Z the cells of S in each B x B block. The coarse matrix Z^T K_SS Z is
assembled exactly, one product per block (not counted in the products
printed, which are those a solver would need): a prototype for grids of a few
hundred cells per side. `--point-loads-beyond-neighbours` keeps only the
3 x 3 nearest blocks exact and takes point loads between block centres for
the rest; `--rebuild-change F` rebuilds it only when S changed in more than
the fraction F of its cells; `--coarse-start` first solves the problem on
the grid of twice the spacing (block-averaged heights, `fourier`) and starts
from its pressure, prolonged piecewise constant, as pk-multilevel's finest
step does.

  bench/balancing_prototype.py surface.h5 --mean-pressure 4e6 --E-star 1e9 [--preconditioner balancing --block 32]
"""

import argparse
import sys

import h5py
import numpy as np

from contact_spectrum import Blocks, Operators, balancing, coarse_inverse, exact_coarse_matrix, fourier_preconditioner


class Contact:
    """The periodic problem on one grid, its K products counted."""

    def __init__(self, height, dx, dy, e_star):
        self.height = height
        self.ops = Operators(height.shape, dx, dy, e_star)
        self.products = 0

    def k_product(self, field):
        self.products += 1
        return self.ops.apply(self.ops.kernel, field)

    def fourier(self, search):
        return fourier_preconditioner(self.ops, search)


class Balancing:
    """The balancing preconditioner of contact_spectrum.py for the current
    search set, its coarse matrix rebuilt when the set has changed enough."""

    def __init__(self, contact, block, point_loads_beyond_neighbours, rebuild_change):
        self.contact = contact
        self.blocks = Blocks(contact.height.shape, block)
        self.point_loads = point_loads_beyond_neighbours
        self.rebuild_change = rebuild_change
        self.built_for = None
        self.rebuilds = 0

    def build(self, search):
        ops, blocks = self.contact.ops, self.blocks
        # Not counted: a solver would not assemble it with products.
        coarse = exact_coarse_matrix(blocks, search, lambda v: search * ops.apply(ops.kernel, search * v))
        if self.point_loads:
            ny, nx = search.shape
            counts = blocks.restrict(search, np.ones_like(search))
            influence = np.fft.irfft2(ops.kernel, s=search.shape)  # the kernel in real space
            index = np.arange(blocks.count)
            sx = (index[:, None] % blocks.bx - index[None, :] % blocks.bx) % blocks.bx
            sy = (index[:, None] // blocks.bx - index[None, :] // blocks.bx) % blocks.by
            near = (np.minimum(sx, blocks.bx - sx) <= 1) & (np.minimum(sy, blocks.by - sy) <= 1)
            far = counts[:, None] * counts[None, :] * influence[(sy * blocks.block) % ny, (sx * blocks.block) % nx]
            coarse = np.where(near, coarse, far)
        self.inverse = coarse_inverse(blocks, search, coarse)
        self.built_for = search.copy()
        self.rebuilds += 1

    def preconditioner(self, search):
        if self.built_for is None or np.abs(search - self.built_for).sum() > self.rebuild_change * self.built_for.sum():
            self.build(search)
        restricted_k = lambda v: search * self.contact.k_product(search * v)
        return balancing(self.blocks, search, self.inverse, restricted_k, self.contact.fourier(search))


def solve(contact, mean_pressure, preconditioner_for, tolerance, max_iterations, start=None):
    """halfspace's preconditioned PK under load control with the projected search set."""
    height = contact.height
    cells = height.size
    initial_gap = height.max() - height
    pressure = np.full(height.shape, mean_pressure) if start is None else start * (mean_pressure * cells / start.sum())
    displacement = contact.k_product(pressure)
    direction = np.zeros_like(pressure)
    previous, conjugate = 1.0, False
    for iteration in range(max_iterations + 1):
        in_contact = pressure > 0.0
        approach = (initial_gap + displacement)[in_contact].mean()
        gap = initial_gap + displacement - approach
        scale = max(np.ptp(initial_gap) + np.ptp(displacement), 0.0)
        residual = ((pressure * np.abs(gap)).sum() * cells / pressure.sum() + np.maximum(-gap, 0.0).sum()) / (
            cells * scale)
        if residual <= tolerance or iteration == max_iterations:
            break
        search = (in_contact | (gap < 0.0)).astype(float)
        z = preconditioner_for(search)(search * gap)
        z = search * (z - (z * search).sum() / search.sum())
        norm = (search * gap * z).sum()
        if conjugate and abs((search * gap * direction).sum()) > 0.2 * norm:
            conjugate = False
        beta = norm / previous if conjugate else 0.0
        previous = norm
        direction = search * (z + beta * direction)
        image = contact.k_product(direction)
        image_mean = (image * search).sum() / search.sum()
        tau = (search * gap * direction).sum() / ((image - image_mean) * search * direction).sum()
        pressure = np.maximum(pressure - tau * direction, 0.0)
        pressure *= mean_pressure * cells / pressure.sum()
        displacement = contact.k_product(pressure)
        conjugate = tau > 0.0
    return pressure, iteration, residual


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("height_map", help="HDF5 height map (dataset 'height', attributes dx, dy), periodic")
    parser.add_argument("--mean-pressure", type=float, required=True)
    parser.add_argument("--E-star", type=float, required=True)
    parser.add_argument("--preconditioner", choices=["fourier", "balancing"], default="fourier")
    parser.add_argument("--block", type=int, default=32)
    parser.add_argument("--point-loads-beyond-neighbours", action="store_true")
    parser.add_argument("--rebuild-change", type=float, default=0.0, metavar="F")
    parser.add_argument("--coarse-start", action="store_true")
    parser.add_argument("--tolerance", type=float, default=1e-10)
    parser.add_argument("--max-iterations", type=int, default=1000)
    args = parser.parse_args()

    with h5py.File(args.height_map, "r") as f:
        if "height" not in f:
            sys.exit(f"balancing_prototype.py: {args.height_map}: no dataset 'height'")
        height = np.asarray(f["height"], dtype=float)
        dx = float(f["height"].attrs.get("dx", f.attrs.get("dx", 0.0)))
        dy = float(f["height"].attrs.get("dy", f.attrs.get("dy", dx)))
    if not dx > 0.0 or height.ndim != 2:
        sys.exit(f"balancing_prototype.py: {args.height_map}: needs a 2D height map with a positive dx")
    ny, nx = height.shape
    if args.preconditioner == "balancing" and (nx % args.block or ny % args.block):
        sys.exit(f"balancing_prototype.py: --block {args.block} must divide the grid ({nx} x {ny})")
    if args.coarse_start and (nx % 2 or ny % 2):
        sys.exit(f"balancing_prototype.py: --coarse-start needs even grid sizes ({nx} x {ny})")

    start = None
    if args.coarse_start:
        coarse = Contact(height.reshape(ny // 2, 2, nx // 2, 2).mean(axis=(1, 3)), 2 * dx, 2 * dy, args.E_star)
        coarse_pressure, coarse_iterations, _ = solve(coarse, args.mean_pressure, coarse.fourier, args.tolerance,
                                                      args.max_iterations)
        start = np.repeat(np.repeat(coarse_pressure, 2, axis=0), 2, axis=1)
        print(f"coarse start: {coarse_iterations} iterations on {nx // 2} x {ny // 2}")

    contact = Contact(height, dx, dy, args.E_star)
    balancing = None
    if args.preconditioner == "fourier":
        preconditioner_for = contact.fourier
    else:
        balancing = Balancing(contact, args.block, args.point_loads_beyond_neighbours, args.rebuild_change)
        preconditioner_for = balancing.preconditioner
    pressure, iterations, residual = solve(contact, args.mean_pressure, preconditioner_for, args.tolerance,
                                           args.max_iterations, start)
    status = "converged" if residual <= args.tolerance else "NOT converged"
    rebuilds = f", {balancing.rebuilds} coarse matrices" if balancing else ""
    print(f"{args.preconditioner}: {status} after {iterations} iterations, residual {residual:.2e}, "
          f"{contact.products} K products, {iterations} M^-1, {int((pressure > 0).sum())} contact cells{rebuilds}")
    return 0 if residual <= args.tolerance else 1


if __name__ == "__main__":
    sys.exit(main())
