#!/usr/bin/python3
"""Plots error against run time from candela --error-log CSVs, log-log, one curve per CSV.

    tools/plot_convergence.py OUT.png LOG.csv [LABEL=LOG.csv ...] [--metric relmse] [--x seconds]

A curve is labelled by LABEL= when given, else by the file name. A dashed line of slope -1 (the
MSE of an unbiased estimator against time or samples) is drawn through the first curve's middle
point for comparison. Needs Debian's python3-matplotlib.
"""
import argparse
import csv
import math
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plot_convergence.py: needs matplotlib (apt-get install python3-matplotlib)")


def read_log(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_convergence.py: {path}: no rows")
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("logs", nargs="+")
    ap.add_argument("--metric", default="relmse", help="column to plot (default relmse)")
    ap.add_argument("--x", default="seconds", help="seconds (default), spp or rays")
    ap.add_argument("--title", default="")
    ap.add_argument("--xlabel", default=None, help="the x axis' label (default: the column's)")
    args = ap.parse_args()

    fig, ax = plt.subplots(figsize=(7, 5))
    first = None
    for spec in args.logs:
        label, _, path = spec.rpartition("=")
        label = label or os.path.splitext(os.path.basename(path))[0]
        rows = [r for r in read_log(path) if float(r[args.x]) > 0 and float(r[args.metric]) > 0]
        xs = [float(r[args.x]) for r in rows]
        ys = [float(r[args.metric]) for r in rows]
        if not xs:
            continue
        ax.loglog(xs, ys, marker="o", markersize=3, label=label)
        if first is None:
            first = (xs, ys)
    if first:
        xs, ys = first
        mid = len(xs) // 2
        x0, y0 = xs[mid], ys[mid]
        lo, hi = min(xs), max(xs)
        ax.loglog([lo, hi], [y0 * x0 / lo, y0 * x0 / hi], "k--", linewidth=1, label="slope -1")
    ax.set_xlabel(args.xlabel or
                  {"seconds": "wall time (s)", "spp": "samples per pixel"}.get(args.x, args.x))
    ax.set_ylabel(args.metric)
    if args.title:
        ax.set_title(args.title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print(args.out)


if __name__ == "__main__":
    main()
