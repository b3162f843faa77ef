// The "loopsubdiv" shape: a TriangleMesh on the limit surface, from either producer.
#include <gtest/gtest.h>

#include "assembly/shape_factory.h"
#include "shapes/loop_subdiv_shape.h"
#include "support/param_items.h"

namespace candela {
namespace {

ParamSet tetrahedronParams(int levels) {
  return test::paramSet({test::points("P", {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1}),
                         test::ints("indices", {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2}),
                         test::ints("nlevels", {levels}),
                         test::floats("uv", {0, 0, 1, 0, 0, 1, 1, 1})});
}

// An octahedron without its last face: a boundary, and inside vertices of valence 4, where the
// draft's β and Loop's differ; uv and, if asked, user normals per vertex.
ParamSet openOctahedronParams(int levels, bool withNormals) {
  std::vector<Float> p = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  ParamSet ps = test::paramSet(
      {test::points("P", p),
       test::ints("indices", {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5}),
       test::ints("nlevels", {levels}),
       test::floats("uv", {1, 0.5f, 0, 0.5f, 0.5f, 1, 0.5f, 0, 0.5f, 0.5f, 0, 0})});
  if (withNormals) ps.add(test::normals("N", p));  // unit positions: their own normals
  return ps;
}

TEST(LoopSubdivShape, BothProducersGiveTheSameSurface) {
  struct Case {
    const char* name;
    ParamSet params;
    size_t triangles;
  };
  for (const Case& c : {Case{"tetrahedron", tetrahedronParams(3), 256},
                        Case{"open octahedron", openOctahedronParams(3, false), 448},
                        Case{"open octahedron with N", openOctahedronParams(2, true), 112}}) {
    SCOPED_TRACE(c.name);
    std::unique_ptr<TriangleMesh> book, osd;
    auto a = createLoopSubdivShapes(Transform(), false, c.params, &book, {}, LoopProducer::Book);
    auto b =
        createLoopSubdivShapes(Transform(), false, c.params, &osd, {}, LoopProducer::OpenSubdiv);
    ASSERT_EQ(a.size(), c.triangles);
    ASSERT_EQ(b.size(), c.triangles);
    ASSERT_EQ(book->p.size(), osd->p.size());
    ASSERT_EQ(book->n.size(), book->p.size());
    ASSERT_EQ(book->uv.size(), book->p.size());
    ASSERT_EQ(osd->n.size(), osd->p.size());
    ASSERT_EQ(osd->uv.size(), osd->p.size());
    // The producers number the vertices differently: match them by position. Both run in double
    // (positions agree to ~1e-15 before rounding to float).
    for (size_t v = 0; v < book->p.size(); ++v) {
      Float best = 1e30f;
      size_t match = 0;
      for (size_t w = 0; w < osd->p.size(); ++w)
        if (distance(book->p[v], osd->p[w]) < best)
          best = distance(book->p[v], osd->p[w]), match = w;
      EXPECT_LT(best, 1e-6f);
      EXPECT_GT(dot(book->n[v], osd->n[match]), 1 - 1e-6f);
      EXPECT_LT(distance(Point3f(book->uv[v].x, book->uv[v].y, 0),
                         Point3f(osd->uv[match].x, osd->uv[match].y, 0)),
                1e-6f);
    }
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
  desc.params.add(test::ints("indices", {0, 1, 2, 0, 2, 2}));
  try {
    createShapes(desc, Transform());
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("loopsubdiv: face 1 repeats vertex 2"), std::string::npos)
        << e.what();
  }
}

TEST(LoopSubdivShape, RefusesMoreTrianglesThanMemoryHolds) {
  // 1100 faces at 8 levels would be 72 million triangles (about 14 GB): a clear error at
  // "nlevels", before any refinement or even validation.
  ParamSet ps;
  ps.add(test::points("P", {0, 0, 0, 1, 0, 0, 0, 1, 0}));
  std::vector<int> indices;
  for (int f = 0; f < 1100; ++f)
    for (int v : {0, 1, 2}) indices.push_back(v);
  ps.add(test::ints("indices", indices));
  ps.add(test::ints("nlevels", {8}, FileLoc{"big.pbrt", 3, 5}));
  std::unique_ptr<TriangleMesh> mesh;
  try {
    createLoopSubdivShapes(Transform(), false, ps, &mesh, {});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("big.pbrt:3:5: error: loopsubdiv: \"nlevels\" 8 would "
                                         "make 72089600 triangles"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace candela
