#!/usr/bin/python3
"""The scene suite: time to a clean image for candela's configurations and, where installed, peers.

    benchmarks/suite.py [--scenes a,b] [--configs uniform,adaptive,...] [--spp N] [--ref-spp N]
                        [--jobs 2] [--pbrt-v4 PATH] [--blender PATH|auto|none] [--out DIR]

Every scene renders with path tracing (its own integrator where that is `path`, else `path` at
the depth SUITE gives) in each of candela's configurations:
  uniform    the scene as written: the same sample count in every pixel
  adaptive   --noise-threshold at each of THRESHOLDS (one render each, a point per threshold)
  bvh        --light-sampler bvh (the light tree)
  guided     --guiding (an SD-tree trained in the first passes)
  bvh+adaptive, guided+adaptive, guided+bvh: both
and, on scenes in the subset they can read (PEER scenes), with pbrt-v4 (--pbrt-v4, on the file
as `pbrt --upgrade` writes it) and Blender Cycles (benchmarks/equal_error/cycles_scene.py) at
each power of two up to --spp.

Time is CPU seconds of one thread (user + system of the renderer's process, parsing and
building included), so that --jobs renders can share the cores without changing the figures
much; for candela's doubling passes (--error-log) each pass's time is its log's seconds plus the
process's set-up (its CPU time less the last pass's seconds). Error is relMSE against one
reference of 16 x the scene's count (--ref-spp; tools/reference.sh, seed 1000; the scene's own
integrator, bdpt for REFERENCE_BDPT scenes), the same measure --error-log and `candela compare`
use; pbrt-v4, which renders spectrally, is measured against two renders of its own (as
benchmarks/equal_error does). At 16 x the runs' largest count the reference's own noise adds
about a sixteenth to the final relMSE of a uniform run.

Written to DIR (default out/suite): suite.csv and suite.md (per scene and configuration: CPU s to
relMSE 1e-2 and 1e-3, interpolated log-log between points, or, marked '*', extrapolated past the
last one as relMSE ~ 1 / time; relMSE at the scene's equal time, the shortest of its runs' total
times, '-' when the run's first point came later; the samples per pixel asked for and taken on
average, the relMSE of the last point, the image mean's offset from the reference's (of the
finished images: the last one, or for adaptive configurations the threshold's image furthest
off) and the last point's CPU s) and one plot per scene, DIR/<scene>.png
(tools/plot_convergence.py). An adaptive configuration's first point is its minimum count (16
spp): a target uniform sampling meets with fewer samples it meets no sooner than that.
"""
import argparse
import concurrent.futures
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "equal_error"))
import convergence  # noqa: E402  (log readers and interpolation)
import equal_error  # noqa: E402  (the peer renderers)

ROOT = convergence.ROOT
SHARED = os.path.join(ROOT, "..", "shared", "scenes")


class Scene:
    def __init__(self, path, quick=True, integrator=None, drop=(), spp=256, peers=False,
                 make=None, note="", replace=()):
        self.replace = replace      # (old, new) text replacements
        self.ref_spp = 16 * spp     # the reference's count: its noise a sixteenth of a run's
        self.path = path            # relative to the repository, or absolute
        self.quick = quick          # render at --quick's quarter resolution
        self.integrator = integrator  # replaces the file's integrator statement when given
        self.drop = drop            # statements to remove (pbrt-v2's Renderer)
        self.spp = spp
        self.peers = peers          # in the subset pbrt-v4 --upgrade and cycles_scene.py read
        self.make = make            # a script that writes the file when it is missing
        self.note = note


