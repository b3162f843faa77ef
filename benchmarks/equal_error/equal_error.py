#!/usr/bin/python3
"""Equal error: renderers side by side on one scene, by error per sample and time to an error.

    benchmarks/equal_error/equal_error.py [--scene FILE] [--spp 16,32,64,128] [--seeds 3]
        [--ref-spp 2048] [--reference A.exr B.exr] [--threads 1] [--targets 0.03,0.01]
        [--candela build/candela] [--pbrt-v3 PATH] [--pbrt-v4 PATH] [--blender PATH]
        [--own-reference pbrt-v4] [--out DIR] [--csv FILE]

The scene (default ../shared/scenes/peer/cornell-glass.pbrt, a Cornell box with a diffuse and
a glass sphere) is rendered by candela at each sample count with --seeds seeds, and, when they
are given or found on PATH (pbrt, blender), by pbrt-v3, pbrt-v4 (after its --upgrade) and
Blender Cycles (benchmarks/equal_error/cycles_scene.py builds the scene in Blender). Every image
is measured with `candela compare` against one reference: two candela renders of --ref-spp / 2
samples each with seeds 1000001 and 1000002 (cached by tools/reference.sh, all cores), whose own
noise compare takes off; a renderer named in --own-reference (pbrt-v4, which renders spectrally
and so differs from RGB renderers by 1-4% on coloured walls) is measured against two renders of
its own made the same way instead. relMSE is --error-log's: the mean over pixels and channels
of (x - ref)^2 / (ref^2 + 0.01). The outlier share is the part of it in the 100 worst pixels.

Time is the CPU time (user + system) of the renderer's process with --threads threads (one by
default: no parallel scaling in the figures), from start to exit: parsing and building the scene
are part of it. For Blender, whose start-up takes about ten seconds before the scene exists,
the render's own CPU time as cycles_scene.py measures it around the render call (which includes
Cycles' scene sync and BVH build) is used instead.

Printed per renderer: CPU s per sample and the fixed CPU s (a least-squares line through CPU time
against the sample count), relMSE at each count (mean over seeds), the outlier share at the
largest count, the image mean's offset from the reference's, and CPU s to each target relMSE:
relMSE * spp is fitted as a constant over the counts (the estimators' error falls as 1/spp), the
count that reaches the target follows, and its time from the line; marked '*' when that count
lies beyond the largest one rendered.
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEFAULT_SCENE = os.path.join(ROOT, "..", "shared", "scenes", "peer", "cornell-glass.pbrt")
CYCLES_SCRIPT = os.path.join(ROOT, "benchmarks", "equal_error", "cycles_scene.py")
REFERENCE_SEEDS = (1000001, 1000002)


def fail(message):
    sys.exit("equal_error.py: error: " + message)


def run(cmd, log, what):
    """Runs cmd, its stderr into log; returns (CPU seconds of the process, its stdout)."""
    with open(log, "w") as err, tempfile.TemporaryFile("w+") as out:
        p = subprocess.Popen(cmd, stdout=out, stderr=err, text=True)
        _, status, usage = os.wait4(p.pid, 0)
        code = os.waitstatus_to_exitcode(status)
        out.seek(0)
        stdout = out.read()
    if code != 0:
        with open(log) as f:
            tail = f.read()[-2000:]
        fail("%s failed (exit %d): %s\n%s" % (what, code, " ".join(cmd), tail))
    return usage.ru_utime + usage.ru_stime, stdout


def with_sampler_count(text, spp):
    """The scene text with its Sampler's pixelsamples set to spp (pbrt-v3 has no --spp)."""
    pattern = re.compile(r'("integer pixelsamples"\s*\[?\s*)(\d+)')
    if not pattern.search(text):
        fail("the scene's Sampler gives no \"integer pixelsamples\" to set for pbrt-v3")
    return pattern.sub(lambda m: m.group(1) + str(spp), text, count=1)


def compare(candela, images, refs):
    cmd = [candela, "compare", *images, "--reference", refs[0], "--reference", refs[1]]
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode != 0:
        fail("candela compare failed: " + out.stderr.strip())
    rows = {}
    for line in out.stdout.splitlines():
        fields = dict(kv.split("=", 1) for kv in line.split())
        rows[fields["image"]] = fields
    return rows


class Renderer:
    """One renderer: render(spp, seed, out) returns CPU seconds."""

    def __init__(self, name, seeds):
        self.name = name
        self.seeds = seeds  # the seeds it can vary; pbrt-v3 has none


def candela_renderer(args, scene):
    r = Renderer("candela", list(range(1, args.seeds + 1)))

    def render(spp, seed, out, log, threads):
        cmd = [args.candela, scene, "--spp", str(spp), "--seed", str(seed), "--nthreads",
               str(threads), "-o", out, "--preview", "none", "-q"]
        return run(cmd, log, "candela")[0]
    r.render = render
    return r


