// The "loopsubdiv" shape: a TriangleMesh on the limit surface, from either producer.
#include <gtest/gtest.h>

#include "scene/shape_factory.h"
#include "shapes/loop_subdiv_shape.h"

namespace candela {
namespace {

ParamItem item(ParamType type, const std::string& typeName, const std::string& name) {
  ParamItem it;
  it.type = type;
  it.name = name;
  it.typeName = typeName;
  it.loc = FileLoc{"subd.pbrt", 2, 7};
  return it;
}

ParamSet tetrahedronParams(int levels) {
  ParamSet ps;
  ParamItem p = item(ParamType::Point3, "point3", "P");
  p.floats = {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1};
  ParamItem i = item(ParamType::Integer, "integer", "indices");
  i.ints = {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2};
  ParamItem n = item(ParamType::Integer, "integer", "nlevels");
  n.ints = {levels};
  ParamItem uv = item(ParamType::Float, "float", "uv");
  uv.floats = {0, 0, 1, 0, 0, 1, 1, 1};
  ps.add(p);
  ps.add(i);
  ps.add(n);
  ps.add(uv);
  return ps;
}

TEST(LoopSubdivShape, BothProducersGiveTheSameSurface) {
  std::unique_ptr<TriangleMesh> book, osd;
  auto a = createLoopSubdivShapes(Transform(), false, tetrahedronParams(3), &book, {},
                                  LoopProducer::Book);
  auto b = createLoopSubdivShapes(Transform(), false, tetrahedronParams(3), &osd, {},
                                  LoopProducer::OpenSubdiv);
  ASSERT_EQ(a.size(), 256u);
  ASSERT_EQ(b.size(), 256u);
  ASSERT_EQ(book->p.size(), osd->p.size());
  ASSERT_EQ(book->n.size(), book->p.size());
  ASSERT_EQ(book->uv.size(), book->p.size());
  // A tetrahedron has only valence-3 vertices, where the draft's β is Loop's, and no boundary: the
  // two agree vertex by vertex, once matched by position.
  for (size_t v = 0; v < book->p.size(); ++v) {
    Float best = 1e30f;
    size_t match = 0;
    for (size_t w = 0; w < osd->p.size(); ++w)
      if (distance(book->p[v], osd->p[w]) < best) best = distance(book->p[v], osd->p[w]), match = w;
    EXPECT_LT(best, 1e-5f * 2 * std::sqrt(3.f));
    EXPECT_GT(dot(book->n[v], osd->n[match]), 1 - 1e-6f);
    EXPECT_EQ(book->uv[v], osd->uv[match]);
    EXPECT_GT(dot(Vector3f(book->n[v]), book->p[v] - Point3f()), 0);
  }
}

TEST(LoopSubdivShape, RegisteredAndErrorsNameTheFace) {
  ShapeDesc desc;
  desc.name = "loopsubdiv";
  desc.params = tetrahedronParams(2);
  CreatedShapes out = createShapes(desc, Transform());
  EXPECT_EQ(out.shapes.size(), 64u);
  ASSERT_TRUE(out.mesh);
  desc.params = tetrahedronParams(2);
  ParamItem bad = item(ParamType::Integer, "integer", "indices");
  bad.ints = {0, 1, 2, 0, 2, 2};
  desc.params.add(bad);
  try {
    createShapes(desc, Transform());
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("loopsubdiv: face 1 repeats vertex 2"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace candela