SUITE = {
    "cornell-box": Scene("scenes/cornell-box/cornell-box.pbrt", note="pbrt-v2 dialect, one quad light"),
    "caustic": Scene("scenes/caustic/caustic.pbrt", note="a small light seen through a glass sphere"),
    "indirect-room": Scene("scenes/indirect-room/indirect-room.pbrt",
                           note="a room lit through a doorway"),
    "spheres": Scene("scenes/spheres/spheres.pbrt", note="matte, plastic, metal, glass spheres"),
    "materials": Scene("scenes/materials/materials.pbrt", note="glossy materials side by side"),
    "many-lights": Scene("scenes/many-lights/many-lights.pbrt", quick=False,
                         make="scenes/many-lights/make_many_lights.py",
                         note="10,000 small emissive quads over a floor, 64 x 48"),
    "cornell-glass": Scene(os.path.join(SHARED, "peer", "cornell-glass.pbrt"), quick=False,
                           spp=128, peers=True,
                           note="pbrt-v3, Cornell box with a glass sphere, 256 x 256, depth 8"),
    "killeroo-simple": Scene(os.path.join(SHARED, "pbrt-v2", "killeroo-simple.pbrt"),
                             integrator='SurfaceIntegrator "path" "integer maxdepth" [8]',
                             spp=128, note="pbrt-v2's scene, Loop subdivision, path tracing to depth 8"),
    "metal": Scene(os.path.join(SHARED, "pbrt-v2", "metal.pbrt"),
                   integrator='SurfaceIntegrator "path" "integer maxdepth" [8]', drop=("Renderer",),
                   spp=128, replace=(("uffizi_latlong", "grace_latlong"),),
                   note="pbrt-v2's scene: rough metals under an environment map (grace, as the "
                   "uffizi map is not in ../shared), depth 8"),
}
DEFAULT_SCENES = list(SUITE)
# The adaptive ladder: relMSE aims at about T^2 (docs/error-and-time.md).
THRESHOLDS = [0.2, 0.1, 0.05, 0.025, 0.0125]
CONFIGS = {"uniform": [], "adaptive": None, "bvh": ["--light-sampler", "bvh"],
           "guided": ["--guiding"], "bvh+adaptive": None, "guided+adaptive": None,
           "guided+bvh": ["--guiding", "--light-sampler", "bvh"]}
ADAPTIVE_BASE = {"adaptive": [], "bvh+adaptive": ["--light-sampler", "bvh"],
                 "guided+adaptive": ["--guiding"]}
DEFAULT_CONFIGS = ["uniform", "adaptive", "bvh", "guided", "guided+adaptive"]
REFERENCE_BDPT = {"caustic"}
TARGETS = [1e-2, 1e-3]


def fail(message):
    sys.exit("suite.py: error: " + message)


def statement_pattern(keyword):
    # A statement and the parameter lines that continue it (lines that start with a quote).
    return re.compile(r'^\s*' + keyword + r'\b[^\n]*\n(?:[ \t]*"[^\n]*\n)*', re.M)


def scene_text(scene, integrator=None):
    text = open(scene_path(scene)).read()
    for old, new in scene.replace:
        text = text.replace(old, new)
    for keyword in scene.drop:
        text = statement_pattern(keyword).sub("", text)
    integrator = integrator or scene.integrator
    if integrator:
        text = statement_pattern(r'(?:Surface)?Integrator').sub(integrator + "\n", text, count=1)
    return text


def scene_path(scene):
    path = scene.path if os.path.isabs(scene.path) else os.path.join(ROOT, scene.path)
    if not os.path.exists(path) and scene.make:
        subprocess.run([sys.executable, os.path.join(ROOT, scene.make)], check=True)
    return path


def written_beside(scene, text, tag):
    """A copy of the scene with text, beside it so that its relative paths still hold."""
    d = os.path.dirname(scene_path(scene))
    with tempfile.NamedTemporaryFile("w", suffix=".pbrt", prefix=f".suite-{tag}-", dir=d,
                                     delete=False) as f:
        f.write(text)
    return f.name


def reference(name, scene, args):
    text = scene_text(scene)
    if name in REFERENCE_BDPT:
        depth = re.search(r'"integer maxdepth"\s*\[\s*(\d+)', text)
        text = statement_pattern(r'(?:Surface)?Integrator').sub(
            'SurfaceIntegrator "bdpt" "integer maxdepth" [%s]\n' % (depth.group(1) if depth else 5),
            text, count=1)
    # A fixed name, so that tools/reference.sh's cache (keyed by the file's bytes) holds.
    path = os.path.join(os.path.dirname(scene_path(scene)), f".suite-{name}-reference.pbrt")
    with open(path, "w") as f:
        f.write(text)
    try:
        out = subprocess.run([os.path.join(ROOT, "tools", "reference.sh"), path,
                              str(args.ref_spp or scene.ref_spp), "1000"] + (["--quick"] if scene.quick else []),
                             env=dict(os.environ, CANDELA=args.candela), capture_output=True,
                             text=True)
    finally:
        os.remove(path)
    if out.returncode != 0:
        fail(f"the reference of {name} failed: {out.stderr.strip()}")
    return out.stdout.strip().splitlines()[-1]


