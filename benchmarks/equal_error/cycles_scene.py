"""Render a (small subset of a) pbrt-v3 scene with Blender Cycles.

Usage (Blender's Python, not the system one):

    blender -b --factory-startup --python cycles_scene.py -- SCENE.pbrt \
        [--spp N] [--seed S] [--threads T] [--filter-width W] --out OUT.exr

Supported pbrt subset (anything else stops with a clear error and exit code 2):
  Scale, Translate, LookAt, Camera "perspective" (fov), Film "image"
  (xresolution, yresolution, filename), PixelFilter "box" (xwidth, ywidth),
  Sampler (pixelsamples), Integrator "path" (maxdepth), WorldBegin/WorldEnd,
  AttributeBegin/AttributeEnd, Material "matte" (rgb Kd) / "glass" (eta),
  AreaLightSource "diffuse" (rgb L, twosided), Shape "trianglemesh"
  (P, indices, N) and "sphere" (radius).

The Cycles settings aim at an unbiased path tracer equivalent to pbrt-v3's
"path" integrator: CPU, no clamping, no denoising, no adaptive sampling, no
path guiding, glossy filter 0, both caustic kinds on, black world, Standard
view transform, 32-bit float linear RGBA EXR.

Mapping notes:
  * pbrt "maxdepth" counts scattering vertices after which the path stops
    (maxdepth 1 = direct lighting only); Cycles' "bounces" count indirect
    bounces (0 = direct lighting only).  So every Cycles bounce limit is set to
    maxdepth - 1 by default; --bounces B overrides that.
  * pbrt's box filter of radius 0.5 px (its default) averages the pixel's own
    area, which is Cycles' BOX filter of width 1 px; the width used is
    2 * max(xwidth, ywidth), or --filter-width W.
  * Surface emission: Cycles' Emission shader with colour C and strength 1
    has radiance C (a surface of strength 1 shows its colour exactly), so pbrt's
    "rgb L" goes in as the colour with strength 1.
  * pbrt's "Scale -1 1 1" before LookAt flips camera x; the camera-to-world
    matrix is then right-handed again, which is what a Blender camera needs.
    A camera whose matrix is left-handed (a mirrored image) is refused.

Prints "cycles: seconds=<process CPU seconds of the render>" and a second line
with wall time and settings.
"""

import math
import os
import re
import resource
import sys
import time

import bpy
import bmesh
from mathutils import Matrix, Vector


class SceneError(Exception):
    pass


def fail(msg):
    sys.stdout.flush()
    sys.stderr.write("cycles_scene.py: error: %s\n" % msg)
    sys.stderr.flush()
    os._exit(2)


# --------------------------------------------------------------------------
# command line

def parse_args(argv):
    if "--" in argv:
        argv = argv[argv.index("--") + 1:]
    else:
        argv = []
    opts = {"scene": None, "spp": None, "seed": 0, "threads": 1, "out": None,
            "filter_width": None, "bounces": None, "sphere_segments": 256}
    i = 0

    def value():
        if i + 1 >= len(argv):
            fail("option %s needs a value" % argv[i])
        return argv[i + 1]

    while i < len(argv):
        a = argv[i]
        if a in ("-h", "--help"):
            print(__doc__)
            sys.stdout.flush()
            os._exit(0)
        elif a == "--spp":
            opts["spp"] = int(value()); i += 2
        elif a == "--seed":
            opts["seed"] = int(value()); i += 2
        elif a == "--threads":
            opts["threads"] = int(value()); i += 2
        elif a == "--out":
            opts["out"] = value(); i += 2
        elif a == "--filter-width":
            opts["filter_width"] = float(value()); i += 2
        elif a == "--bounces":
            opts["bounces"] = int(value()); i += 2
        elif a == "--sphere-segments":
            opts["sphere_segments"] = int(value()); i += 2
        elif a.startswith("-"):
            fail("unknown option %s" % a)
        elif opts["scene"] is None:
            opts["scene"] = a; i += 1
        else:
            fail("unexpected argument %s" % a)
    if opts["scene"] is None:
        fail("no scene file given (usage: blender -b --factory-startup --python "
             "cycles_scene.py -- SCENE.pbrt --spp N --seed S --threads T --out OUT.exr)")
    if opts["out"] is None:
        fail("--out OUT.exr is required")
    if opts["spp"] is not None and opts["spp"] < 1:
        fail("--spp must be >= 1")
    if opts["threads"] < 1:
        fail("--threads must be >= 1")
    return opts


