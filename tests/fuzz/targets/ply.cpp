#include "core/error.h"
#include "fuzz/targets/fuzz_targets.h"
#include "shapes/ply_reader.h"

namespace candela::fuzz {

// A mesh the reader returns is whole: triangles index existing vertices, and normals and
// texture coordinates are absent or one per vertex.
void ply(std::string_view input) {
  PlyMesh m;
  try {
    m = parsePly(input, "fuzz.ply");
  } catch (const FileError&) {
    return;
  }
  if (m.indices.size() % 3) broken("PLY indices are not whole triangles");
  for (int i : m.indices)
    if (i < 0 || size_t(i) >= m.positions.size()) broken("a PLY index out of range");
  if (!m.normals.empty() && m.normals.size() != m.positions.size())
    broken("PLY normals do not match the vertices");
  if (!m.uvs.empty() && m.uvs.size() != m.positions.size())
    broken("PLY texture coordinates do not match the vertices");
}

}  // namespace candela::fuzz
