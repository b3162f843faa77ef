#!/usr/bin/python3
"""What a candela run costs beyond its render: start-up (CPU and wall time, peak resident set,
shared libraries loaded) on an empty scene, and peak resident set against triangle count, for a
mesh and for many instances of it.

    benchmarks/footprint.py [--candela [LABEL=]PATH ...] [--runs 10] [--triangles 1e4,1e5,1e6]
                            [--instances 1000] [--accel embree,bvh,kdtree,grid] [--csv out.csv]

Cases (each run --preview none unless named, at 32 x 32 pixels and 1 sample per pixel):
  empty          Film 1 x 1, nothing in the world (the issue's figure: 0.16 s, 140 MB, 264 libraries)
  empty+png      the same with its PNG preview (the image plug-in, OpenImageIO, loaded)
  mesh N         a flat grid of N triangles from a binary PLY (Shape "plymesh")
  instanced K    the largest mesh as one ObjectBegin, K ObjectInstances of it (K = 1 and
                 --instances); "bytes per instance" is (peak(K) - peak(1)) / (K - 1)
Every binary given runs every case, alternating (so that load on the machine falls on all).
CPU time (user + system) and peak RSS come from wait4 and are robust to other load; wall time is
not. Libraries are counted in one extra run with LD_DEBUG=files (dlopen'ed ones included).
Times are medians over --runs for the empty scene, over 3 runs for the meshes; RSS the median too.
"""
import argparse
import os
import statistics
import struct
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def grid_ply(path, n):
    """A flat n x n grid of squares over [0, 1]^2 as a binary PLY: 2 n^2 triangles."""
    with open(path, "wb") as f:
        nv, nf = (n + 1) * (n + 1), 2 * n * n
        f.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {nv}\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 f"element face {nf}\nproperty list uchar int vertex_indices\nend_header\n")
                .encode())
        row = bytearray()
        for j in range(n + 1):
            row.clear()
            for i in range(n + 1):
                row += struct.pack("<fff", i / n, j / n, 0.0)
            f.write(row)
        tri = struct.Struct("<Biii")
        for j in range(n):
            row.clear()
            for i in range(n):
                v00 = j * (n + 1) + i
                v10, v01 = v00 + 1, v00 + n + 1
                row += tri.pack(3, v00, v10, v01 + 1) + tri.pack(3, v00, v01 + 1, v01)
            f.write(row)
    return 2 * n * n


HEADER = """Film "image" "integer xresolution" [{res}] "integer yresolution" [{res}]
Sampler "random" "integer pixelsamples" [1]
LookAt {eye} {look} 0 1 0
Camera "perspective" "float fov" [60]
Accelerator "{accel}"
WorldBegin
LightSource "distant" "point from" [0 0 5] "point to" [0 0 0]
"""


def write_scenes(tmp, triangle_counts, instances, accels):
    """(case name, accel, scene path, triangles in the scene, extra args) for every case."""
    cases = []
    empty = os.path.join(tmp, "empty.pbrt")
    with open(empty, "w") as f:
        f.write('Film "image" "integer xresolution" [1] "integer yresolution" [1]\n'
                'Camera "perspective"\nWorldBegin\nWorldEnd\n')
    cases.append(("empty", "-", empty, 0, ["--preview", "none"]))
    cases.append(("empty+png", "-", empty, 0, ["--preview", os.path.join(tmp, "empty.png")]))
    meshes = {}
    for count in triangle_counts:
        n = max(1, round((count / 2) ** 0.5))
        path = os.path.join(tmp, f"grid{n}.ply")
        meshes[count] = (path, grid_ply(path, n))
    for accel in accels:
        for count in triangle_counts:
            ply, tris = meshes[count]
            scene = os.path.join(tmp, f"mesh{count}-{accel}.pbrt")
            with open(scene, "w") as f:
                f.write(HEADER.format(res=32, eye="0.5 0.5 1.2", look="0.5 0.5 0", accel=accel))
                f.write(f'Shape "plymesh" "string filename" "{ply}"\nWorldEnd\n')
            cases.append(("mesh", accel, scene, tris, ["--preview", "none"]))
        ply, tris = meshes[max(triangle_counts)]
        for k in sorted({1, instances}):
            side = max(1, round(k ** 0.5 + 0.499))
            scene = os.path.join(tmp, f"inst{k}-{accel}.pbrt")
            with open(scene, "w") as f:
                centre = f"{side * 1.25 / 2} {side * 1.25 / 2}"
                f.write(HEADER.format(res=32, eye=f"{centre} {side * 1.6}", look=f"{centre} 0",
                                      accel=accel))
                f.write(f'ObjectBegin "grid"\nShape "plymesh" "string filename" "{ply}"\n'
                        "ObjectEnd\n")
                for i in range(k):
                    f.write(f"AttributeBegin\nTranslate {1.25 * (i % side)} {1.25 * (i // side)} 0\n"
                            'ObjectInstance "grid"\nAttributeEnd\n')
                f.write("WorldEnd\n")
            cases.append((f"instanced {k}", accel, scene, tris, ["--preview", "none"]))
    return cases


