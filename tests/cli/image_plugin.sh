#!/usr/bin/env bash
# OpenImageIO is loaded only when it is needed (DESIGN.md, "leave out what the scene does not
# use"): through the image plug-in candela_oiio.so beside the executable, for a preview or a
# non-EXR texture, never for EXR output or EXR textures. A plug-in that cannot be found or loaded
# is an error naming its path, before the render, with nothing written.
set -euo pipefail
candela=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"

# Libraries the run initialised, from the dynamic linker's own log.
loaded() {
  rm -f ld.*
  LD_DEBUG=files LD_DEBUG_OUTPUT=$work/ld "$@" >/dev/null 2>&1
  cat ld.* | grep -o 'calling init: .*' | sort -u
}

cat > empty.pbrt <<'S'
Film "image" "integer xresolution" [1] "integer yresolution" [1]
Camera "perspective"
WorldBegin
WorldEnd
S
# A scene with an image texture; TEX is replaced by the file.
texture_scene() {
  cat <<S
Film "image" "integer xresolution" [4] "integer yresolution" [4]
Camera "perspective"
WorldBegin
LightSource "distant" "point from" [0 0 -1] "point to" [0 0 0]
Texture "t" "spectrum" "imagemap" "string filename" "$1"
Material "matte" "texture Kd" "t"
Translate 0 0 3
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point P" [-1 -1 0 1 -1 0 1 1 0 -1 1 0] "float uv" [0 0 1 0 1 1 0 1]
WorldEnd
S
}

# EXR only: OpenImageIO and the plug-in are never loaded.
libs=$(loaded "$candela" -q --preview none empty.pbrt -o a.exr)
test -s a.exr || { echo "FAIL: no a.exr"; exit 1; }
if grep -q -e libOpenImageIO -e candela_oiio <<<"$libs"; then
  echo "FAIL: an EXR-only render loaded OpenImageIO:"; echo "$libs"; exit 1
fi
grep -q libOpenEXR <<<"$libs" || { echo "FAIL: the log shows no OpenEXR: $libs"; exit 1; }
# The EXR as a texture: read through OpenEXR too.
texture_scene a.exr > exrtex.pbrt
libs=$(loaded "$candela" -q --preview none exrtex.pbrt -o b.exr)
test -s b.exr || { echo "FAIL: no b.exr"; exit 1; }
if grep -q libOpenImageIO <<<"$libs"; then echo "FAIL: an EXR texture loaded OpenImageIO"; exit 1; fi

# A preview, and a PNG texture: the plug-in, and OpenImageIO with it.
libs=$(loaded "$candela" -q empty.pbrt -o c.exr)
test -s c.png || { echo "FAIL: no preview c.png"; exit 1; }
grep -q candela_oiio.so <<<"$libs" && grep -q libOpenImageIO <<<"$libs" ||
  { echo "FAIL: the preview did not load the plug-in"; exit 1; }
texture_scene "$src/tests/data/textures/grey8.png" > pngtex.pbrt
libs=$(loaded "$candela" -q --preview none pngtex.pbrt -o d.exr)
grep -q libOpenImageIO <<<"$libs" || { echo "FAIL: the PNG texture did not load OIIO"; exit 1; }

# Without the plug-in: EXR-only runs still work; the others fail, naming the plug-in's path,
# before the render (no output, no temporary file).
export CANDELA_OIIO_PLUGIN=$work/missing/candela_oiio.so
"$candela" -q --preview none exrtex.pbrt -o e.exr
test -s e.exr || { echo "FAIL: an EXR-only run needed the plug-in"; exit 1; }
expect_plugin_error() {  # $1: what the message says; the rest: the command
  local says=$1 status=0
  shift
  "$@" >out.txt 2>err.txt || status=$?
  [ "$status" = 1 ] || { echo "FAIL: exit $status, expected 1: $*"; cat err.txt; exit 1; }
  grep -q "$CANDELA_OIIO_PLUGIN: error: .*$says" err.txt ||
    { echo "FAIL: the message does not name the plug-in: $*"; cat err.txt; exit 1; }
}
expect_plugin_error "not found" "$candela" empty.pbrt -o f.exr
expect_plugin_error "not found" "$candela" --preview none pngtex.pbrt -o g.exr
printf 'not a shared library\n' > "$work/bad.so"
CANDELA_OIIO_PLUGIN=$work/bad.so expect_plugin_error "cannot load" "$candela" empty.pbrt -o h.exr
leftover=$(ls -A | grep -v -e '^ld\.' -e '\.pbrt$' -e '^[abcd]\.\(exr\|png\)$' -e '^e\.exr$' \
  -e '^\(out\|err\)\.txt$' -e '^bad\.so$' || true)
[ -z "$leftover" ] || { echo "FAIL: files left by the failed runs: $leftover"; exit 1; }
echo "image plug-in: ok"