def mean_offset(metrics):
    """The image mean's offset from the reference's, over R, G and B, from `candela compare`."""
    return sum(float(metrics["mean_" + c]) / float(metrics["ref_mean_" + c]) - 1
               for c in "rgb") / 3


def run_candela(args, scene, path, ref, options, log, out):
    """One render with --error-log; its rows with seconds moved to process CPU time."""
    cmd = [args.candela, path, "--spp", str(scene.spp), "--seed", "1", "--nthreads", "1",
           "--reference", ref, "--error-log", log, "-o", out, "--preview", "none", "--quiet"]
    cmd += (["--quick"] if scene.quick else []) + options
    if os.path.exists(log):
        os.remove(log)
    cpu, _ = equal_error.run(cmd, out + ".stderr", "candela")
    rows = convergence.read_log(log)
    setup = max(0.0, cpu - rows[-1]["seconds"])
    # The first pass takes every pixel (one sample, or adaptive sampling's minimum).
    pixels = rows[0]["samples"] / rows[0]["spp"]
    for r in rows:
        r["seconds"] += setup
        r["mean_spp"] = r["samples"] / pixels
    return rows


def candela_curves(name, scene, args, ref, configs, pool):
    """{config: rows}, each row a point (seconds, spp, relmse)."""
    path = written_beside(scene, scene_text(scene), name)
    jobs = {}
    try:
        for c in configs:
            if CONFIGS[c] is not None:
                out = os.path.join(args.out, f"{name}-{c}.exr")
                jobs[(c, None)] = pool.submit(run_candela, args, scene, path, ref, CONFIGS[c],
                                              os.path.join(args.out, f"{name}-{c}.log.csv"), out)
            else:
                for t in THRESHOLDS:
                    out = os.path.join(args.out, f"{name}-{c}-{t}.exr")
                    jobs[(c, t)] = pool.submit(
                        run_candela, args, scene, path, ref,
                        ADAPTIVE_BASE[c] + ["--noise-threshold", str(t)],
                        os.path.join(args.out, f"{name}-{c}-{t}.log.csv"), out)
        curves = {}
        images = {}
        for (c, t), job in jobs.items():
            rows = job.result()
            image = os.path.join(args.out, f"{name}-{c}{'' if t is None else '-' + str(t)}.exr")
            images[image] = rows[-1]
            if t is None:
                curves[c] = rows
            else:
                # The threshold's finished image is the point; its passes are not images a
                # user asking for another threshold would have had.
                curves.setdefault(c, []).append(dict(rows[-1], threshold=t))
                images[image] = curves[c][-1]
        # Each finished image's mean against the reference's (adaptive sampling stops on the
        # samples themselves, so it can be biased: relMSE alone would not show it).
        metrics = equal_error.compare(args.candela, list(images), [ref, ref])
        for image, row in images.items():
            row["offset"] = mean_offset(metrics[image])
        for c in curves:
            curves[c].sort(key=lambda r: r["seconds"])
        return curves
    finally:
        os.remove(path)


def peer_curves(name, scene, args, ref):
    """{peer: rows} for the peers given, at each power of two up to the scene's count."""
    if not scene.peers:
        return {}
    ns = argparse.Namespace(pbrt_v4=args.pbrt_v4, blender=args.blender, seeds=1,
                            ref_spp=args.ref_spp or scene.ref_spp, candela=args.candela)
    work = os.path.join(args.out, f"{name}-peers")
    os.makedirs(work, exist_ok=True)
    path = scene_path(scene)
    peers = []
    if args.pbrt_v4:
        peers.append((equal_error.pbrt_v4_renderer(ns, path, work), True))
    if args.blender:
        peers.append((equal_error.cycles_renderer(ns, path), False))
    counts = [1 << k for k in range(2, 20) if (1 << k) <= scene.spp]
    curves = {}
    for r, own in peers:
        rows = []
        images = []
        for spp in counts:
            out = os.path.join(work, f"{r.name}-{spp}.exr")
            rows.append({"seconds": r.render(spp, 1, out, out + ".log", 1), "spp": spp})
            images.append(out)
        refs = equal_error.own_reference(r, ns, work) if own else [ref, ref]
        metrics = equal_error.compare(args.candela, images, refs)
        for row, image in zip(rows, images):
            row["mean_spp"] = row["spp"]
            row["offset"] = mean_offset(metrics[image])
            # With one reference given twice, relmse_raw is the plain relMSE against it.
            row["relmse"] = float(metrics[image]["relmse" if own else "relmse_raw"])
        curves[r.name + (" (own reference)" if own else "")] = rows
    return curves