def run(candela, scene, extra, out):
    """One run: (CPU seconds, wall seconds, peak RSS in bytes)."""
    start = time.perf_counter()
    proc = subprocess.Popen([candela, "-q", "-o", out, *extra, scene],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    err = proc.stderr.read().decode()
    proc.stderr.close()
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"footprint.py: {candela} {scene} failed:\n{err}")
    return usage.ru_utime + usage.ru_stime, wall, usage.ru_maxrss * 1024


def libraries(candela, scene, extra, out, tmp):
    """Shared libraries the run initialised (LD_DEBUG=files: one 'calling init' per library)."""
    prefix = os.path.join(tmp, "lddebug")
    env = dict(os.environ, LD_DEBUG="files", LD_DEBUG_OUTPUT=prefix)
    subprocess.run([candela, "-q", "-o", out, *extra, scene], env=env, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    names = set()
    for f in os.listdir(tmp):
        if f.startswith("lddebug."):
            with open(os.path.join(tmp, f)) as log:
                names |= {line.split("calling init:")[1].strip() for line in log
                          if "calling init:" in line}
            os.remove(os.path.join(tmp, f))
    return len(names)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--candela", action="append",
                    help="[LABEL=]PATH of a candela binary (repeatable; default build/candela)")
    ap.add_argument("--runs", type=int, default=10, help="runs of the empty scene per binary")
    ap.add_argument("--triangles", default="1e4,1e5,1e6")
    ap.add_argument("--instances", type=int, default=1000)
    ap.add_argument("--accel", default="embree,bvh,kdtree,grid")
    ap.add_argument("--csv", help="also write the rows here")
    args = ap.parse_args()
    binaries = []
    for spec in args.candela or [os.path.join(ROOT, "build", "candela")]:
        label, _, path = spec.rpartition("=")
        binaries.append((label or os.path.basename(os.path.dirname(os.path.abspath(path))),
                         os.path.abspath(path)))
    counts = sorted({int(float(t)) for t in args.triangles.split(",")})

    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "out.exr")
        cases = write_scenes(tmp, counts, args.instances, args.accel.split(","))
        for name, accel, scene, tris, extra in cases:
            runs = args.runs if name.startswith("empty") else 3
            samples = {label: [] for label, _ in binaries}
            for _ in range(runs):
                for label, path in binaries:
                    samples[label].append(run(path, scene, extra, out))
            for label, path in binaries:
                cpu, wall, rss = (statistics.median(s[i] for s in samples[label]) for i in range(3))
                libs = libraries(path, scene, extra, out, tmp) if name.startswith("empty") else ""
                rows.append({"binary": label, "case": name, "accel": accel, "triangles": tris,
                             "instances": name.split()[1] if name.startswith("instanced") else "",
                             "cpu_s": cpu, "wall_s": wall, "peak_rss_mb": rss / 1e6,
                             "libraries": libs})
    # Per instance: the extra peak RSS of K instances over one, per added instance.
    one = {(r["binary"], r["accel"]): r["peak_rss_mb"] for r in rows if r["case"] == "instanced 1"}
    for r in rows:
        k = int(r["case"].split()[1]) if r["case"].startswith("instanced ") else 0
        extra = r["peak_rss_mb"] - one[(r["binary"], r["accel"])] if k > 1 else 0
        r["bytes_per_instance"] = f"{extra * 1e6 / (k - 1):.0f}" if k > 1 else ""

    keys = ["binary", "case", "accel", "triangles", "instances", "cpu_s", "wall_s", "peak_rss_mb",
            "bytes_per_instance", "libraries"]
    print("| binary | case | accel | mesh triangles | instances | CPU s | wall s | peak RSS MB | "
          "bytes per instance | libraries |")
    print("|" + "---|" * len(keys))
    for r in rows:
        print(f"| {r['binary']} | {r['case']} | {r['accel']} | {r['triangles']:,} | "
              f"{r['instances']} | {r['cpu_s']:.3f} | {r['wall_s']:.3f} | "
              f"{r['peak_rss_mb']:.1f} | {r['bytes_per_instance']} | {r['libraries']} |")
    if args.csv:
        with open(args.csv, "w") as f:
            f.write(",".join(keys) + "\n")
            for r in rows:
                f.write(",".join(str(r[k]) for k in keys) + "\n")


if __name__ == "__main__":
    main()
