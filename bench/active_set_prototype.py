#!/usr/bin/python3
"""Research prototype, not part of halfspace: a primal-dual active-set
(semismooth Newton) outer loop with preconditioned conjugate gradients on
the fixed contact set inside, in numpy, to count its iterations before
building it in C++ (issue 31, the moving-set phase of pk-multilevel).

The normal contact under load control is the LCP p >= 0, g >= 0, p g = 0
with g = g0 + K p - a, a the approach fixed by the force. The primal-dual
active-set method (Hintermueller, Ito & Kunisch 2002, SIAM J. Optim. 13,
865: a semismooth Newton method for the complementarity function
min(p, g)) solves, for a set C, the linear problem

  K_CC p_C = a - g0_C,   p = 0 off C,   sum p = F / cell area,

then takes C+ = {i in C : p_i > 0} | {i not in C : g_i < 0}, until C+ = C.
Inside a set nothing is clipped, so a coarse-grid correction could apply
from the first iteration (block deflation cycled when it joined while the
set moved; docs/development-log.md). The inner solve here is conjugate
gradients with halfspace's Fourier preconditioner on C (mean-free on C,
which fixes the force), warm-started from the previous pressure, stopped at
a relative reduction `--inner-reduction` of its preconditioned residual
norm (inexact Newton). The start is pk-multilevel's: the same problem on
the grid of twice the spacing (block-averaged heights, solved by the
Fourier-preconditioned Polonsky-Keer of balancing_prototype.py to 1e-4),
prolonged piecewise constant. Printed: outer iterations, inner iterations
(each one K and one M^-1 product), the K products of the whole solve, and
halfspace's residual of the final pressure; for comparison the
Fourier-preconditioned Polonsky-Keer from the same start.

  bench/active_set_prototype.py surface.h5 --mean-pressure 4e6 --E-star 1e9
"""

import argparse
import sys

import h5py
import numpy as np

from balancing_prototype import Contact, solve as polonsky_keer
from contact_spectrum import Blocks, balancing, coarse_inverse, exact_coarse_matrix


def residual_of(initial_gap, pressure, displacement):
    """halfspace's relative residual (polonsky_keer.hpp) of a pressure >= 0."""
    cells = pressure.size
    in_contact = pressure > 0.0
    approach = (initial_gap + displacement)[in_contact].mean()
    gap = initial_gap + displacement - approach
    scale = np.ptp(initial_gap) + np.ptp(displacement)
    return ((pressure * np.abs(gap)).sum() * cells / pressure.sum() + np.maximum(-gap, 0.0).sum()) / (cells * scale)