def time_to(rows, target):
    """(CPU s to relMSE target, whether extrapolated): interpolated between the points, or past
    the last one as relMSE ~ 1 / time (an unbiased estimator's rate)."""
    t = convergence.time_to(rows, target)
    if t is not None:
        return t, False
    last = rows[-1]
    return last["seconds"] * last["relmse"] / target, True


def fmt_time(value):
    t, extrapolated = value
    return f"{t:.3g}" + ("*" if extrapolated else "")


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["seconds", "spp", "relmse"], extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", default=",".join(DEFAULT_SCENES))
    ap.add_argument("--configs", default=",".join(DEFAULT_CONFIGS),
                    help="comma-separated, of: " + ", ".join(CONFIGS))
    ap.add_argument("--spp", type=int, default=None, help="every scene's count (default: SUITE's)")
    ap.add_argument("--ref-spp", type=int, default=None,
                    help="the references' count (default: 16 x each scene's)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                    help="candela renders at once, one thread each")
    ap.add_argument("--pbrt-v4", dest="pbrt_v4", default=None)
    ap.add_argument("--blender", default="auto", help="'auto': blender on PATH; 'none'")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "suite"))
    args = ap.parse_args()
    args.candela = convergence.candela_binary("suite.py")
    if args.blender == "auto":
        args.blender = shutil.which("blender")
    elif args.blender == "none":
        args.blender = None
    names = args.scenes.split(",")
    configs = args.configs.split(",")
    for n in names:
        if n not in SUITE:
            fail(f"unknown scene {n} (known: {', '.join(SUITE)})")
    for c in configs:
        if c not in CONFIGS:
            fail(f"unknown configuration {c} (known: {', '.join(CONFIGS)})")
    os.makedirs(args.out, exist_ok=True)

    table = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for name in names:
            scene = SUITE[name]
            if args.spp:
                scene.spp = args.spp
                scene.ref_spp = 16 * args.spp
            if not os.path.exists(scene_path(scene)):
                print(f"suite.py: {name}: {scene.path} is not here; skipped", file=sys.stderr)
                continue
            print(f"suite.py: {name}", file=sys.stderr)
            ref = reference(name, scene, args)
            curves = candela_curves(name, scene, args, ref, configs, pool)
            curves.update(peer_curves(name, scene, args, ref))
            equal_time = min(rows[-1]["seconds"] for rows in curves.values())
            plots = []
            for label, rows in curves.items():
                log = os.path.join(args.out, f"{name}-{label.split(' ')[0]}.csv")
                write_csv(log, rows)
                plots.append(f"{label}={log}")
                last = rows[-1]
                t2, t3 = (time_to(rows, t) for t in TARGETS)
                table.append({"scene": name, "configuration": label,
                              "cpu_s_to_1e-2": fmt_time(t2),
                              "cpu_s_to_1e-3": fmt_time(t3),
                              "equal_time_s": f"{equal_time:.3g}",
                              "relmse_at_equal_time": convergence.fmt(
                                  convergence.error_at(rows, equal_time)),
                              "spp": int(last["spp"]),
                              "mean_spp": f"{last['mean_spp']:.3g}",
                              "relmse": f"{last['relmse']:.3g}",
                              "mean_offset": "%+.2f%%" % (100 * max(
                                  (r["offset"] for r in rows if "offset" in r), key=abs)),
                              "cpu_s": f"{last['seconds']:.3g}"})
            plot = subprocess.run([os.path.join(ROOT, "tools", "plot_convergence.py"),
                                   os.path.join(args.out, f"{name}.png"), "--title", name,
                                   "--xlabel", "CPU s (one thread)"] + plots,
                                  capture_output=True, text=True)
            if plot.returncode != 0:
                print(f"suite.py: no plot for {name}: {plot.stderr.strip()}", file=sys.stderr)
    if not table:
        fail("no scene was rendered")
    with open(os.path.join(args.out, "suite.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0]))
        w.writeheader()
        w.writerows(table)
    keys = list(table[0])
    lines = ["| " + " | ".join(keys) + " |", "|" + "---|" * len(keys)]
    lines += ["| " + " | ".join(str(r[k]) for k in keys) + " |" for r in table]
    convergence.write_report(os.path.join(args.out, "suite.md"), lines)


if __name__ == "__main__":
    main()
