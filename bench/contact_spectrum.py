#!/usr/bin/python3
"""Spectrum of the preconditioned contact-set operator of a solved contact.

Reads a periodic 2D result file of `halfspace solve`, takes its contact set C
(p > 0) and runs preconditioned CG on K_CC x = b (random b on C). The CG
coefficients give a Lanczos matrix whose extreme eigenvalues estimate those of
the preconditioned operator, which set the rate of the solver's last phase,
when the contact set no longer changes:

  fourier        z = P_C M^-1 P_C r, M^-1 the symbol E*|q|/2 (what pk-fourier
                 and pk-multilevel apply)
  balancing B    the same with a multiplicative (balancing) coarse correction
                 on blocks of B x B cells: Q = Z (Z^T K_CC Z)^-1 Z^T with Z the
                 block indicators restricted to C, and
                 z = Q r + (I - Q K_CC) P_C M^-1 P_C (I - K_CC Q) r.
                 Z^T K_CC Z is assembled exactly, one product per block, so
                 this is a diagnostic for small grids, not a solver.

The operator and the preconditioner scale as dx/E* and E*/dx, so the
spectrum depends only on the contact set. Uses numpy and h5py only.

  bench/contact_spectrum.py result.h5 [--balancing 32] [--steps 80]
"""

import argparse
import sys

import h5py
import numpy as np


def fail(message):
    print(f"contact_spectrum.py: {message}", file=sys.stderr)
    sys.exit(2)


def read_contact_set(path):
    try:
        with h5py.File(path, "r") as f:
            if f.attrs.get("format") != "halfspace-result":
                fail(f"{path}: not a halfspace result file (attribute 'format' is not 'halfspace-result')")
            if f.attrs.get("boundary") != "periodic" or int(f.attrs.get("dimension", 0)) != 2:
                fail(f"{path}: only periodic 2D results are supported "
                     f"(boundary '{f.attrs.get('boundary')}', dimension {f.attrs.get('dimension')})")
            if "pressure" not in f:
                fail(f"{path}: no dataset 'pressure'")
            pressure = np.asarray(f["pressure"], dtype=float)
            dx, dy = float(f.attrs["dx"]), float(f.attrs["dy"])
    except OSError as error:
        fail(f"{path}: cannot read as HDF5 ({error})")
    contact = (pressure > 0.0).astype(float)
    if contact.sum() == 0:
        fail(f"{path}: the contact set is empty")
    return contact, dx, dy


class Operators:
    """K (2/(E*|q|), zero mean) and M^-1 (E*|q|/2, the DC at the smallest |q|); E* = 1 unless given."""

    def __init__(self, shape, dx, dy, e_star=1.0):
        ny, nx = shape
        qy = 2.0 * np.pi * np.fft.fftfreq(ny, dy)[:, None]
        qx = 2.0 * np.pi * np.fft.rfftfreq(nx, dx)[None, :]
        q = np.hypot(qx, qy)
        self.shape = shape
        self.kernel = np.zeros_like(q)
        self.kernel[q > 0] = 2.0 / (e_star * q[q > 0])
        self.inverse = 0.5 * e_star * q
        self.inverse[0, 0] = 0.5 * e_star * q[q > 0].min()

    def apply(self, symbol, field):
        return np.fft.irfft2(np.fft.rfft2(field) * symbol, s=self.shape)


def fourier_preconditioner(ops, contact):
    return lambda r: contact * ops.apply(ops.inverse, contact * r)


