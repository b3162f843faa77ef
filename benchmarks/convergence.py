#!/usr/bin/python3
"""Convergence benchmark: error against run time for the example scenes x integrators x samplers.

    benchmarks/convergence.py [--out DIR] [--spp N] [--ref-spp N] [--full]
                              [--scenes a,b] [--methods path/stratified,...]

Renders each scene's reference once (tools/reference.sh caches it; path tracing at --ref-spp,
bidirectional for the caustic scene),
then each method with --reference and --error-log, and writes DIR/convergence.csv (the table),
DIR/convergence.md (the same as Markdown) and one plot per scene DIR/<scene>.png
(tools/plot_convergence.py). By default scenes render at --quick resolution so the whole run takes
a few minutes on two cores.

Columns: time to reach relMSE 1e-2 and 1e-3 (log-log interpolation between passes; '-' when not
reached), and relMSE at equal time (the shortest total time of the scene's runs).
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = {"cornell-box": "scenes/cornell-box/cornell-box.pbrt",
          "caustic": "scenes/caustic/caustic.pbrt",
          "indirect-room": "scenes/indirect-room/indirect-room.pbrt",
          "spheres": "scenes/spheres/spheres.pbrt",
          # pbrt-v3 media: only "volpath" renders them (run with --scenes smoke
          # --methods volpath/random,volpath/stratified; the other integrators ignore media).
          "smoke": "scenes/smoke/smoke.pbrt",
          # pbrt-v2 Volume regions (homogeneous fog; the smoke as a volumegrid): "single" against
          # "volpath1", volpath limited to one scattering event, which estimates the same image
          # (run with --scenes fog,smoke-grid --methods single/stratified,volpath1/stratified).
          "fog": "scenes/fog/fog.pbrt",
          "smoke-grid": "scenes/smoke-grid/smoke-grid.pbrt"}
# Each scene's size, for the parameters given in scene units (the photon search radius).
SCENE_SIZE = {"cornell-box": 550, "caustic": 16, "indirect-room": 10, "spheres": 10, "smoke": 10,
              "fog": 10, "smoke-grid": 10}
DEFAULT_SCENES = ["cornell-box", "caustic", "indirect-room"]
# The method that renders each scene's reference: path tracing, except where it converges too
# slowly to serve (the caustic of a small light seen through glass: bidirectional).
REFERENCE_METHOD = {"caustic": "bdpt", "smoke": "volpath", "fog": "volpath1",
                    "smoke-grid": "volpath1"}
# "single"'s ray-marching step, in scene units (the scene files' own).
SINGLE_STEP = {"fog": 0.1, "smoke-grid": 0.02}
# Every method at its scene-file defaults except the depth of the unbiased ones, which matches the
# reference's (deep enough that Russian roulette, not the limit, ends the paths), and the photon
# radii, in scene units: photonmap's maxdist a hundredth of the scene, SPPM's initial radius about
# an eightieth (smaller ones left the caustic scene speckled at 64 iterations). --spp sets SPPM's
# iterations; it takes no Sampler, so one sampler suffices.
INTEGRATORS = {"path": '"path" "integer maxdepth" [100]',
               # Path guiding (Müller et al. 2017): a quarter of the samples train the field.
               "pathguided": '"path" "integer maxdepth" [100] "bool guiding" "true"',
               "volpath": '"volpath" "integer maxdepth" [100]',
               "volpath1": '"volpath" "integer maxdepth" [1]',
               # pbrt-v2's pair for Volume regions: surfaces lit directly, the volume by single
               # scattering.
               "single": '"directlighting"\nVolumeIntegrator "single" "float stepsize" [{step}]',
               "directlighting": '"directlighting"',
               "bdpt": '"bdpt" "integer maxdepth" [100]',
               "photonmap": '"photonmap" "float maxdist" [{maxdist}]',
               "irradiancecache": '"irradiancecache"',
               "igi": '"igi"',
               "sppm": '"sppm" "integer maxdepth" [100] "float radius" [{radius}]',
               # Its bootstrap takes bootstrapsamples x (maxdepth + 1) paths: depth 8, so it
               # leaves out light of more than 8 bounces that the reference has.
               "mlt": '"mlt" "integer maxdepth" [8]'}
SPPM_RADIUS = {"cornell-box": 8, "caustic": 0.2, "indirect-room": 0.2, "spheres": 0.2,
               "smoke": 0.2, "fog": 0.2, "smoke-grid": 0.2}
SAMPLERS = {"stratified": '"stratified"', "random": '"random"'}
DEFAULT_METHODS = ["path/stratified", "path/random", "directlighting/stratified",
                   "bdpt/stratified", "photonmap/stratified", "irradiancecache/stratified",
                   "igi/stratified", "sppm/stratified", "mlt/stratified"]


def integrator_statement(integrator, scene):
    return "SurfaceIntegrator " + INTEGRATORS[integrator].format(
        maxdist=SCENE_SIZE[scene] / 100, radius=SPPM_RADIUS[scene],
        step=SINGLE_STEP.get(scene, 1))


def with_integrator(scene_text, integrator, scene):
    """The scene with its (Surface/Volume)Integrator statements replaced by the method's."""
    s = re.sub(r'^VolumeIntegrator [^\n]*\n', "", scene_text, flags=re.M)
    return re.sub(r'^(Surface)?Integrator .*$', lambda m: integrator_statement(integrator, scene), s,
                  flags=re.M)


