#!/usr/bin/python3
"""Adaptive sampling against uniform sampling: time to a relMSE, and the error it predicts.

    benchmarks/adaptive_sampling.py [--out DIR] [--scenes a,b] [--spp N] [--ref-spp N]
                                    [--thresholds 0.3,0.2,...] [--min-samples N] [--threads N]

For each scene: a reference (tools/reference.sh, as benchmarks/convergence.py makes it), uniform
sampling in doubling passes up to --spp (--error-log), and one adaptive render per noise
threshold with the same --spp as its cap. Prints, per scene and target relMSE (1e-2, 3e-3, 1e-3),
the seconds each needs (log-log interpolation, between passes for uniform sampling, between the
thresholds' finished renders for adaptive sampling; '-' when not reached) and their ratio; then,
per threshold, the finished render's seconds, mean samples per pixel, relMSE against the
reference and the relMSE its pixels' variances predict. Writes DIR/adaptive.md.
"""
import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import convergence  # noqa: E402  (its scenes, references and log readers)

ROOT = convergence.ROOT
TARGETS = [1e-2, 3e-3, 1e-3]


def render(candela, scene_file, ref, log, spp, threads, quick, extra):
    if os.path.exists(log):
        os.remove(log)
    subprocess.run([candela, scene_file, "--spp", str(spp), "--seed", "1", "--reference", ref,
                    "--error-log", log, "-o", os.path.join(os.path.dirname(log), "last.exr"),
                    "--preview", "none", "--quiet", "--nthreads", str(threads)] + quick + extra,
                   check=True)
    return convergence.read_log(log)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "adaptive"))
    ap.add_argument("--scenes", default="cornell-box,indirect-room,spheres,caustic")
    ap.add_argument("--spp", type=int, default=1024)
    ap.add_argument("--ref-spp", type=int, default=8192)
    ap.add_argument("--thresholds", default="0.3,0.2,0.14,0.1,0.07,0.05,0.035,0.025")
    ap.add_argument("--min-samples", type=int, default=0)
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--full", action="store_true", help="full resolution (slow)")
    args = ap.parse_args()
    candela = convergence.candela_binary("adaptive_sampling.py")
    os.makedirs(args.out, exist_ok=True)
    quick = [] if args.full else ["--quick"]
    env = dict(os.environ, CANDELA=candela)
    thresholds = [float(t) for t in args.thresholds.split(",")]
    minimum = ["--adaptive-min-samples", str(args.min_samples)] if args.min_samples else []
    lines = []
    for name in args.scenes.split(","):
        if name not in convergence.SCENES:
            sys.exit(f"adaptive_sampling.py: unknown scene {name}")
        scene_path = os.path.join(ROOT, convergence.SCENES[name])
        text = open(scene_path).read()
        method = convergence.REFERENCE_METHOD.get(name, "path")
        ref_scene = os.path.join(os.path.dirname(scene_path), f".{name}-reference.pbrt")
        with open(ref_scene, "w") as f:
            f.write(convergence.with_integrator(text, method, name))
        try:
            ref = subprocess.run([os.path.join(ROOT, "tools", "reference.sh"), ref_scene,
                                  str(args.ref_spp), "1000"] + quick, env=env, check=True,
                                 capture_output=True, text=True).stdout.strip()
        finally:
            os.remove(ref_scene)
        # Path tracing at the reference's depth, the scene's own sampler.
        with tempfile.NamedTemporaryFile("w", suffix=".pbrt", dir=os.path.dirname(scene_path),
                                         delete=False) as f:
            f.write(convergence.with_integrator(text, "path", name))
        try:
            uniform = render(candela, f.name, ref, os.path.join(args.out, f"{name}-uniform.csv"),
                             args.spp, args.threads, quick, [])
            finished = []
            for t in thresholds:
                rows = render(candela, f.name, ref,
                              os.path.join(args.out, f"{name}-adaptive-{t}.csv"), args.spp,
                              args.threads, quick, ["--noise-threshold", str(t)] + minimum)
                finished.append((t, rows[-1]))
        finally:
            os.remove(f.name)
        pixels = uniform[-1]["samples"] / uniform[-1]["spp"]
        lines.append(f"\n### {name}\n")
        lines.append("| target relMSE | uniform s | adaptive s | uniform / adaptive |")
        lines.append("|---|---|---|---|")
        curve = sorted((r for _, r in finished), key=lambda r: r["seconds"])
        for target in TARGETS:
            tu = convergence.time_to(uniform, target)
            ta = convergence.time_to(curve, target)
            ratio = f"{tu / ta:.2f}" if tu and ta else "-"
            lines.append(f"| {target:g} | {convergence.fmt(tu)} | {convergence.fmt(ta)} | {ratio} |")
        lines.append("")
        lines.append("| noise threshold | s | mean spp | relMSE | predicted relMSE |")
        lines.append("|---|---|---|---|---|")
        for t, r in finished:
            lines.append(f"| {t:g} | {r['seconds']:.3f} | {r['samples'] / pixels:.1f} | "
                         f"{r['relmse']:.3g} | {r['relmse_predicted']:.3g} |")
        u = uniform[-1]
        lines.append(f"| uniform, {int(u['spp'])} spp | {u['seconds']:.3f} | {u['spp']:.0f} | "
                     f"{u['relmse']:.3g} | {u['relmse_predicted']:.3g} |")
    convergence.write_report(os.path.join(args.out, "adaptive.md"), lines)


if __name__ == "__main__":
    main()
