#!/usr/bin/python3
"""Writes many-lights.pbrt: 10,000 small emissive quads (20,000 emitting triangles, each its own
light) hanging at different heights over a floor with a few matte blocks, for the light samplers.

    scenes/many-lights/make_many_lights.py [--quads 10000] [--out FILE]

Each quad is 0.06 units across, tilted at random up to 60 degrees from facing straight down, one
of four colours, at height 1.5-3.5 over a 20 x 20 floor; the camera, below them, looks down at the
floor and sees none of them (their noise is the light samplers', not the tiny quads' coverage
of pixels).
Path tracing, depth 3, 16 samples per pixel at 64 x 48 by default (pbrt-v3 syntax; candela's
default light sampler for it is pbrt-v3's "spatial"). The same arguments always write the same
file.
"""
import argparse
import math
import os
import random

HEADER = """# Written by make_many_lights.py: {quads} emissive quads over a floor.
LookAt 0 1.3 2.5   0 0 -0.3   0 1 0
Camera "perspective" "float fov" [30]
Film "image" "integer xresolution" [64] "integer yresolution" [48] "string filename" "many-lights.exr"
Sampler "random" "integer pixelsamples" [16]
Integrator "path" "integer maxdepth" [3]
WorldBegin
Material "matte" "rgb Kd" [0.5 0.5 0.5]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point P" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]
Material "matte" "rgb Kd" [0.6 0.4 0.3]
"""

COLOURS = ["6 5 4", "3 4 7", "7 3 2", "3 6 3"]


def block(x, z, w, h):
    """An axis-aligned box standing on the floor, as a triangle mesh."""
    p = [(x - w, 0, z - w), (x + w, 0, z - w), (x + w, 0, z + w), (x - w, 0, z + w),
         (x - w, h, z - w), (x + w, h, z - w), (x + w, h, z + w), (x - w, h, z + w)]
    idx = [4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7]
    pts = " ".join(f"{a:g} {b:g} {c:g}" for a, b, c in p)
    return (f'Shape "trianglemesh" "integer indices" [{" ".join(map(str, idx))}] '
            f'"point P" [{pts}]\n')


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quads", type=int, default=10000)
    # Not kept in the repository (1.2 MB); benchmarks/light_sampling.py writes it when missing.
    ap.add_argument("--out", default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                  "many-lights.pbrt"))
    args = ap.parse_args()
    rng = random.Random(1)
    out = [HEADER.format(quads=args.quads)]
    for x, z, w, h in [(-2, -1.5, 0.4, 0.8), (2.5, -2, 0.6, 1.1), (0, -4, 1.2, 0.6), (-1, -5, 0.5, 1.2)]:
        out.append(block(x, z, w, h))
    meshes = [([], []) for _ in COLOURS]
    size = 0.03
    for _ in range(args.quads):
        c = (rng.uniform(-9, 9), rng.uniform(1.5, 3.5), rng.uniform(-9, 9))
        # The quad's normal: down, tilted by up to 60 degrees toward a random azimuth.
        tilt, azimuth = math.radians(rng.uniform(0, 60)), rng.uniform(0, 2 * math.pi)
        n = (math.sin(tilt) * math.cos(azimuth), -math.cos(tilt), math.sin(tilt) * math.sin(azimuth))
        # Two edges perpendicular to n.
        a = (1, 0, 0) if abs(n[0]) < 0.9 else (0, 0, 1)
        u = (n[1] * a[2] - n[2] * a[1], n[2] * a[0] - n[0] * a[2], n[0] * a[1] - n[1] * a[0])
        lu = math.sqrt(sum(x * x for x in u))
        u = tuple(x / lu for x in u)
        v = (n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0])
        pts, idx = meshes[rng.randrange(len(COLOURS))]
        base = len(pts)
        for su, sv in [(-1, -1), (1, -1), (1, 1), (-1, 1)]:
            pts.append(tuple(c[k] + size * (su * u[k] + sv * v[k]) for k in range(3)))
        # Wound so that cross(p1 - p0, p2 - p0) is n: the side that emits.
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    for colour, (pts, idx) in zip(COLOURS, meshes):
        out.append(f'AttributeBegin\nAreaLightSource "diffuse" "rgb L" [{colour}]\n'
                   f'Shape "trianglemesh" "integer indices" [{" ".join(map(str, idx))}]\n'
                   f'  "point P" [{" ".join(f"{x:.4f}" for p in pts for x in p)}]\nAttributeEnd\n')
    out.append("WorldEnd\n")
    with open(args.out, "w") as f:
        f.write("".join(out))


if __name__ == "__main__":
    main()