def pbrt_v3_renderer(args, scene, work):
    r = Renderer("pbrt-v3", [0])
    text = open(scene).read()
    if re.search(r"^\s*Include", text, re.M):
        fail("pbrt-v3 runs on a copy of the scene with its sample count set; scenes with "
             "Include are not supported")

    def render(spp, seed, out, log, threads):
        copy = os.path.join(work, "pbrt-v3-%d.pbrt" % spp)
        with open(copy, "w") as f:
            f.write(with_sampler_count(text, spp))
        cmd = [args.pbrt_v3, "--nthreads", str(threads), "--quiet", "--outfile", out, copy]
        return run(cmd, log, "pbrt-v3")[0]
    r.render = render
    return r


def pbrt_v4_renderer(args, scene, work):
    r = Renderer("pbrt-v4", list(range(1, args.seeds + 1)))
    upgraded = os.path.join(work, "scene-v4.pbrt")
    code = subprocess.run([args.pbrt_v4, "--upgrade", scene], capture_output=True, text=True)
    if code.returncode != 0:
        fail("pbrt-v4 --upgrade failed: " + code.stderr.strip())
    with open(upgraded, "w") as f:
        f.write(code.stdout)

    def render(spp, seed, out, log, threads):
        cmd = [args.pbrt_v4, "--nthreads", str(threads), "--spp", str(spp), "--seed",
               str(seed), "--quiet", "--outfile", out, upgraded]
        return run(cmd, log, "pbrt-v4")[0]
    r.render = render
    return r


def cycles_renderer(args, scene):
    r = Renderer("cycles", list(range(1, args.seeds + 1)))

    def render(spp, seed, out, log, threads):
        cmd = [args.blender, "-b", "--factory-startup", "--python", CYCLES_SCRIPT, "--", scene,
               "--spp", str(spp), "--seed", str(seed), "--threads", str(threads), "--out", out]
        _, stdout = run(cmd, log, "blender")
        m = re.search(r"cycles: seconds=([0-9.eE+-]+)", stdout)
        if not m:
            fail("cycles_scene.py printed no 'cycles: seconds=' line (log: %s)" % log)
        return float(m.group(1))
    r.render = render
    return r