def active_set(contact, mean_pressure, start, tolerance, inner_reduction, max_outer, max_inner, block):
    """The primal-dual active-set loop from `start`; returns (pressure, outer, inner, residual)."""
    initial_gap = contact.height.max() - contact.height
    cells = initial_gap.size
    total = mean_pressure * cells
    pressure = start * (total / start.sum())
    in_set = pressure > 0.0
    inner_total = 0
    residual = np.inf
    for outer in range(1, max_outer + 1):
        mask = in_set.astype(float)
        # Start on the set: the previous pressure there, the load restored
        # by a uniform shift (it may leave negative values: C is fixed).
        p = mask * pressure
        p += mask * (total - p.sum()) / mask.sum()
        restricted_k = lambda v: mask * contact.ops.apply(contact.ops.kernel, mask * v)
        fourier = lambda r: mask * contact.ops.apply(contact.ops.inverse, mask * r)
        if block:
            # The balancing form on C, its coarse matrix exact (not counted:
            # halfspace assembles it from the kernel in real space); each
            # application costs two more K products, counted.
            blocks = Blocks(p.shape, block)
            inverse = coarse_inverse(blocks, mask, exact_coarse_matrix(blocks, mask, restricted_k))
            counted_k = lambda v: mask * contact.k_product(mask * v)
            precondition = balancing(blocks, mask, inverse, counted_k, fourier)
        else:
            precondition = fourier
        displacement = contact.k_product(p)
        direction = np.zeros_like(p)
        previous = 1.0
        first_norm = None
        for inner in range(max_inner):
            # The gap with the approach that makes its mean on C vanish.
            approach = (initial_gap + displacement)[in_set].mean()
            gap = mask * (initial_gap + displacement - approach)
            z = precondition(gap - mask * gap[in_set].mean())
            z = mask * (z - z[in_set].mean())
            norm = (gap * z).sum()
            if first_norm is None:
                first_norm = norm
            if norm <= inner_reduction ** 2 * first_norm or norm <= 0.0:
                break
            beta = norm / previous if inner > 0 else 0.0
            previous = norm
            direction = z + beta * direction
            full_image = contact.k_product(direction)
            image = mask * (full_image - full_image[in_set].mean())
            tau = (gap * direction).sum() / (image * direction).sum()
            p -= tau * direction
            displacement -= tau * full_image
            inner_total += 1
        # The full gap (off C too) of the set's solution.
        approach = (initial_gap + displacement)[in_set].mean()
        gap = initial_gap + displacement - approach
        new_set = (in_set & (p > 0.0)) | (~in_set & (gap < 0.0))
        changed = int((new_set != in_set).sum())
        pressure = np.maximum(p, 0.0)
        pressure *= total / pressure.sum()
        residual = residual_of(initial_gap, pressure, contact.k_product(pressure))
        print(f"  outer {outer}: {int(in_set.sum())} cells in C, {changed} change, inner total {inner_total}, "
              f"residual of max(p, 0) {residual:.2e}")
        if residual <= tolerance:
            break
        in_set = new_set
        if changed == 0:
            inner_reduction *= 0.1  # the set has settled: solve it more exactly
    return pressure, outer, inner_total, residual


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("height_map", help="HDF5 height map (dataset 'height', attributes dx, dy), periodic")
    parser.add_argument("--mean-pressure", type=float, required=True)
    parser.add_argument("--E-star", type=float, required=True)
    parser.add_argument("--tolerance", type=float, default=1e-10)
    parser.add_argument("--inner-reduction", type=float, default=1e-2)
    parser.add_argument("--block", type=int, default=0, help="balancing coarse correction on B x B blocks of C")
    parser.add_argument("--max-outer", type=int, default=60)
    parser.add_argument("--max-inner", type=int, default=200)
    args = parser.parse_args()

    with h5py.File(args.height_map, "r") as f:
        height = np.asarray(f["height"], dtype=float)
        dx = float(f["height"].attrs.get("dx", f.attrs.get("dx", 0.0)))
        dy = float(f["height"].attrs.get("dy", f.attrs.get("dy", dx)))
    ny, nx = height.shape
    coarse = Contact(height.reshape(ny // 2, 2, nx // 2, 2).mean(axis=(1, 3)), 2 * dx, 2 * dy, args.E_star)
    coarse_pressure, coarse_iterations, _ = polonsky_keer(coarse, args.mean_pressure, coarse.fourier, 1e-4, 1000)
    start = np.repeat(np.repeat(coarse_pressure, 2, axis=0), 2, axis=1)
    print(f"coarse start: {coarse_iterations} iterations on {nx // 2} x {ny // 2}")

    contact = Contact(height, dx, dy, args.E_star)
    _, pk_iterations, pk_residual = polonsky_keer(contact, args.mean_pressure, contact.fourier, args.tolerance, 1000,
                                                  start)
    print(f"pk-fourier from the coarse start: {pk_iterations} iterations, {contact.products} K products "
          f"(the prototype makes an exact product per iteration), residual {pk_residual:.2e}")
    contact.products = 0
    _, outer, inner, residual = active_set(contact, args.mean_pressure, start, args.tolerance, args.inner_reduction,
                                           args.max_outer, args.max_inner, args.block)
    status = "converged" if residual <= args.tolerance else "NOT converged"
    print(f"active set: {status}, {outer} outer and {inner} inner iterations, {contact.products} K products "
          f"(one per inner iteration, two more with --block, and one per outer), residual {residual:.2e}")
    return 0 if residual <= args.tolerance else 1


if __name__ == "__main__":
    sys.exit(main())
