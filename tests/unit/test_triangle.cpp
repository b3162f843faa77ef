// Triangles: barycentrics, (u, v) and tangents, orientation rules, shading frames, sampling,
// watertightness along shared edges, and the trianglemesh / plymesh factories' validation.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/rng.h"
#include "shapes/triangle_mesh.h"
#include "support/geometry_expect.h"
#include "support/param_items.h"
#include "support/shape_sample_expect.h"

namespace candela {
namespace {

TriangleMesh unitTriangle(const Transform& t = Transform(), bool reverse = false,
                          std::vector<Normal3f> n = {}, std::vector<Vector3f> s = {},
                          std::vector<Point2f> uv = {}) {
  return TriangleMesh(t, reverse, {0, 1, 2}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, std::move(n),
                      std::move(s), std::move(uv));
}

TEST(TriangleShape, HitPointIsTheRayCrossingUnlessFarOutside) {
  // interactionAt recomputes the barycentrics of the ray's crossing in double and uses them
  // when the crossing is inside, or outside an edge by at most 64 float steps (here 3.8e-6);
  // farther out it keeps the barycentrics it was given. The given ones are off on purpose.
  TriangleMesh mesh = unitTriangle();
  TriangleShape tri(&mesh, 0);
  Vector3f down(0, 0, -1);
  SurfaceInteraction inside = tri.interactionAt(Ray(Point3f(0.2f, 0.3f, 1), down), 0.25f, 0.25f, 1);
  EXPECT_NEAR(inside.p.x, 0.2f, 1e-7);
  EXPECT_NEAR(inside.p.y, 0.3f, 1e-7);
  SurfaceInteraction edge = tri.interactionAt(Ray(Point3f(-1e-7f, 0.5f, 1), down), 0, 0.5f, 1);
  EXPECT_NEAR(edge.p.x, -1e-7f, 1e-13);  // the crossing, outside the edge x = 0
  EXPECT_NEAR(edge.p.y, 0.5f, 1e-7);
  SurfaceInteraction far = tri.interactionAt(Ray(Point3f(-0.5f, 0.5f, 1), down), 0.1f, 0.5f, 1);
  EXPECT_NEAR(far.p.x, 0.1f, 1e-7);  // the given barycentrics' point
  EXPECT_NEAR(far.p.y, 0.5f, 1e-7);
}

TEST(TriangleShape, BarycentricsNormalAndDefaultUV) {
  TriangleMesh mesh = unitTriangle();
  TriangleShape tri(&mesh, 0);
  Float t;
  SurfaceInteraction isect;
  ASSERT_TRUE(tri.intersect(Ray(Point3f(0.2f, 0.3f, 1), Vector3f(0, 0, -1)), &t, &isect));
  EXPECT_NEAR(t, 1, 1e-6);
  test::expectNear(Vector3f(isect.p), Vector3f(0.2f, 0.3f, 0), 1e-6f);
  test::expectNear(Vector3f(isect.n), Vector3f(0, 0, 1), 1e-6f);  // counter-clockwise winding
  test::expectNear(Vector3f(isect.shading.n), Vector3f(0, 0, 1), 1e-6f);
  // Default (u, v) at the vertices (0,0), (1,0), (1,1): b1 + b2, b2 with b1 = 0.2, b2 = 0.3.
  EXPECT_NEAR(isect.uv.x, 0.5f, 1e-6);
  EXPECT_NEAR(isect.uv.y, 0.3f, 1e-6);
  test::expectNear(isect.dpdu, Vector3f(1, 0, 0), 1e-6f);
  test::expectNear(isect.dpdv, Vector3f(-1, 1, 0), 1e-6f);
  EXPECT_GT(isect.pError.x + isect.pError.y, 0);
  // Two-sided: from below too, same normal.
  ASSERT_TRUE(tri.intersect(Ray(Point3f(0.2f, 0.3f, -2), Vector3f(0, 0, 1)), &t, &isect));
  EXPECT_NEAR(t, 2, 1e-6);
  EXPECT_NEAR(isect.n.z, 1, 1e-6);
  EXPECT_EQ(tri.area(), 0.5f);
  // interactionAt, as Embree's hits use it, agrees with intersect.
  SurfaceInteraction again =
      tri.interactionAt(Ray(Point3f(0.2f, 0.3f, -2), Vector3f(0, 0, 1)), 0.2f, 0.3f, 2);
  test::expectNear(Vector3f(again.p), Vector3f(isect.p), 1e-6f);
  test::expectNear(again.dpdu, isect.dpdu, 1e-6f);
}

TEST(TriangleShape, Misses) {
  TriangleMesh mesh = unitTriangle();
  TriangleShape tri(&mesh, 0);
  Float t;
  EXPECT_FALSE(tri.intersect(Ray(Point3f(0.6f, 0.6f, 1), Vector3f(0, 0, -1)), &t, nullptr));
  EXPECT_FALSE(tri.intersectP(Ray(Point3f(0.2f, 0.2f, 1), Vector3f(0, 0, -1), 0.99f)));
  EXPECT_FALSE(tri.intersectP(Ray(Point3f(0.2f, 0.2f, 1), Vector3f(0, 0, 1))));
  EXPECT_FALSE(tri.intersectP(Ray(Point3f(0.2f, 0.2f, 1), Vector3f(1, 0, 0))));  // parallel
  Float nan = std::numeric_limits<Float>::quiet_NaN();
  EXPECT_FALSE(tri.intersectP(Ray(Point3f(0.2f, nan, 1), Vector3f(0, 0, -1))));
  EXPECT_FALSE(tri.intersectP(Ray(Point3f(0.2f, 0.2f, 1), Vector3f(0, 0, 0))));
  // An origin on the plane does not hit it.
  EXPECT_FALSE(tri.intersectP(Ray(Point3f(0.2f, 0.2f, 0), Vector3f(0.3f, 0.1f, 1))));
}

TEST(TriangleShape, VertexUVsGiveTangents) {
  // (u, v) = (x / 2, y / 4): dp/du = (2, 0, 0), dp/dv = (0, 4, 0).
  TriangleMesh mesh(Transform(), false, {0, 1, 2}, {{0, 0, 0}, {2, 0, 0}, {0, 4, 0}}, {}, {},
                    {{0, 0}, {1, 0}, {0, 1}});
  TriangleShape tri(&mesh, 0);
  Float t;
  SurfaceInteraction isect;
  ASSERT_TRUE(tri.intersect(Ray(Point3f(0.5f, 1, 3), Vector3f(0, 0, -1)), &t, &isect));
  test::expectNear(isect.dpdu, Vector3f(2, 0, 0), 1e-5f);
  test::expectNear(isect.dpdv, Vector3f(0, 4, 0), 1e-5f);
  EXPECT_NEAR(isect.uv.x, 0.25f, 1e-6);
  EXPECT_NEAR(isect.uv.y, 0.25f, 1e-6);
}

TEST(TriangleShape, DegenerateUVsFallBackToAFrame) {
  TriangleMesh mesh =
      unitTriangle(Transform(), false, {}, {}, {{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}});
  TriangleShape tri(&mesh, 0);
  Float t;
  SurfaceInteraction isect;
  ASSERT_TRUE(tri.intersect(Ray(Point3f(0.2f, 0.2f, 1), Vector3f(0, 0, -1)), &t, &isect));
  EXPECT_NEAR(isect.dpdu.length(), 1, 1e-5);
  EXPECT_NEAR(isect.dpdv.length(), 1, 1e-5);
  EXPECT_NEAR(dot(isect.dpdu, isect.n), 0, 1e-6);
  EXPECT_NEAR(dot(isect.dpdv, isect.n), 0, 1e-6);
  EXPECT_NEAR(std::abs(isect.n.z), 1, 1e-6);
}

TEST(TriangleShape, Orientation) {
  Float t;
  SurfaceInteraction isect;
  Ray down(Point3f(0.2f, 0.2f, 1), Vector3f(0, 0, -1));
  {
    TriangleMesh mesh = unitTriangle(Transform(), true);
    ASSERT_TRUE(TriangleShape(&mesh, 0).intersect(down, &t, &isect));
    EXPECT_NEAR(isect.n.z, -1, 1e-6);
  }
  {
    // A mirror reverses the winding in world space; the handedness xor restores +z (the object
    // normal (0,0,1) transformed as a normal), and ReverseOrientation then flips it.
    for (bool reverse : {false, true}) {
      TriangleMesh mesh = unitTriangle(scale(-1, 1, 1), reverse);
      TriangleShape tri(&mesh, 0);
      ASSERT_TRUE(tri.intersect(Ray(Point3f(-0.2f, 0.2f, 1), Vector3f(0, 0, -1)), &t, &isect));
      EXPECT_NEAR(isect.n.z, reverse ? -1 : 1, 1e-6);
      Float pdf;
      EXPECT_NEAR(tri.sample(Point2f(0.3f, 0.4f), &pdf).n.z, reverse ? -1 : 1, 1e-6);
    }
  }
  {
    // Per-vertex normals decide the side of the geometric normal.
    std::vector<Normal3f> n(3, Normal3f(0.1f, 0, -1));
    TriangleMesh mesh = unitTriangle(Transform(), false, n);
    ASSERT_TRUE(TriangleShape(&mesh, 0).intersect(down, &t, &isect));
    EXPECT_NEAR(isect.n.z, -1, 1e-6);
    test::expectNear(Vector3f(isect.shading.n), normalize(Vector3f(0.1f, 0, -1)), 1e-5f);
    // ReverseOrientation flips the given normals, and with them the surface.
    TriangleMesh reversed = unitTriangle(Transform(), true, n);
    ASSERT_TRUE(TriangleShape(&reversed, 0).intersect(down, &t, &isect));
    EXPECT_NEAR(isect.n.z, 1, 1e-6);
  }
}

TEST(TriangleShape, ShadingFrame) {
  std::vector<Normal3f> n = {Normal3f(0, 0, 1), Normal3f(1, 0, 1), Normal3f(0, 1, 1)};
  std::vector<Vector3f> s(3, Vector3f(1, 1, 0));
  TriangleMesh mesh = unitTriangle(Transform(), false, n, s);
  TriangleShape tri(&mesh, 0);
  Float t;
  SurfaceInteraction isect;
  ASSERT_TRUE(tri.intersect(Ray(Point3f(0.25f, 0.25f, 1), Vector3f(0, 0, -1)), &t, &isect));
  // ns = normalize(0.5 n0 + 0.25 n1 + 0.25 n2).
  Vector3f ns = normalize(Vector3f(0.25f, 0.25f, 1));
  test::expectNear(Vector3f(isect.shading.n), ns, 1e-5f);
  // shading dp/du follows S, made perpendicular to ns; the frame is right-handed about ns.
  Vector3f ss = normalize(isect.shading.dpdu);
  EXPECT_NEAR(dot(ss, ns), 0, 1e-5);
  EXPECT_GT(dot(ss, Vector3f(1, 1, 0)), 0.9f);
  test::expectNear(normalize(cross(isect.shading.dpdu, isect.shading.dpdv)), ns, 1e-5f);
  // dn/du, dn/dv from the normals with the default (u, v): u = b1 + b2, v = b2.
  test::expectNear(Vector3f(isect.shading.dndu), Vector3f(1, 0, 0), 1e-5f);
  test::expectNear(Vector3f(isect.shading.dndv), Vector3f(-1, 1, 0), 1e-5f);
}

TEST(TriangleShape, SamplingIsUniformOverTheTriangle) {
  TriangleMesh mesh(Transform(), false, {0, 1, 2}, {{1, 1, 1}, {3, 1, 1}, {1, 2, 3}});
  TriangleShape tri(&mesh, 0);
  RNG rng(11);
  int nearP0 = 0, n = 20000;
  for (int i = 0; i < n; ++i) {
    Float pdf;
    Float u0 = rng.uniformFloat();
    Interaction it = tri.sample(Point2f(u0, rng.uniformFloat()), &pdf);
    EXPECT_NEAR(pdf, 1 / tri.area(), 1e-5f);
    // On the plane, inside the triangle.
    Float tHit;
    Vector3f nrm(it.n);
    ASSERT_TRUE(tri.intersectP(Ray(it.p + nrm, -nrm)));
    EXPECT_TRUE(tri.intersect(Ray(it.p + nrm, -nrm), &tHit, nullptr));
    EXPECT_NEAR(tHit, 1, 1e-5);
    // The sub-triangle at p0 with half the edges holds a quarter of the area.
    Vector3f e1(2, 0, 0), e2(0, 1, 2), d = it.p - Point3f(1, 1, 1);
    // Solve d = a e1 + b e2 (e1 and e2 are orthogonal).
    Float a = dot(d, e1) / dot(e1, e1), b = dot(d, e2) / dot(e2, e2);
    if (a + b < 0.5f) ++nearP0;
  }
  EXPECT_NEAR(Float(nearP0) / n, 0.25f, 0.01f);
}

// sampleFrom is sample(ref, ...) with the unit direction to the point: the same point and density,
// and the direction bit for bit normalize(p - ref.p), from the distance the density was converted
// with; no density (and no direction owed) for a reference point on the sampled point.
TEST(TriangleShape, SampleFromGivesSampleAndItsDirection) {
  TriangleMesh mesh(Transform(), false, {0, 1, 2}, {{1, 1, 1}, {3, 1, 1}, {1, 2, 3}});
  TriangleShape tri(&mesh, 0);
  RNG rng(5);
  int compared = 0;
  for (int i = 0; i < 2000; ++i) {
    Interaction ref(
        Point3f(4 * rng.uniformFloat() - 1, 4 * rng.uniformFloat() - 1, 4 * rng.uniformFloat() - 1),
        0);
    if (test::expectSampleFromIsSample(tri, ref, Point2f(rng.uniformFloat(), rng.uniformFloat())))
      ++compared;
  }
  EXPECT_GT(compared, 1900);
  // The reference point on the sample itself: density 0.
  Point2f u(0.25f, 0.5f);
  Float areaPdf;
  Interaction onShape = tri.sample(u, &areaPdf);
  Float pdf = -1;
  Vector3f wi;
  tri.sampleFrom(Interaction(onShape.p, 0), u, &pdf, &wi);
  EXPECT_EQ(pdf, 0);
}

TEST(TriangleShape, WatertightAlongSharedEdges) {
  // A fan of triangles around a centre vertex; rays aimed exactly at the shared edges and at the
  // centre vertex must never slip through.
  const int k = 7;
  std::vector<Point3f> p = {Point3f(0.1f, -0.2f, 0.3f)};
  std::vector<int> idx;
  for (int i = 0; i < k; ++i) {
    Float a = 2 * kPi * i / k;
    p.emplace_back(0.1f + std::cos(a), -0.2f + std::sin(a), 0.3f + 0.2f * std::cos(3 * a));
    idx.insert(idx.end(), {0, 1 + i, 1 + (i + 1) % k});
  }
  TriangleMesh mesh(rotate(33, Vector3f(1, 2, 3)), false, idx, p);
  std::vector<std::unique_ptr<Shape>> tris = createTriangleShapes(&mesh);
  RNG rng(12);
  int misses = 0;
  for (int i = 0; i < 20000; ++i) {
    int e = int(rng.uniformUInt32(k));
    Float s = rng.uniformFloat();
    Point3f target = lerp(s, mesh.p[0], mesh.p[1 + e]);
    if (i % 100 == 0) target = mesh.p[0];
    Point3f o(rng.uniformFloat() * 4 - 2, rng.uniformFloat() * 4 - 2, 5);
    Ray ray(o, target - o);
    bool hit = false;
    for (const auto& tri : tris) hit = hit || tri->intersectP(ray);
    if (!hit) ++misses;
  }
  EXPECT_EQ(misses, 0);
}

// Each parameter on its own line, so that an error's line tells which one it is about.
FileLoc meshLine(int line) { return FileLoc{"mesh.pbrt", line, 1}; }

ParamSet quadParams() {
  ParamSet ps;
  ps.add(test::ints("indices", {0, 1, 2, 0, 2, 3}, meshLine(2)));
  ps.add(test::points("P", {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, meshLine(3)));
  return ps;
}

// The SceneError's line and whether its message names the parameter.
void expectError(const ParamSet& ps, int line, const std::string& name) {
  std::unique_ptr<TriangleMesh> mesh;
  try {
    createTriangleMeshShapes(Transform(), false, ps, &mesh, FileLoc{"mesh.pbrt", 99, 1});
    ADD_FAILURE() << "expected a SceneError about " << name;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find("\"" + name + "\""), std::string::npos) << e.what();
  }
}

TEST(TriangleShape, MeshFactory) {
  ParamSet ps = quadParams();
  ps.add(test::floats("st", {0, 0, 1, 0, 1, 1, 0, 1}, meshLine(4)));
  std::unique_ptr<TriangleMesh> mesh;
  auto shapes = createTriangleMeshShapes(translate(Vector3f(0, 0, 2)), false, ps, &mesh, FileLoc{});
  ASSERT_EQ(shapes.size(), 2u);
  ASSERT_TRUE(mesh);
  EXPECT_EQ(mesh->p[2], Point3f(1, 1, 2));  // world space
  EXPECT_EQ(mesh->uv.size(), 4u);
  int index = -1;
  EXPECT_EQ(shapes[1]->triangleMesh(&index), mesh.get());
  EXPECT_EQ(index, 1);
  EXPECT_STREQ(shapes[0]->kind(), "triangle");
  ps.forEachUnused([](const ParamItem& it) { ADD_FAILURE() << it.name << " unused"; });

  ParamSet bad = quadParams();
  bad.add(test::ints("indices", {0, 1, 2, 0}, meshLine(5)));
  expectError(bad, 5, "indices");
  bad = quadParams();
  bad.add(test::ints("indices", {0, 1, 2, 0, 2, 4}, meshLine(6)));
  expectError(bad, 6, "indices");
  bad = quadParams();
  bad.add(test::normals("N", {0, 0, 1, 0, 0, 1, 0, 0, 1}, meshLine(7)));
  expectError(bad, 7, "N");
  bad = quadParams();
  bad.add(test::vectors("S", {1, 0, 0}, meshLine(8)));
  expectError(bad, 8, "S");
  bad = quadParams();
  bad.add(test::point2s("uv", {0, 0, 1, 0}, meshLine(9)));
  expectError(bad, 9, "uv");
  ParamSet noP;
  noP.add(test::ints("indices", {0, 1, 2}, meshLine(10)));
  expectError(noP, 99, "P");
  // A single triangle may omit its indices.
  ParamSet one;
  one.add(test::points("P", {0, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(createTriangleMeshShapes(Transform(), false, one, &mesh, FileLoc{}).size(), 1u);
}

TEST(TriangleShape, PlyMeshFactory) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("candela_ply_" + std::to_string(::getpid()));
  fs::create_directories(dir / "sub");
  {
    std::ofstream f(dir / "sub" / "quad.ply");
    f << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
         "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  }
  ParamSet ps;
  const FileLoc filenameLoc{"scene.pbrt", 12, 5};
  ps.add(test::strings("filename", {"sub/quad.ply"}, filenameLoc));
  std::unique_ptr<TriangleMesh> mesh;
  auto shapes = createPlyMeshShapes(Transform(), false, ps, &mesh, FileLoc{}, dir.string());
  EXPECT_EQ(shapes.size(), 2u);
  Float area = 0;
  for (const auto& s : shapes) area += s->area();
  EXPECT_NEAR(area, 1, 1e-6);

  ps.add(test::strings("filename", {"sub/missing.ply"}, filenameLoc));
  try {
    createPlyMeshShapes(Transform(), false, ps, &mesh, FileLoc{}, dir.string());
    ADD_FAILURE() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 12);
    EXPECT_NE(std::string(e.what()).find("missing.ply"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace candela
