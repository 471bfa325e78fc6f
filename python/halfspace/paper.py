"""The seed paper's Table 1, reproduced as arrays (``halfspace paper`` as a function)."""

from __future__ import annotations

from . import _core

__all__ = ["reproduce"]


def reproduce(test: int = 1, load: float = 1e5) -> dict:
    """Solves test ``test`` (1-4) of Table 1 under a line load ``load`` (N/m)
    by Lemke pivoting, the paper's LCPquad and Polonsky-Keer, on the same
    plane-strain strip kernel, with the Hertz solution beside them.

    Returns the columns of ``halfspace paper``'s testN.csv as float64 arrays,
    ``x`` (m), ``gap`` (m), ``p_lemke``, ``p_lcpquad``, ``p_pk``, ``p_hertz``
    (Pa), and ``summary``, a dict of the test's numbers (nodes, load, E*,
    radius, Hertz half-width and peak, contact nodes, the largest pressure
    differences between methods over the Hertz peak, convergence).
    """
    return _core.paper_reproduce(int(test), float(load))