class Blocks:
    """B x B blocks of the grid: the coarse space is their cells in a search set."""

    def __init__(self, shape, block):
        ny, nx = shape
        self.block, self.bx, self.by = block, nx // block, ny // block
        self.count = self.bx * self.by
        self.owner = (np.arange(ny) // block)[:, None] * self.bx + (np.arange(nx) // block)[None, :]

    def restrict(self, search, field):
        """Z^T field: the sum over each block's cells in the search set."""
        return np.bincount(self.owner.ravel(), weights=(search * field).ravel(), minlength=self.count)


def exact_coarse_matrix(blocks, search, restricted_k):
    """Z^T K_SS Z, one product per block."""
    coarse = np.zeros((blocks.count, blocks.count))
    for j in range(blocks.count):
        coarse[:, j] = blocks.restrict(search, restricted_k((blocks.owner == j) * search))
    return coarse


def coarse_inverse(blocks, search, coarse):
    """coarse^-1 on the blocks with a cell in the search set, zero elsewhere."""
    used = blocks.restrict(search, np.ones_like(search)) > 0
    inverse = np.zeros_like(coarse)
    inverse[np.ix_(used, used)] = np.linalg.inv(coarse[np.ix_(used, used)])
    return inverse


def balancing(blocks, search, inverse, restricted_k, fourier):
    """z = Q r + (I - Q K_SS) fourier (I - K_SS Q) r, Q = Z inverse Z^T."""
    correction = lambda r: search * (inverse @ blocks.restrict(search, r))[blocks.owner]

    def apply(r):
        y = correction(r)
        v = fourier(r - restricted_k(y))
        return y + v - correction(restricted_k(v))

    return apply


def balancing_preconditioner(ops, contact, block, restricted_k, fourier):
    ny, nx = contact.shape
    if nx % block or ny % block:
        fail(f"--balancing {block} must divide the grid ({nx} x {ny})")
    blocks = Blocks(contact.shape, block)
    inverse = coarse_inverse(blocks, contact, exact_coarse_matrix(blocks, contact, restricted_k))
    return balancing(blocks, contact, inverse, restricted_k, fourier)


def lanczos_spectrum(restricted_k, preconditioner, contact, steps):
    """Extreme eigenvalues of the preconditioned operator from `steps` CG steps,
    and the steps CG needed to reduce sqrt(r.z) by 1e-6."""
    rng = np.random.default_rng(1)
    r = contact * rng.standard_normal(contact.shape)
    z = preconditioner(r)
    d = z.copy()
    rz = float((r * z).sum())
    first = np.sqrt(rz)
    alphas, betas = [], []
    to_1e6 = None
    for step in range(steps):
        kd = restricted_k(d)
        alpha = rz / float((d * kd).sum())
        r -= alpha * kd
        z = preconditioner(r)
        rz_new = float((r * z).sum())
        beta = rz_new / rz
        rz = rz_new
        d = z + beta * d
        alphas.append(alpha)
        betas.append(beta)
        if to_1e6 is None and np.sqrt(max(rz, 0.0)) < 1e-6 * first:
            to_1e6 = step + 1
            break
    m = len(alphas)
    t = np.zeros((m, m))
    for i in range(m):
        t[i, i] = 1.0 / alphas[i] + (betas[i - 1] / alphas[i - 1] if i > 0 else 0.0)
        if i + 1 < m:
            t[i, i + 1] = t[i + 1, i] = np.sqrt(betas[i]) / alphas[i]
    eigenvalues = np.linalg.eigvalsh(t)
    return eigenvalues.min(), eigenvalues.max(), to_1e6


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("result", help="periodic 2D result file of halfspace solve")
    parser.add_argument("--balancing", type=int, metavar="B", help="also with the balancing coarse correction on B x B blocks")
    parser.add_argument("--steps", type=int, default=100, help="most CG steps (default 100)")
    args = parser.parse_args()
    if args.steps < 2:
        fail(f"--steps {args.steps} must be at least 2")
    if args.balancing is not None and args.balancing < 1:
        fail(f"--balancing {args.balancing} must be a positive block size")

    contact, dx, dy = read_contact_set(args.result)
    ops = Operators(contact.shape, dx, dy)
    restricted_k = lambda v: contact * ops.apply(ops.kernel, contact * v)
    fourier = fourier_preconditioner(ops, contact)
    cases = [("fourier", fourier)]
    if args.balancing:
        cases.append((f"balancing {args.balancing}",
                      balancing_preconditioner(ops, contact, args.balancing, restricted_k, fourier)))
    ny, nx = contact.shape
    print(f"{args.result}: {nx} x {ny}, {int(contact.sum())} contact cells ({contact.mean():.4f})")
    print(f"{'preconditioner':<16} {'eig min':>9} {'eig max':>9} {'condition':>9} {'CG steps to 1e-6':>17}")
    for name, preconditioner in cases:
        low, high, steps = lanczos_spectrum(restricted_k, preconditioner, contact, args.steps)
        shown = str(steps) if steps is not None else f">{args.steps}"
        print(f"{name:<16} {low:9.3f} {high:9.3f} {high / low:9.1f} {shown:>17}")


if __name__ == "__main__":
    main()