def own_reference(r, args, work):
    """Two renders of the scene by r itself (seeds as candela's reference, all cores): for a
    renderer whose image differs from candela's by design (pbrt-v4 renders spectrally: 1-4% in
    the coloured walls of the Cornell box), so that its relMSE measures its noise, not that."""
    refs = []
    for seed in REFERENCE_SEEDS:
        out = os.path.join(work, "%s-reference-%d-%d.exr" % (r.name, args.ref_spp // 2, seed))
        if not os.path.isfile(out):
            r.render(args.ref_spp // 2, seed, out, out + ".log", os.cpu_count() or 1)
        refs.append(out)
    return refs


def fit_line(xs, ys):
    """Least squares y = a + b x; (a, b)."""
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    if sxx == 0:
        return 0.0, my / mx
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    return my - b * mx, b


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scene", default=DEFAULT_SCENE)
    ap.add_argument("--spp", default="16,32,64,128")
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--ref-spp", type=int, default=2048)
    ap.add_argument("--reference", nargs=2, metavar=("A", "B"),
                    help="two independent reference renders instead of building them")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--targets", default="0.03,0.01")
    ap.add_argument("--candela", default=os.path.join(ROOT, "build", "candela"))
    ap.add_argument("--pbrt-v3", dest="pbrt_v3", default=None,
                    help="pbrt-v3's binary (default: none; 'auto': pbrt on PATH if it says 3)")
    ap.add_argument("--pbrt-v4", dest="pbrt_v4", default=None,
                    help="pbrt-v4's binary (default: none; 'auto': pbrt on PATH if it says 4)")
    ap.add_argument("--blender", default="auto",
                    help="Blender's binary for Cycles ('auto': blender on PATH; 'none')")
    ap.add_argument("--own-reference", default="pbrt-v4",
                    help="renderers measured against references of their own (comma-separated)")
    ap.add_argument("--out", default=None, help="keep the images here (default: a temp dir)")
    ap.add_argument("--csv", default=None, help="also write the rows here")
    args = ap.parse_args()

    scene = os.path.abspath(args.scene)
    if not os.path.isfile(scene):
        fail("%s: no such scene file" % scene)
    if not os.access(args.candela, os.X_OK):
        fail("%s: no candela binary (build first: tools/setup.sh build)" % args.candela)
    spps = sorted(int(s) for s in args.spp.split(","))
    args.own_reference = [n for n in args.own_reference.split(",") if n]
    targets = [float(t) for t in args.targets.split(",")]
    for name in ("pbrt_v3", "pbrt_v4"):
        v = getattr(args, name)
        if v == "auto":
            found = shutil.which("pbrt")
            version = subprocess.run([found, "--version"], capture_output=True,
                                     text=True).stdout if found else ""
            want = "3" if name == "pbrt_v3" else "4"
            setattr(args, name, found if found and ("version " + want) in version else None)
    if args.blender == "auto":
        args.blender = shutil.which("blender")
    elif args.blender == "none":
        args.blender = None

    work = args.out or tempfile.mkdtemp(prefix="equal-error-")
    os.makedirs(work, exist_ok=True)

    if args.reference:
        refs = args.reference
    else:
        refs = []
        for seed in REFERENCE_SEEDS:
            out = subprocess.run([os.path.join(ROOT, "tools", "reference.sh"), scene,
                                  str(args.ref_spp // 2), str(seed)],
                                 capture_output=True, text=True,
                                 env=dict(os.environ, CANDELA=args.candela))
            if out.returncode != 0:
                fail("tools/reference.sh failed: " + out.stderr.strip())
            refs.append(out.stdout.strip().splitlines()[-1])

    renderers = [candela_renderer(args, scene)]
    if args.pbrt_v3:
        renderers.append(pbrt_v3_renderer(args, scene, work))
    if args.pbrt_v4:
        renderers.append(pbrt_v4_renderer(args, scene, work))
    if args.blender:
        renderers.append(cycles_renderer(args, scene))

    rows = []
    for r in renderers:
        images = {}
        cpu = {}
        for spp in spps:
            for seed in r.seeds:
                out = os.path.join(work, "%s-%d-%d.exr" % (r.name, spp, seed))
                log = out + ".log"
                cpu[(spp, seed)] = r.render(spp, seed, out, log, args.threads)
                images[(spp, seed)] = out
                print("%s: %d spp, seed %d: %.2f CPU s" % (r.name, spp, seed, cpu[(spp, seed)]),
                      file=sys.stderr)
        own = r.name in args.own_reference
        metrics = compare(args.candela, list(images.values()),
                          own_reference(r, args, work) if own else refs)
        per_spp = {}
        for spp in spps:
            ms = [metrics[images[(spp, s)]] for s in r.seeds]
            mean = lambda key: sum(float(m[key]) for m in ms) / len(ms)
            offset = sum(mean("mean_" + c) / mean("ref_mean_" + c) - 1 for c in "rgb") / 3
            per_spp[spp] = {"cpu": sum(cpu[(spp, s)] for s in r.seeds) / len(r.seeds),
                            "relmse": mean("relmse"), "share": mean("outlier_share"),
                            "offset": offset, "noise": mean("reference_noise")}
        fixed, per_sample = fit_line(spps, [per_spp[s]["cpu"] for s in spps])
        # relMSE ~ a / spp: a from the counts, each weighted by its own relMSE's reliability
        # alike (a plain mean of relMSE * spp).
        a = sum(per_spp[s]["relmse"] * s for s in spps) / len(spps)
        to_target = []
        for t in targets:
            need = a / t
            seconds = fixed + per_sample * need
            to_target.append((seconds, need > spps[-1]))
        rows.append((r.name + (" (own reference)" if own else ""), per_sample, fixed, per_spp,
                     to_target))

    largest = spps[-1]
    head = ("| renderer | CPU s per sample | fixed CPU s | " +
            " | ".join("relMSE at %d spp" % s for s in spps) +
            " | outlier share at %d spp | mean offset | " % largest +
            " | ".join("CPU s to relMSE %g" % t for t in targets) + " |")
    print("scene: %s; %d thread(s); reference: %s (noise %.2g)" %
          (scene, args.threads, " + ".join(refs), rows[0][3][largest]["noise"]))
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    for name, per_sample, fixed, per_spp, to_target in rows:
        cells = [name, "%.4f" % per_sample, "%.2f" % fixed]
        cells += ["%.4f" % per_spp[s]["relmse"] for s in spps]
        cells += ["%.2f" % per_spp[largest]["share"], "%+.2f%%" % (100 * per_spp[largest]["offset"])]
        cells += ["%.1f%s" % (sec, "*" if beyond else "") for sec, beyond in to_target]
        print("| " + " | ".join(cells) + " |")
    print("(* extrapolated beyond %d spp; seeds per count: %s)" %
          (largest, ", ".join("%s %d" % (r.name, len(r.seeds)) for r in renderers)))
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["renderer", "spp", "cpu_s", "relmse", "outlier_share", "mean_offset"])
            for name, _, _, per_spp, _ in rows:
                for s in spps:
                    p = per_spp[s]
                    w.writerow([name, s, "%.4f" % p["cpu"], "%.6g" % p["relmse"],
                                "%.4f" % p["share"], "%.5f" % p["offset"]])
    if not args.out:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
