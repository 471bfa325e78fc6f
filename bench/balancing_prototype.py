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

Z the cells of S in each B x B block. The coarse matrix is assembled exactly
for the current S in every iteration, one product per block (not counted in
the products printed, which are those a solver would need): a prototype for
grids of a few hundred cells per side.

  bench/balancing_prototype.py surface.h5 --mean-pressure 4e6 --E-star 1e9 [--preconditioner balancing --block 32]
"""

import argparse
import sys

import h5py
import numpy as np


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("height_map", help="HDF5 height map (dataset 'height', attributes dx, dy), periodic")
    parser.add_argument("--mean-pressure", type=float, required=True)
    parser.add_argument("--E-star", type=float, required=True)
    parser.add_argument("--preconditioner", choices=["fourier", "balancing"], default="fourier")
    parser.add_argument("--block", type=int, default=32)
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

    qy = 2.0 * np.pi * np.fft.fftfreq(ny, dy)[:, None]
    qx = 2.0 * np.pi * np.fft.rfftfreq(nx, dx)[None, :]
    q = np.hypot(qx, qy)
    kernel = np.zeros_like(q)
    kernel[q > 0] = 2.0 / (args.E_star * q[q > 0])
    inverse = 0.5 * args.E_star * q
    inverse[0, 0] = 0.5 * args.E_star * q[q > 0].min()
    convolve = lambda symbol, field: np.fft.irfft2(np.fft.rfft2(field) * symbol, s=field.shape)
    products = [0]

    def k_product(field):
        products[0] += 1
        return convolve(kernel, field)

    bx, by = nx // args.block, ny // args.block
    owner = (np.arange(ny) // args.block)[:, None] * bx + (np.arange(nx) // args.block)[None, :]
    blocks = bx * by

    def preconditioner(search):
        fourier = lambda r: search * convolve(inverse, search * r)
        if args.preconditioner == "fourier":
            return fourier
        restrict = lambda field: np.bincount(owner.ravel(), weights=(search * field).ravel(), minlength=blocks)
        coarse = np.zeros((blocks, blocks))
        for j in range(blocks):
            coarse[:, j] = restrict(convolve(kernel, (owner == j) * search))
        used = restrict(np.ones_like(search)) > 0
        coarse_inverse = np.zeros_like(coarse)
        coarse_inverse[np.ix_(used, used)] = np.linalg.inv(coarse[np.ix_(used, used)])
        correction = lambda r: search * (coarse_inverse @ restrict(r))[owner]
        restricted_k = lambda v: search * k_product(search * v)

        def balancing(r):
            y = correction(r)
            v = fourier(r - restricted_k(y))
            return y + v - correction(restricted_k(v))

        return balancing

    cells = nx * ny
    initial_gap = height.max() - height
    pressure = np.full(height.shape, args.mean_pressure)
    displacement = k_product(pressure)
    direction = np.zeros_like(pressure)
    previous, conjugate = 1.0, False
    for iteration in range(args.max_iterations + 1):
        contact = pressure > 0.0
        approach = (initial_gap + displacement)[contact].mean()
        gap = initial_gap + displacement - approach
        scale = max(np.ptp(initial_gap) + np.ptp(displacement), 0.0)
        residual = ((pressure * np.abs(gap)).sum() * cells / pressure.sum() + np.maximum(-gap, 0.0).sum()) / (
            cells * scale)
        if residual <= args.tolerance or iteration == args.max_iterations:
            break
        search = (contact | (gap < 0.0)).astype(float)
        z = preconditioner(search)(search * gap)
        z = search * (z - (z * search).sum() / search.sum())
        norm = (search * gap * z).sum()
        if conjugate and abs((search * gap * direction).sum()) > 0.2 * norm:
            conjugate = False
        beta = norm / previous if conjugate else 0.0
        previous = norm
        direction = search * (z + beta * direction)
        image = k_product(direction)
        image_mean = (image * search).sum() / search.sum()
        tau = (search * gap * direction).sum() / ((image - image_mean) * search * direction).sum()
        pressure = np.maximum(pressure - tau * direction, 0.0)
        pressure *= args.mean_pressure * cells / pressure.sum()
        displacement = k_product(pressure)
        conjugate = tau > 0.0
    status = "converged" if residual <= args.tolerance else "NOT converged"
    print(f"{args.preconditioner} (block {args.block}): {status} after {iteration} iterations, residual {residual:.2e}, "
          f"{products[0]} K products, {int((pressure > 0).sum())} contact cells")
    return 0 if residual <= args.tolerance else 1


if __name__ == "__main__":
    sys.exit(main())
