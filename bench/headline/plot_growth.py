#!/usr/bin/env python3
"""Plot iterations and FFT pairs per solve against the grid side from
growing-domain results files (bench/results/*-growing-domain.md, written by
scripts/growing-domain.sh): one line per file, labelled as given.

    plot_growth.py --out docs/figures/performance/iteration_growth.png \
        "default, 2026-11-29=bench/results/2026-11-29-bf4a591-growing-domain.md" ...
"""
import argparse
import re
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_table(path):
    """The last table of a growing-domain file: side -> (mean iterations, mean FFT pairs or None)."""
    rows = {}
    for line in Path(path).read_text().splitlines():
        if line.startswith("## "):
            rows = {}  # a later run in the same file replaces an earlier one
        m = re.match(r"\| (\d+)x\1 \| ([^|]*) \| ([\d.]+) \| ([\d.]+) \| (.*)", line)
        if not m:
            continue
        cells = [c.strip() for c in m.group(5).split("|")]
        # Files before 2026-11-28 have no FFT pairs column.
        pairs = float(cells[0]) if len(cells) >= 5 and re.fullmatch(r"[\d.]+", cells[0]) else None
        rows[int(m.group(1))] = (float(m.group(3)), pairs)
    if not rows:
        raise SystemExit(f"plot_growth: error: {path} holds no growing-domain table")
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="the image to write (.png or .svg)")
    parser.add_argument("series", nargs="+", help="LABEL=FILE[,SIDE:ITERATIONS:PAIRS...] (extra points by hand)")
    args = parser.parse_args()
    fig, (ax_it, ax_pairs) = plt.subplots(1, 2, figsize=(10, 4))
    for spec in args.series:
        label, _, rest = spec.partition("=")
        file, *extra = rest.split(",")
        rows = read_table(file)
        for point in extra:
            side, iterations, pairs = point.split(":")
            rows[int(side)] = (float(iterations), float(pairs) if pairs else None)
        sides = sorted(rows)
        ax_it.plot(sides, [rows[s][0] for s in sides], "o-", label=label)
        with_pairs = [s for s in sides if rows[s][1] is not None]
        if with_pairs:
            ax_pairs.plot(with_pairs, [rows[s][1] for s in with_pairs], "o-", label=label)
    for ax, what in ((ax_it, "iterations per solve"), (ax_pairs, "FFT pairs per solve (K, M^-1, coarse)")):
        ax.set_xscale("log", base=2)
        ax.set_xlabel("grid side n (n x n, 1 um cells: the domain grows)")
        ax.set_ylabel(what)
        ax.set_ylim(bottom=0)
        ax.grid(True, alpha=0.3)
    ax_it.axhline(30, color="grey", ls=":", lw=1)
    ax_pairs.axhline(40, color="grey", ls=":", lw=1)
    ax_it.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