# --------------------------------------------------------------------------
# pbrt tokenizer and parser

TOKEN_RE = re.compile(r'\s+|#[^\n]*|"([^"]*)"|(\[)|(\])|([^\s"\[\]#]+)')


def tokenize(text, filename):
    tokens = []  # (kind, value, line) with kind in 'str', '[', ']', 'word'
    pos = 0
    line = 1
    while pos < len(text):
        m = TOKEN_RE.match(text, pos)
        if not m:
            raise SceneError("%s:%d: cannot tokenize near %r" % (filename, line, text[pos:pos + 20]))
        if m.group(1) is not None:
            tokens.append(("str", m.group(1), line))
        elif m.group(2):
            tokens.append(("[", "[", line))
        elif m.group(3):
            tokens.append(("]", "]", line))
        elif m.group(4):
            tokens.append(("word", m.group(4), line))
        line += text.count("\n", pos, m.end())
        pos = m.end()
    return tokens


def to_number(tok, filename):
    kind, val, line = tok
    if kind != "word":
        raise SceneError("%s:%d: expected a number, got %r" % (filename, line, val))
    try:
        return float(val)
    except ValueError:
        raise SceneError("%s:%d: expected a number, got %r" % (filename, line, val))


class Param:
    def __init__(self, ptype, name, values, line):
        self.type = ptype
        self.name = name
        self.values = values
        self.line = line


class Parser:
    def __init__(self, filename):
        self.filename = filename
        with open(filename) as f:
            self.toks = tokenize(f.read(), filename)
        self.i = 0

    def err(self, line, msg):
        raise SceneError("%s:%d: %s" % (self.filename, line, msg))

    def peek(self):
        return self.toks[self.i] if self.i < len(self.toks) else None

    def next(self):
        t = self.peek()
        if t is None:
            raise SceneError("%s: unexpected end of file" % self.filename)
        self.i += 1
        return t

    def numbers(self, n):
        return [to_number(self.next(), self.filename) for _ in range(n)]

    def string(self):
        t = self.next()
        if t[0] != "str":
            self.err(t[2], "expected a quoted string, got %r" % t[1])
        return t[1]

    def params(self):
        """Parameter list: "type name" value-or-[values] ... until the next directive."""
        out = {}
        while True:
            t = self.peek()
            if t is None or t[0] != "str":
                return out
            self.i += 1
            decl = t[1].split()
            if len(decl) != 2:
                self.err(t[2], "bad parameter declaration %r" % t[1])
            ptype, name = decl
            v = self.next()
            vals = []
            if v[0] == "[":
                while True:
                    w = self.next()
                    if w[0] == "]":
                        break
                    vals.append(w)
            else:
                vals.append(v)
            if ptype in ("string", "texture", "bool"):
                conv = []
                for w in vals:
                    if w[0] != "str":
                        self.err(w[2], "parameter %r wants quoted strings" % name)
                    conv.append(w[1])
                if ptype == "bool":
                    for c in conv:
                        if c not in ("true", "false"):
                            self.err(t[2], "bool parameter %r must be \"true\" or \"false\"" % name)
                    conv = [c == "true" for c in conv]
            else:
                conv = [to_number(w, self.filename) for w in vals]
            if name in out:
                self.err(t[2], "parameter %r given twice" % name)
            out[name] = Param(ptype, name, conv, t[2])


def translate(x, y, z):
    return Matrix(((1, 0, 0, x), (0, 1, 0, y), (0, 0, 1, z), (0, 0, 0, 1)))


def scale(x, y, z):
    return Matrix(((x, 0, 0, 0), (0, y, 0, 0), (0, 0, z, 0), (0, 0, 0, 1)))


def look_at(eye, look, up):
    """pbrt-v3's LookAt: returns world-to-camera (camera looks down +z, left-handed)."""
    eye, look, up = Vector(eye), Vector(look), Vector(up)
    d = look - eye
    if d.length == 0:
        raise SceneError("LookAt: eye and look point coincide")
    d.normalize()
    if up.normalized().cross(d).length == 0:
        raise SceneError("LookAt: up vector and viewing direction are parallel")
    right = up.normalized().cross(d).normalized()
    new_up = d.cross(right)
    cam_to_world = Matrix((
        (right.x, new_up.x, d.x, eye.x),
        (right.y, new_up.y, d.y, eye.y),
        (right.z, new_up.z, d.z, eye.z),
        (0, 0, 0, 1)))
    return cam_to_world.inverted()


