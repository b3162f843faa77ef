#!/usr/bin/python3
"""Light samplers side by side: time to a relMSE and relMSE at equal time and at equal samples.

    benchmarks/light_sampling.py [--out DIR] [--scenes many-lights,cornell-box]
                                 [--strategies uniform,power,spatial,bvh] [--spp N]
                                 [--ref-spp N] [--threads N]

Each scene renders with path tracing and each light sampler (--light-sampler) in doubling passes
up to --spp, with --error-log against one reference (tools/reference.sh: the scene's own
integrator with the light tree at --ref-spp, seed 1000; every sampler is unbiased, so any of them
would do and the tree gets there soonest). many-lights is scenes/many-lights (written by its
make_many_lights.py when missing: 10,000 small emissive quads over a floor, 64 x 48, depth 3);
cornell-box renders at --quick resolution. Printed and written to DIR/light_sampling.md, per
scene and sampler: seconds to relMSE 1e-1, 1e-2 and 1e-3 (log-log between passes; '-' when not
reached; the first pass's time includes parsing, building and the sampler's own set-up), relMSE
at the time the fastest sampler's last pass ended, relMSE at --spp, and seconds per sample per
pixel over the passes after the first.
"""
import argparse
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import convergence  # noqa: E402  (its log readers)

ROOT = convergence.ROOT
SCENES = {"many-lights": ("scenes/many-lights/many-lights.pbrt", []),
          "cornell-box": ("scenes/cornell-box/cornell-box.pbrt", ["--quick"])}
TARGETS = [1e-1, 1e-2, 1e-3]


def scene_file(name):
    path = os.path.join(ROOT, SCENES[name][0])
    if name == "many-lights" and not os.path.exists(path):
        subprocess.run([sys.executable, os.path.join(os.path.dirname(path), "make_many_lights.py")],
                       check=True)
    return path


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "light_sampling"))
    ap.add_argument("--scenes", default="many-lights,cornell-box")
    ap.add_argument("--strategies", default="uniform,power,spatial,bvh")
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--ref-spp", type=int, default=4096)
    ap.add_argument("--threads", type=int, default=0)
    args = ap.parse_args()
    candela = convergence.candela_binary("light_sampling.py")
    os.makedirs(args.out, exist_ok=True)
    env = dict(os.environ, CANDELA=candela)
    lines = []
    for name in args.scenes.split(","):
        if name not in SCENES:
            sys.exit(f"light_sampling.py: unknown scene {name}")
        path, extra = scene_file(name), SCENES[name][1]
        ref = subprocess.run([os.path.join(ROOT, "tools", "reference.sh"), path, str(args.ref_spp),
                              "1000", "--light-sampler", "bvh"] + extra, env=env, check=True,
                             capture_output=True, text=True).stdout.strip()
        runs = {}
        for strategy in args.strategies.split(","):
            log = os.path.join(args.out, f"{name}-{strategy}.csv")
            if os.path.exists(log):
                os.remove(log)
            subprocess.run([candela, path, "--spp", str(args.spp), "--seed", "1", "--light-sampler",
                            strategy, "--reference", ref, "--error-log", log, "-o",
                            os.path.join(args.out, f"{name}-{strategy}.exr"), "--preview", "none",
                            "--quiet", "--nthreads", str(args.threads)] + extra, check=True)
            runs[strategy] = convergence.read_log(log)
        equal_time = min(rows[-1]["seconds"] for rows in runs.values())
        lines.append(f"\n### {name} (path, {args.spp} spp; relMSE at equal time: {equal_time:.3g} s)\n")
        lines.append("| sampler | s to 1e-1 | s to 1e-2 | s to 1e-3 | relMSE at equal time | "
                     f"relMSE at {args.spp} spp | s per spp |")
        lines.append("|---|---|---|---|---|---|---|")
        for strategy, rows in runs.items():
            first, last = rows[0], rows[-1]
            per_spp = ((last["seconds"] - first["seconds"]) / (last["spp"] - first["spp"])
                       if last["spp"] > first["spp"] else last["seconds"] / last["spp"])
            cells = [convergence.fmt(convergence.time_to(rows, t)) for t in TARGETS]
            lines.append(f"| {strategy} | " + " | ".join(cells) +
                         f" | {convergence.fmt(convergence.error_at(rows, equal_time))}"
                         f" | {last['relmse']:.3g} | {per_spp:.3g} |")
    convergence.write_report(os.path.join(args.out, "light_sampling.md"), lines)


if __name__ == "__main__":
    main()