def variant(scene_text, integrator, sampler, scene):
    s = with_integrator(scene_text, integrator, scene)
    return re.sub(r'^Sampler [^\n]*$', "Sampler " + SAMPLERS[sampler], s, flags=re.M)


def read_log(path):
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def time_to(rows, target):
    prev = None
    for r in rows:
        if r["relmse"] <= target:
            if prev is None:
                return r["seconds"]
            # Interpolate in log-log between the passes on either side of the target.
            lx0, lx1 = math.log(prev["seconds"]), math.log(r["seconds"])
            ly0, ly1 = math.log(prev["relmse"]), math.log(r["relmse"])
            t = (math.log(target) - ly0) / (ly1 - ly0) if ly1 != ly0 else 1
            return math.exp(lx0 + t * (lx1 - lx0))
        prev = r
    return None


def error_at(rows, seconds):
    """relMSE at `seconds`, interpolated log-log; None when the first pass ended later."""
    if not rows or seconds < rows[0]["seconds"]:
        return None
    pts = [(math.log(r["seconds"]), math.log(r["relmse"])) for r in rows if r["seconds"] > 0]
    for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
        if x0 <= math.log(seconds) <= x1:
            t = (math.log(seconds) - x0) / (x1 - x0) if x1 != x0 else 0
            return math.exp(y0 + t * (y1 - y0))
    return rows[-1]["relmse"] if rows else None


def candela_binary(tool):
    """$CANDELA or build/candela; exits naming the tool when it is not built."""
    candela = os.environ.get("CANDELA", os.path.join(ROOT, "build", "candela"))
    if not os.access(candela, os.X_OK):
        sys.exit(f"{tool}: no candela at {candela} (build first)")
    return candela


def write_report(path, lines):
    """Writes the Markdown lines to path and prints them."""
    text = "\n".join(lines) + "\n"
    with open(path, "w") as f:
        f.write(text)
    print(text)


