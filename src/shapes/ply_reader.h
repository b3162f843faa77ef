// A reader for Stanford PLY triangle meshes (ASCII and binary of either byte order), as used by
// pbrt's "plymesh" shape. Debian 12 packages no C++ PLY library (no rply/tinyply), so this is a
// small, bounds-checked reader of its own.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/vector.h"

namespace candela {

struct PlyMesh {
  std::vector<Point3f> positions;
  std::vector<Normal3f> normals;  // empty, or one per position (nx ny nz)
  std::vector<Point2f> uvs;       // empty, or one per position (u v, s t or texture_u texture_v)
  std::vector<int> indices;       // triangles; quads and larger polygons fan-triangulated
};

// Reads the vertex element (x y z, optional normals and texture coordinates, of any numeric type)
// and the face element (list vertex_indices or vertex_index); other elements and properties are
// skipped. Faces with fewer than three vertices are dropped. Throws FileError naming path and the
// problem (missing file, bad header, unsupported format, truncated data, index out of range).
PlyMesh readPly(const std::string& path);

// The same, from the bytes of a PLY file in memory; path is used only in error messages.
PlyMesh parsePly(std::string_view bytes, const std::string& path);

}  // namespace candela
