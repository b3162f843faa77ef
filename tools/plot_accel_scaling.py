#!/usr/bin/python3
"""Draws the accelerator scaling series of candela_accel_bench as a log-log PNG.

Usage: tools/plot_accel_scaling.py accel_scaling.csv [-o accel_scaling.png]

Left: build time (CPU seconds) against the triangle count; right: nanoseconds per camera ray
and per diffuse-bounce ray (one thread). One line per aggregate. Needs matplotlib
(Debian: apt-get install python3-matplotlib; hence /usr/bin/python3, which has Debian's
modules, rather than whatever python3 comes first in PATH).
"""
import argparse
import csv
import sys
from collections import defaultdict


def read_series(path):
    series = defaultdict(list)
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            series[row["aggregate"]].append(
                (int(row["triangles"]), float(row["build_cpu_s"]),
                 float(row["camera_ns_per_ray"]), float(row["bounce_ns_per_ray"])))
    for rows in series.values():
        rows.sort()
    return series


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", help="the --scaling-csv output of candela_accel_bench")
    parser.add_argument("-o", "--output", default="accel_scaling.png")
    args = parser.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("plot_accel_scaling.py: needs matplotlib (apt-get install python3-matplotlib)")

    series = read_series(args.csv)
    if not series:
        sys.exit(f"plot_accel_scaling.py: {args.csv} has no rows")
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
    for name, rows in sorted(series.items()):
        n = [r[0] for r in rows]
        # A build too fast for the CPU clock reads 0, which a log axis cannot show.
        left.plot(n, [max(r[1], 1e-5) for r in rows], marker="o", label=name)
        line, = right.plot(n, [r[2] for r in rows], marker="o", label=f"{name} camera")
        right.plot(n, [r[3] for r in rows], marker="s", linestyle="--", color=line.get_color(),
                   label=f"{name} bounce")
    left.set(xscale="log", yscale="log", xlabel="triangles", ylabel="build time (CPU s)",
             title="Build time")
    right.set(xscale="log", yscale="log", xlabel="triangles", ylabel="ns per ray (1 thread)",
              title="Cost per ray")
    for ax in (left, right):
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