def fmt(value):
    return "-" if value is None else f"{value:.3g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "convergence"))
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--ref-spp", type=int, default=4096)
    ap.add_argument("--full", action="store_true", help="full resolution (slow)")
    ap.add_argument("--scenes", default=",".join(DEFAULT_SCENES),
                    help="comma-separated, of: " + ", ".join(SCENES))
    ap.add_argument("--methods", default=",".join(DEFAULT_METHODS),
                    help="comma-separated integrator/sampler pairs, of: " +
                    ", ".join(INTEGRATORS) + " / " + ", ".join(SAMPLERS))
    args = ap.parse_args()
    scenes = args.scenes.split(",")
    methods = [m.split("/") for m in args.methods.split(",")]
    for name in scenes:
        if name not in SCENES:
            sys.exit(f"convergence.py: unknown scene {name} (known: {', '.join(SCENES)})")
    for m in methods:
        if len(m) != 2 or m[0] not in INTEGRATORS or m[1] not in SAMPLERS:
            sys.exit(f"convergence.py: bad method {'/'.join(m)}")
    candela = candela_binary("convergence.py")
    os.makedirs(args.out, exist_ok=True)
    quick = [] if args.full else ["--quick"]
    env = dict(os.environ, CANDELA=candela)
    table = []
    for name in scenes:
        scene_path = os.path.join(ROOT, SCENES[name])
        text = open(scene_path).read()
        # The reference is path tracing (or REFERENCE_METHOD's) of the same depth as the "path"
        # method, whatever the scene file selects; a fixed file name keeps tools/reference.sh's
        # cache.
        ref_scene = os.path.join(os.path.dirname(scene_path), f".{name}-reference.pbrt")
        with open(ref_scene, "w") as f:
            f.write(with_integrator(text, REFERENCE_METHOD.get(name, "path"), name))
        try:
            ref = subprocess.run([os.path.join(ROOT, "tools", "reference.sh"), ref_scene,
                                  str(args.ref_spp), "1000"] + quick, env=env, check=True,
                                 capture_output=True, text=True).stdout.strip()
        finally:
            os.remove(ref_scene)
        logs = {}
        for integ, samp in methods:
            label = f"{integ}/{samp}"
            log = os.path.join(args.out, f"{name}-{integ}-{samp}.csv")
            if os.path.exists(log):
                os.remove(log)
            with tempfile.NamedTemporaryFile("w", suffix=".pbrt", dir=os.path.dirname(scene_path),
                                             delete=False) as f:
                f.write(variant(text, integ, samp, name))
            try:
                subprocess.run([candela, f.name, "--spp", str(args.spp), "--seed", "1",
                                "--reference", ref, "--error-log", log, "-o",
                                os.path.join(args.out, "last.exr"), "--preview", "none",
                                "--quiet"] + quick, check=True)
            finally:
                os.remove(f.name)
            logs[label] = read_log(log)
        equal_time = min(rows[-1]["seconds"] for rows in logs.values())
        for label, rows in logs.items():
            t2, t3 = time_to(rows, 1e-2), time_to(rows, 1e-3)
            table.append({"scene": name, "method": label,
                          "t_relmse_1e-2_s": f"{t2:.3f}" if t2 else "-",
                          "t_relmse_1e-3_s": f"{t3:.3f}" if t3 else "-",
                          "equal_time_s": f"{equal_time:.3f}",
                          "relmse_at_equal_time": fmt(error_at(rows, equal_time)),
                          "final_spp": int(rows[-1]["spp"]),
                          "final_relmse": f"{rows[-1]['relmse']:.3g}"})
        subprocess.run([os.path.join(ROOT, "tools", "plot_convergence.py"),
                        os.path.join(args.out, f"{name}.png"), "--title", name] +
                       [f"{label}={os.path.join(args.out, name + '-' + label.replace('/', '-') + '.csv')}"
                        for label in logs], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(args.out, "convergence.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0].keys()))
        w.writeheader()
        w.writerows(table)
    with open(os.path.join(args.out, "convergence.md"), "w") as f:
        keys = list(table[0].keys())
        f.write("| " + " | ".join(keys) + " |\n|" + "---|" * len(keys) + "\n")
        for r in table:
            f.write("| " + " | ".join(str(r[k]) for k in keys) + " |\n")
    print(open(os.path.join(args.out, "convergence.md")).read())


if __name__ == "__main__":
    main()
