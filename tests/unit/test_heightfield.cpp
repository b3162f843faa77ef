// The heightfield shape: its mesh (vertices, (u, v), winding), hits interpolating the heights,
// orientation, and the factory's errors for wrong counts.
#include <gtest/gtest.h>

#include "core/rng.h"
#include "shapes/heightfield.h"
#include "support/param_items.h"

namespace candela {
namespace {

// The lines of the counts and of the heights: each error must point to the one at fault.
const FileLoc kCountsLoc{"hf.pbrt", 3, 5}, kHeightsLoc{"hf.pbrt", 4, 5};

ParamSet heightfieldParams(int nu, int nv, std::vector<Float> z) {
  return test::paramSet({test::ints("nu", {nu}, kCountsLoc), test::ints("nv", {nv}, kCountsLoc),
                         test::floats("Pz", std::move(z), kHeightsLoc)});
}

TEST(Heightfield, MeshLayout) {
  // 3 x 2 heights: 2 x 1 cells, 4 triangles; vertex (i, j) at (i / 2, j, z[j * 3 + i]).
  std::vector<Float> z = {0, 1, 2, 3, 4, 5};
  auto mesh = makeHeightfieldMesh(Transform(), false, 3, 2, z);
  EXPECT_EQ(mesh->triangleCount(), 4);
  ASSERT_EQ(mesh->p.size(), 6u);
  EXPECT_EQ(mesh->p[4], Point3f(0.5f, 1, 4));
  EXPECT_EQ(mesh->uv[4], Point2f(0.5f, 1));
  for (int idx : mesh->indices) EXPECT_LT(idx, 6);
}

TEST(Heightfield, HitsFollowTheHeights) {
  // A plane z = 0.3 x - 0.2 y + 0.5 sampled on 5 x 4 points: every hit lies on it, with
  // (u, v) = (x, y) and a normal with positive z (counter-clockwise seen from above).
  const int nu = 5, nv = 4;
  std::vector<Float> z;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) z.push_back(0.3f * i / (nu - 1) - 0.2f * j / (nv - 1) + 0.5f);
  std::unique_ptr<TriangleMesh> mesh;
  ParamSet ps = heightfieldParams(nu, nv, z);
  auto shapes = createHeightfieldShapes(Transform(), false, ps, &mesh, FileLoc());
  ASSERT_EQ(shapes.size(), size_t(2 * (nu - 1) * (nv - 1)));
  Vector3f planeNormal = normalize(Vector3f(-0.3f, 0.2f, 1));
  RNG rng(31);
  for (int k = 0; k < 500; ++k) {
    Float x = rng.uniformFloat(), y = rng.uniformFloat();
    Ray ray(Point3f(x, y, 3), Vector3f(0, 0, -1));
    int hits = 0;
    for (const auto& s : shapes) {
      Float t;
      SurfaceInteraction si;
      if (!s->intersect(ray, &t, &si)) continue;
      ++hits;
      EXPECT_NEAR(si.p.z, 0.3f * x - 0.2f * y + 0.5f, 1e-5f);
      EXPECT_NEAR(si.uv.x, x, 1e-5f);
      EXPECT_NEAR(si.uv.y, y, 1e-5f);
      EXPECT_NEAR(dot(si.n, planeNormal), 1, 1e-5f);
    }
    EXPECT_GE(hits, 1);  // more than one only on a shared edge
  }
}

TEST(Heightfield, ReverseOrientationAndTransform) {
  std::vector<Float> z = {0, 0, 0, 0};
  auto up = makeHeightfieldMesh(translate(Vector3f(0, 0, 2)), false, 2, 2, z);
  auto down = makeHeightfieldMesh(translate(Vector3f(0, 0, 2)), true, 2, 2, z);
  Ray ray(Point3f(0.25f, 0.5f, 5), Vector3f(0, 0, -1));
  for (auto* mesh : {up.get(), down.get()}) {
    auto shapes = createTriangleShapes(mesh);
    bool hit = false;
    for (const auto& s : shapes) {
      Float t;
      SurfaceInteraction si;
      if (!s->intersect(ray, &t, &si)) continue;
      hit = true;
      EXPECT_NEAR(t, 3, 1e-6);
      EXPECT_NEAR(si.n.z, mesh == up.get() ? 1 : -1, 1e-6);
    }
    EXPECT_TRUE(hit);
  }
}

void expectError(const ParamSet& ps, int line, const std::string& word) {
  std::unique_ptr<TriangleMesh> mesh;
  try {
    createHeightfieldShapes(Transform(), false, ps, &mesh, FileLoc{"hf.pbrt", 1, 1});
    ADD_FAILURE() << "expected a SceneError about " << word;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
  }
}

TEST(Heightfield, FactoryErrors) {
  expectError(heightfieldParams(3, 2, {0, 1, 2, 3, 4}), 4, "5 values but nu * nv = 3 * 2 = 6");
  expectError(heightfieldParams(1, 4, {0, 1, 2, 3}), 3, "\"nu\" must be at least 2");
  expectError(heightfieldParams(2, 0, {}), 3, "\"nv\" must be at least 2");
  expectError(heightfieldParams(2, 2, {0, 1, std::numeric_limits<Float>::quiet_NaN(), 3}), 4,
              "not finite");
  ParamSet noNu;
  noNu.add(test::ints("nv", {2}, kCountsLoc));
  noNu.add(test::floats("Pz", {0, 0, 0, 0}, kHeightsLoc));
  expectError(noNu, 1, "missing \"integer nu\"");
  ParamSet noPz;
  noPz.add(test::ints("nu", {2}, kCountsLoc));
  noPz.add(test::ints("nv", {2}, kCountsLoc));
  expectError(noPz, 1, "missing \"float Pz\"");
}

}  // namespace
}  // namespace candela
