#!/usr/bin/env python3
"""Writes scenes/smoke/smoke.pbrt: a small puff of smoke (a pbrt-v3 "heterogeneous" grid medium)
over a floor, rendered with Integrator "volpath"; and scenes/smoke-grid/smoke-grid.pbrt, the same
smoke as a pbrt-v2 `Volume "volumegrid"` region rendered with VolumeIntegrator "single" (which
volpath renders too: the convergence benchmark compares them). The density is procedural and
deterministic: a few Gaussian blobs rising in a column, modulated by low-frequency sines, on a
24^3 grid.

Usage: tools/make_smoke_scene.py [output directory of scenes]  (default: scenes/)
"""
import math
import os
import sys

N = 24  # grid samples per axis
BLOBS = [  # centre (in the unit cube), radius, peak density
    ((0.50, 0.25, 0.50), 0.22, 1.0),
    ((0.45, 0.50, 0.55), 0.18, 0.8),
    ((0.58, 0.72, 0.45), 0.14, 0.6),
]


def density(x, y, z):
    d = 0.0
    for (cx, cy, cz), r, peak in BLOBS:
        q = ((x - cx) ** 2 + (y - cy) ** 2 + (z - cz) ** 2) / (r * r)
        d += peak * math.exp(-q)
    wisps = 0.75 + 0.25 * math.sin(9 * x + 4 * y) * math.sin(7 * z + 5 * y)
    return max(0.0, d * wisps)


def grid_values():
    values = []
    for k in range(N):
        for j in range(N):
            for i in range(N):
                values.append(density((i + 0.5) / N, (j + 0.5) / N, (k + 0.5) / N))
    return values


HEADER = """LookAt 0 1.2 -4.5  0 1 0  0 1 0
Camera "perspective" "float fov" [35]
Film "image" "integer xresolution" [240] "integer yresolution" [240]
    "string filename" "{name}.exr"
Sampler "random" "integer pixelsamples" [16]
"""

LIGHTS_AND_FLOOR = """WorldBegin

LightSource "infinite" "rgb L" [0.08 0.1 0.16]
LightSource "spot" "point from" [3 5 -3] "point to" [0 1 0] "float coneangle" [25]
    "rgb I" [60 52 40]

Material "matte" "rgb Kd" [0.5 0.5 0.5]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
    "point P" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]

AttributeBegin
  # The medium's space: the unit cube, placed over the floor as a 2 x 2.4 x 2 box.
  Translate -1 0.02 -1
  Scale 2 2.4 2
"""

COEFFICIENTS = f"""    "rgb sigma_a" [0.4 0.4 0.4] "rgb sigma_s" [3.6 3.6 3.6] "float g" [0.3]
    "integer nx" [{N}] "integer ny" [{N}] "integer nz" [{N}]
    "point p0" [0 0 0] "point p1" [1 1 1]
    "float density" [
"""


def density_lines():
    values = grid_values()
    return "\n".join("    " + " ".join("%.4f" % v for v in values[start:start + 12])
                     for start in range(0, len(values), 12))


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    scenes = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "scenes")
    write(os.path.join(scenes, "smoke", "smoke.pbrt"),
          f"""# A puff of smoke over a floor: a pbrt-v3 "heterogeneous" medium (a {N}^3 density grid
# written by tools/make_smoke_scene.py; edit that, not this) inside a pure-interface box
# (Material "none"), lit by a warm spot light and a dim blue sky, rendered with "volpath".
""" + HEADER.format(name="smoke") + """Integrator "volpath" "integer maxdepth" [16]

""" + LIGHTS_AND_FLOOR + """  MakeNamedMedium "smoke" "string type" "heterogeneous"
""" + COEFFICIENTS + density_lines() + """
    ]
  MediumInterface "smoke" ""
  Material "none"
  # The box's six faces, normals outward.
  Shape "trianglemesh" "point P" [0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  0 1 1]
    "integer indices" [0 2 1 0 3 2  4 5 6 4 6 7  0 1 5 0 5 4  3 7 6 3 6 2  0 4 7 0 7 3
                       1 2 6 1 6 5]
AttributeEnd

WorldEnd
""")
    write(os.path.join(scenes, "smoke-grid", "smoke-grid.pbrt"),
          f"""# The smoke of scenes/smoke as a pbrt-v2 Volume "volumegrid" region ({N}^3 densities, written by
# tools/make_smoke_scene.py; edit that, not this), in pbrt-v2's dialect: direct lighting on the
# floor and single scattering in the smoke, ray-marched. Integrator "volpath" renders it too,
# with every scattering order.
""" + HEADER.format(name="smoke-grid") + """SurfaceIntegrator "directlighting"
VolumeIntegrator "single" "float stepsize" [0.02]

""" + LIGHTS_AND_FLOOR + """  Volume "volumegrid"
""" + COEFFICIENTS + density_lines() + """
    ]
AttributeEnd

WorldEnd
""")


if __name__ == "__main__":
    main()