class Scene:
    def __init__(self):
        self.camera_to_world = None
        self.fov = 90.0
        self.xres = 640
        self.yres = 480
        self.filter_radius = 0.5
        self.spp = 16
        self.maxdepth = 5
        self.shapes = []  # dicts: kind, ctm, params, material, light


def check_params(p, directive, allowed, line_of):
    for name, prm in p.items():
        if name not in allowed:
            raise SceneError("%s: %s: unsupported parameter \"%s %s\"" %
                             (line_of(prm.line), directive, prm.type, name))
        want = allowed[name]
        if prm.type not in want:
            raise SceneError("%s: %s: parameter %r must be of type %s, not %s" %
                             (line_of(prm.line), directive, name, "/".join(want), prm.type))


def one(p, name, default):
    if name not in p:
        return default
    v = p[name].values
    if len(v) != 1:
        raise SceneError("parameter %r wants one value, got %d" % (name, len(v)))
    return v[0]


def rgb(p, name, default):
    if name not in p:
        return tuple(default)
    v = p[name].values
    if len(v) != 3:
        raise SceneError("parameter %r wants 3 values (rgb), got %d" % (name, len(v)))
    return tuple(v)


def parse_scene(filename):
    ps = Parser(filename)
    sc = Scene()
    line_of = lambda ln: "%s:%d" % (filename, ln)
    ctm = Matrix.Identity(4)
    material = ("matte", {"Kd": (0.5, 0.5, 0.5)})
    light = None
    stack = []
    in_world = False
    seen_world_end = False
    while ps.peek() is not None:
        kind, word, line = ps.next()
        if kind != "word":
            ps.err(line, "expected a directive, got %r" % word)
        if seen_world_end:
            ps.err(line, "%s after WorldEnd" % word)
        if word == "Scale":
            ctm = ctm @ scale(*ps.numbers(3))
        elif word == "Translate":
            ctm = ctm @ translate(*ps.numbers(3))
        elif word == "LookAt":
            v = ps.numbers(9)
            ctm = ctm @ look_at(v[0:3], v[3:6], v[6:9])
        elif word == "Camera":
            if in_world:
                ps.err(line, "Camera inside the world block")
            name = ps.string()
            p = ps.params()
            if name != "perspective":
                ps.err(line, "Camera %r unsupported (only \"perspective\")" % name)
            check_params(p, "Camera", {"fov": ("float",)}, line_of)
            sc.fov = one(p, "fov", 90.0)
            if ctm.determinant() == 0:
                ps.err(line, "singular camera transform")
            sc.camera_to_world = ctm.inverted()
        elif word == "Film":
            name = ps.string()
            p = ps.params()
            if name != "image":
                ps.err(line, "Film %r unsupported (only \"image\")" % name)
            check_params(p, "Film", {"xresolution": ("integer",), "yresolution": ("integer",),
                                     "filename": ("string",)}, line_of)
            sc.xres = int(one(p, "xresolution", 640))
            sc.yres = int(one(p, "yresolution", 480))
        elif word == "PixelFilter":
            name = ps.string()
            p = ps.params()
            if name != "box":
                ps.err(line, "PixelFilter %r unsupported (only \"box\")" % name)
            check_params(p, "PixelFilter", {"xwidth": ("float",), "ywidth": ("float",)}, line_of)
            xw, yw = one(p, "xwidth", 0.5), one(p, "ywidth", 0.5)
            if xw != yw:
                ps.err(line, "box filter with xwidth != ywidth unsupported")
            sc.filter_radius = xw
        elif word == "Sampler":
            name = ps.string()
            p = ps.params()
            if name not in ("halton", "sobol", "random", "zerotwosequence", "lowdiscrepancy",
                            "maxmindist"):
                ps.err(line, "Sampler %r unsupported" % name)
            check_params(p, "Sampler", {"pixelsamples": ("integer",)}, line_of)
            sc.spp = int(one(p, "pixelsamples", 16))
        elif word == "Integrator":
            name = ps.string()
            p = ps.params()
            if name != "path":
                ps.err(line, "Integrator %r unsupported (only \"path\")" % name)
            check_params(p, "Integrator", {"maxdepth": ("integer",)}, line_of)
            sc.maxdepth = int(one(p, "maxdepth", 5))
        elif word == "WorldBegin":
            if in_world:
                ps.err(line, "nested WorldBegin")
            in_world = True
            ctm = Matrix.Identity(4)
        elif word == "WorldEnd":
            if not in_world:
                ps.err(line, "WorldEnd without WorldBegin")
            if stack:
                ps.err(line, "WorldEnd inside an unclosed AttributeBegin")
            seen_world_end = True
        elif word == "AttributeBegin":
            if not in_world:
                ps.err(line, "AttributeBegin outside the world block")
            stack.append((ctm.copy(), material, light))
        elif word == "AttributeEnd":
            if not stack:
                ps.err(line, "unmatched AttributeEnd")
            ctm, material, light = stack.pop()
        elif word == "Material":
            name = ps.string()
            p = ps.params()
            if name == "matte":
                check_params(p, "Material matte", {"Kd": ("rgb", "color")}, line_of)
                material = ("matte", {"Kd": rgb(p, "Kd", (0.5, 0.5, 0.5))})
            elif name == "glass":
                check_params(p, "Material glass", {"eta": ("float",), "index": ("float",)}, line_of)
                if "eta" in p and "index" in p:
                    ps.err(line, "glass: give eta or index, not both")
                material = ("glass", {"eta": one(p, "eta", one(p, "index", 1.5))})
            else:
                ps.err(line, "Material %r unsupported (only \"matte\" and \"glass\")" % name)
        elif word == "AreaLightSource":
            name = ps.string()
            p = ps.params()
            if name != "diffuse":
                ps.err(line, "AreaLightSource %r unsupported (only \"diffuse\")" % name)
            check_params(p, "AreaLightSource", {"L": ("rgb", "color"), "twosided": ("bool",)},
                         line_of)
            light = {"L": rgb(p, "L", (1.0, 1.0, 1.0)), "twosided": bool(one(p, "twosided", False))}
        elif word == "Shape":
            if not in_world:
                ps.err(line, "Shape outside the world block")
            name = ps.string()
            p = ps.params()
            if name == "trianglemesh":
                check_params(p, "Shape trianglemesh", {"P": ("point", "point3"),
                                                       "indices": ("integer",),
                                                       "N": ("normal", "normal3")}, line_of)
                if "P" not in p or "indices" not in p:
                    ps.err(line, "trianglemesh needs \"point P\" and \"integer indices\"")
                P = p["P"].values
                idx = [int(x) for x in p["indices"].values]
                if len(P) % 3 or len(idx) % 3:
                    ps.err(line, "trianglemesh: P or indices not a multiple of 3")
                nv = len(P) // 3
                if any(k < 0 or k >= nv for k in idx):
                    ps.err(line, "trianglemesh: index out of range")
                N = p["N"].values if "N" in p else None
                if N is not None and len(N) != len(P):
                    ps.err(line, "trianglemesh: N must have one normal per vertex")
                geo = {"P": [tuple(P[3 * k:3 * k + 3]) for k in range(nv)],
                       "indices": [tuple(idx[3 * k:3 * k + 3]) for k in range(len(idx) // 3)],
                       "N": None if N is None else [tuple(N[3 * k:3 * k + 3]) for k in range(nv)]}
            elif name == "sphere":
                check_params(p, "Shape sphere", {"radius": ("float",)}, line_of)
                geo = {"radius": one(p, "radius", 1.0)}
                if geo["radius"] <= 0:
                    ps.err(line, "sphere radius must be > 0")
            else:
                ps.err(line, "Shape %r unsupported (only \"trianglemesh\" and \"sphere\")" % name)
            sc.shapes.append({"kind": name, "ctm": ctm.copy(), "geo": geo,
                              "material": material, "light": light, "line": line})
        else:
            ps.err(line, "directive %r unsupported by cycles_scene.py" % word)
    if not seen_world_end:
        raise SceneError("%s: no WorldEnd" % filename)
    if sc.camera_to_world is None:
        raise SceneError("%s: no Camera" % filename)
    return sc


# --------------------------------------------------------------------------
# Blender scene

def clear_blender():
    for ob in list(bpy.data.objects):
        bpy.data.objects.remove(ob, do_unlink=True)
    for coll in (bpy.data.meshes, bpy.data.materials, bpy.data.cameras, bpy.data.lights,
                 bpy.data.worlds):
        for b in list(coll):
            coll.remove(b)


def make_material(name, material, light):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    out.target = "CYCLES"
    kind, prm = material
    if kind == "matte":
        bsdf = nt.nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Color"].default_value = (*prm["Kd"], 1.0)
        bsdf.inputs["Roughness"].default_value = 0.0
    elif kind == "glass":
        bsdf = nt.nodes.new("ShaderNodeBsdfGlass")
        bsdf.distribution = "SHARP"
        bsdf.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        bsdf.inputs["Roughness"].default_value = 0.0
        bsdf.inputs["IOR"].default_value = prm["eta"]
    else:
        raise SceneError("internal: material %r" % kind)
    surface = bsdf.outputs["BSDF"]
    if light is not None:
        em = nt.nodes.new("ShaderNodeEmission")
        em.inputs["Color"].default_value = (*light["L"], 1.0)
        em.inputs["Strength"].default_value = 1.0
        add = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(em.outputs["Emission"], add.inputs[0])
        nt.links.new(bsdf.outputs["BSDF"], add.inputs[1])
        surface = add.outputs["Shader"]
        if not light["twosided"]:
            # pbrt's diffuse area light emits only on the side its normal faces;
            # the back is just the surface's material.
            geom = nt.nodes.new("ShaderNodeNewGeometry")
            mix = nt.nodes.new("ShaderNodeMixShader")
            nt.links.new(geom.outputs["Backfacing"], mix.inputs["Fac"])
            nt.links.new(add.outputs["Shader"], mix.inputs[1])
            nt.links.new(bsdf.outputs["BSDF"], mix.inputs[2])
            surface = mix.outputs["Shader"]
    nt.links.new(surface, out.inputs["Surface"])
    return mat


def add_object(name, mesh, ctm, mat, collection):
    mesh.materials.append(mat)
    ob = bpy.data.objects.new(name, mesh)
    ob.matrix_world = ctm
    collection.objects.link(ob)
    return ob


def build_trianglemesh(name, geo):
    P, tris, N = geo["P"], geo["indices"], geo["N"]
    faces = []
    for (a, b, c) in tris:
        if N is not None:
            # pbrt turns the geometric normal towards the shading normals, so
            # wind each triangle to face its vertices' mean normal.
            pa, pb, pc = Vector(P[a]), Vector(P[b]), Vector(P[c])
            ng = (pb - pa).cross(pc - pa)
            ns = Vector(N[a]) + Vector(N[b]) + Vector(N[c])
            if ng.dot(ns) < 0:
                b, c = c, b
        faces.append((a, b, c))
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(P, [], faces)
    mesh.validate()
    mesh.update()
    if N is not None:
        mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
        mesh.use_auto_smooth = True
        mesh.normals_split_custom_set_from_vertices([Vector(n).normalized() for n in N])
    return mesh


def build_sphere(name, geo, segments):
    bm = bmesh.new()
    bmesh.ops.create_uvsphere(bm, u_segments=segments, v_segments=max(segments // 2, 3),
                              radius=geo["radius"])
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
    mesh.update()
    return mesh


def build_blender_scene(sc, opts):
    clear_blender()
    scene = bpy.context.scene
    coll = scene.collection

    # camera: pbrt camera space is x right, y up, +z forward; Blender's camera
    # looks down -z with x right and y up, so negate the third column.
    m = sc.camera_to_world
    rot = Matrix(((m[0][0], m[0][1], -m[0][2]),
                  (m[1][0], m[1][1], -m[1][2]),
                  (m[2][0], m[2][1], -m[2][2])))
    if rot.determinant() < 0:
        raise SceneError("the camera transform is mirrored (left-handed after conversion); "
                         "Cycles cannot render a mirrored camera (add or remove \"Scale -1 1 1\")")
    cols = [Vector((rot[0][k], rot[1][k], rot[2][k])).normalized() for k in range(3)]
    cam_m = Matrix(((cols[0].x, cols[1].x, cols[2].x, m[0][3]),
                    (cols[0].y, cols[1].y, cols[2].y, m[1][3]),
                    (cols[0].z, cols[1].z, cols[2].z, m[2][3]),
                    (0, 0, 0, 1)))
    cam_data = bpy.data.cameras.new("pbrt_camera")
    cam_data.type = "PERSP"
    cam_data.lens_unit = "FOV"
    # pbrt's fov spans the shorter image axis
    cam_data.sensor_fit = "HORIZONTAL" if sc.xres <= sc.yres else "VERTICAL"
    cam_data.angle = math.radians(sc.fov)
    cam_data.clip_start = 1e-4
    cam_data.clip_end = 1e6
    cam_data.shift_x = cam_data.shift_y = 0.0
    cam = bpy.data.objects.new("pbrt_camera", cam_data)
    cam.matrix_world = cam_m
    coll.objects.link(cam)
    scene.camera = cam

    for k, sh in enumerate(sc.shapes):
        name = "shape%03d_%s" % (k, sh["kind"])
        mat = make_material(name + "_mat", sh["material"], sh["light"])
        if sh["kind"] == "trianglemesh":
            mesh = build_trianglemesh(name, sh["geo"])
        else:
            mesh = build_sphere(name, sh["geo"], opts["sphere_segments"])
        add_object(name, mesh, sh["ctm"], mat, coll)

    # black world
    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    bg = world.node_tree.nodes.get("Background")
    bg.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    bg.inputs["Strength"].default_value = 0.0
    world.color = (0.0, 0.0, 0.0)
    scene.world = world

    # render settings
    r = scene.render
    r.engine = "CYCLES"
    r.resolution_x = sc.xres
    r.resolution_y = sc.yres
    r.resolution_percentage = 100
    r.pixel_aspect_x = r.pixel_aspect_y = 1.0
    r.use_border = False
    r.film_transparent = False
    r.use_motion_blur = False
    r.use_persistent_data = False
    r.threads_mode = "FIXED"
    r.threads = opts["threads"]
    r.use_compositing = False
    r.use_sequencer = False
    r.dither_intensity = 0.0
    r.filepath = os.path.abspath(opts["out"])
    r.use_file_extension = False
    im = r.image_settings
    im.file_format = "OPEN_EXR"
    im.color_depth = "32"
    im.color_mode = "RGBA"
    im.exr_codec = "ZIP"

    c = scene.cycles
    c.device = "CPU"
    c.feature_set = "SUPPORTED"
    c.shading_system = False
    c.samples = opts["spp"] if opts["spp"] is not None else sc.spp
    c.use_adaptive_sampling = False
    c.time_limit = 0.0
    c.use_denoising = False
    c.use_guiding = False
    c.seed = opts["seed"]
    c.use_animated_seed = False
    c.sample_offset = 0
    c.scrambling_distance = 1.0
    c.auto_scrambling_distance = False
    c.use_layer_samples = "IGNORE"
    bounces = opts["bounces"] if opts["bounces"] is not None else max(sc.maxdepth - 1, 0)
    c.max_bounces = bounces
    c.diffuse_bounces = bounces
    c.glossy_bounces = bounces
    c.transmission_bounces = bounces
    c.transparent_max_bounces = bounces
    c.volume_bounces = bounces
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.light_sampling_threshold = 0.0
    c.use_fast_gi = False
    c.film_exposure = 1.0
    c.pixel_filter_type = "BOX"
    fw = opts["filter_width"] if opts["filter_width"] is not None else 2.0 * sc.filter_radius
    c.filter_width = fw
    for vl in scene.view_layers:
        vl.samples = 0
        if hasattr(vl, "cycles"):
            vl.cycles.use_denoising = False

    vs = scene.view_settings
    vs.view_transform = "Standard"
    vs.look = "None"
    vs.exposure = 0.0
    vs.gamma = 1.0
    vs.use_curve_mapping = False
    return {"samples": c.samples, "bounces": bounces, "filter_width": c.filter_width}


def main():
    opts = parse_args(sys.argv)
    try:
        sc = parse_scene(opts["scene"])
        info = build_blender_scene(sc, opts)
    except (SceneError, OSError) as e:
        fail(str(e))
    sys.stdout.flush()
    ru0 = resource.getrusage(resource.RUSAGE_SELF)
    t0 = time.monotonic()
    bpy.ops.render.render(write_still=True)
    t1 = time.monotonic()
    ru1 = resource.getrusage(resource.RUSAGE_SELF)
    cpu = (ru1.ru_utime - ru0.ru_utime) + (ru1.ru_stime - ru0.ru_stime)
    if not os.path.exists(bpy.context.scene.render.filepath):
        fail("render finished but %s was not written" % bpy.context.scene.render.filepath)
    print("cycles: seconds=%.3f" % cpu)
    print("cycles: wall_seconds=%.3f spp=%d threads=%d seed=%d bounces=%d filter_width=%g out=%s"
          % (t1 - t0, info["samples"], opts["threads"], opts["seed"], info["bounces"],
             info["filter_width"], bpy.context.scene.render.filepath))
    sys.stdout.flush()


if __name__ == "__main__":
    try:
        main()
    except SystemExit:
        raise
    except Exception as e:  # unexpected: still exit non-zero
        import traceback
        traceback.print_exc()
        fail("unexpected %s: %s" % (type(e).__name__, e))
