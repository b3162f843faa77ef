#!/usr/bin/python3
"""Two candela builds on the same scenes: render time (best of N runs, alternating builds so that
load on the machine falls on both), rays traced, and whether the images are the same bits.

    benchmarks/compare_builds.py OLD_CANDELA NEW_CANDELA [--scenes a,b] [--scene-dir DIR]...
        [--spp 16] [--runs 4]

Scenes are names under scenes/ (scenes/NAME/NAME.pbrt) or paths to .pbrt files, and with
--scene-dir every .pbrt file in DIR (--scenes '' for those alone), rendered with --spp and
--seed 1 at full resolution. Used to show what a change costs scenes that do not use it (a scene without media
after media landed: docs/scene-support.md, "Media and volpath").
"""
import argparse
import os
import re
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def render(candela, scene, spp, out):
    r = subprocess.run([candela, scene, "--spp", str(spp), "--seed", "1", "-o", out,
                        "--preview", "none"], capture_output=True, text=True, check=True)
    m = re.search(r"Render time ([0-9.]+)s.* ([0-9]+) rays", r.stderr + r.stdout)
    if not m:
        raise SystemExit(f"compare_builds.py: no render time in the output of {candela} {scene}")
    return float(m.group(1)), int(m.group(2))


def same_pixels(a, b):
    # idiff (OpenImageIO's tools) with zero tolerance: any difference fails.
    r = subprocess.run(["idiff", "-fail", "0", "-warn", "0", a, b], capture_output=True, text=True)
    return r.returncode == 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--scenes", default="cornell-box,spheres,indirect-room")
    ap.add_argument("--scene-dir", action="append", default=[],
                    help="also every .pbrt file in this folder (repeatable)")
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--runs", type=int, default=4)
    args = ap.parse_args()
    print("| scene | old best s | new best s | new/old | rays old | rays new | same bits |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        scenes = []
        for name in filter(None, args.scenes.split(",")):
            scenes.append((name, name if name.endswith(".pbrt") else
                           os.path.join(ROOT, "scenes", name, name + ".pbrt")))
        for d in args.scene_dir:
            scenes += [(f[:-5], os.path.join(d, f)) for f in sorted(os.listdir(d))
                       if f.endswith(".pbrt")]
        for name, scene in scenes:
            times = {"old": [], "new": []}
            rays = {}
            for _ in range(args.runs):
                for which in ("old", "new"):
                    t, n = render(getattr(args, which), scene, args.spp,
                                  os.path.join(tmp, which + ".exr"))
                    times[which].append(t)
                    rays[which] = n
            same = same_pixels(os.path.join(tmp, "old.exr"), os.path.join(tmp, "new.exr"))
            old, new = min(times["old"]), min(times["new"])
            print(f"| {name} | {old:.2f} | {new:.2f} | {new / old:.3f} | {rays['old']} | "
                  f"{rays['new']} | {'yes' if same else 'no'} |")


if __name__ == "__main__":
    main()
