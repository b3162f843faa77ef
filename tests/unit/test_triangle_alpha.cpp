// Triangle-mesh cut-outs ("alpha", "shadowalpha"; pbrt-v2, v3): hits where the texture is 0 are
// ignored by the triangle's own tests and by Embree's filter callbacks alike; occlusion queries
// pass where alpha or shadowalpha is 0 (as pbrt-v3's IntersectP); the factory reads both from
// textures.
#include <gtest/gtest.h>

#include "accel/embree/embree_aggregate.h"
#include "assembly/shape_factory.h"
#include "assembly/texture_factory.h"
#include "core/rng.h"
#include "shapes/triangle_mesh.h"
#include "support/param_items.h"
#include "support/test_device.h"

namespace candela {
namespace {

// Zero where u < 0.5.
class HalfTexture : public Texture<Float> {
 public:
  Float evaluate(const SurfaceInteraction& si) const override { return si.uv.x < 0.5f ? 0 : 1; }
};

// The unit square at height z as two triangles, (u, v) = (x, y).
std::unique_ptr<TriangleMesh> square(Float z) {
  return std::make_unique<TriangleMesh>(
      Transform(), false, std::vector<int>{0, 1, 2, 0, 2, 3},
      std::vector<Point3f>{{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}}, std::vector<Normal3f>(),
      std::vector<Vector3f>(), std::vector<Point2f>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
}

struct Scene {
  std::vector<std::unique_ptr<TriangleMesh>> meshes;
  std::vector<std::unique_ptr<Shape>> shapes;
  std::vector<Primitive> primitives;
  void add(std::unique_ptr<TriangleMesh> m) {
    for (auto& s : createTriangleShapes(m.get())) {
      primitives.push_back(Primitive{s.get(), nullptr, nullptr});
      shapes.push_back(std::move(s));
    }
    meshes.push_back(std::move(m));
  }
};

TEST(TriangleAlpha, CutOutsInEmbreeAndInTheShape) {
  HalfTexture half;
  Scene scene;
  auto front = square(1);
  front->alpha = &half;
  front->shadowAlpha = &half;
  scene.add(std::move(front));
  scene.add(square(0));  // opaque, behind
  EmbreeAggregate agg(test::embreeDevice(), scene.primitives);
  RNG rng(41);
  int cut = 0;
  for (int i = 0; i < 2000; ++i) {
    Float x = rng.uniformFloat(), y = rng.uniformFloat();
    if (std::abs(x - 0.5f) < 1e-3f) continue;
    Ray ray(Point3f(x, y, 2), Vector3f(0, 0, -1));
    SurfaceInteraction si;
    ASSERT_TRUE(agg.intersect(ray, &si));
    Float expectedZ = x < 0.5f ? 0 : 1;
    cut += x < 0.5f;
    EXPECT_NEAR(si.p.z, expectedZ, 1e-6f) << x << " " << y;
    // Occlusion of the segment down to z = 0.5: only the solid half of the front square.
    EXPECT_EQ(agg.intersectP(Ray(Point3f(x, y, 2), Vector3f(0, 0, -1), 1.5f)), x >= 0.5f);
    // The triangles' own tests agree (on a fresh ray: intersect shortened the first).
    bool shapeHit = false, shapeOccluded = false;
    Ray fresh(Point3f(x, y, 2), Vector3f(0, 0, -1));
    for (size_t k = 0; k < 2; ++k) {
      Float t;
      shapeHit |= scene.shapes[k]->intersect(fresh, &t, nullptr);
      shapeOccluded |= scene.shapes[k]->intersectP(fresh);
    }
    EXPECT_EQ(shapeHit, x >= 0.5f);
    EXPECT_EQ(shapeOccluded, x >= 0.5f);
  }
  EXPECT_GT(cut, 800);
}

TEST(TriangleAlpha, ShadowAlphaOnlyForOcclusion) {
  HalfTexture half;
  Scene scene;
  auto m = square(1);
  m->shadowAlpha = &half;  // seen by camera rays everywhere, casts a shadow only where u >= 0.5
  scene.add(std::move(m));
  EmbreeAggregate agg(test::embreeDevice(), scene.primitives);
  for (Float x : {0.25f, 0.75f}) {
    Ray ray(Point3f(x, 0.5f, 2), Vector3f(0, 0, -1));
    SurfaceInteraction si;
    EXPECT_TRUE(agg.intersect(ray, &si)) << x;
    EXPECT_EQ(agg.intersectP(Ray(Point3f(x, 0.5f, 2), Vector3f(0, 0, -1))), x > 0.5f) << x;
  }
}

ShapeDesc meshDesc() {
  ShapeDesc d;
  d.name = "trianglemesh";
  d.loc = FileLoc{"alpha.pbrt", 2, 1};
  d.params.add(test::ints("indices", {0, 1, 2}));
  d.params.add(test::points("P", {0, 0, 0, 1, 0, 0, 0, 1, 0}));
  return d;
}

TEST(TriangleAlpha, FactoryReadsAlphaAndShadowAlpha) {
  TextureDesc zero;
  zero.name = "constant";
  zero.textureName = "zero";
  zero.type = "float";
  zero.params.add(test::floats("value", {0}));
  std::vector<TextureDesc> descs = {zero};
  TextureFactory textures(descs);
  SurfaceInteraction si;

  // Opaque: no alpha, or alpha 1, needs no test.
  EXPECT_EQ(createShapes(meshDesc(), Transform(), textures).mesh->alpha, nullptr);
  ShapeDesc one = meshDesc();
  one.params.add(test::floats("alpha", {1}));
  CreatedShapes c1 = createShapes(one, Transform(), textures);
  EXPECT_EQ(c1.mesh->alpha, nullptr);
  EXPECT_EQ(c1.mesh->shadowAlpha, nullptr);
  one.params.forEachUnused([](const ParamItem& item) { ADD_FAILURE() << item.name << " unused"; });

  // alpha 0: cut everywhere; shadowalpha defaults to it.
  ShapeDesc cut = meshDesc();
  cut.params.add(test::floats("alpha", {0}));
  CreatedShapes c2 = createShapes(cut, Transform(), textures);
  ASSERT_NE(c2.mesh->alpha, nullptr);
  EXPECT_EQ(c2.mesh->alpha->evaluate(si), 0);
  EXPECT_EQ(c2.mesh->shadowAlpha, c2.mesh->alpha);
  Ray down(Point3f(0.2f, 0.2f, 1), Vector3f(0, 0, -1));
  Float t;
  EXPECT_FALSE(c2.shapes[0]->intersect(down, &t, nullptr));
  EXPECT_FALSE(c2.shapes[0]->intersectP(down));

  // A named texture for alpha, and shadowalpha 1: shadowalpha cannot bring back what alpha cut
  // (pbrt-v3 tests both for shadow rays), so the mesh is invisible and casts no shadow.
  ShapeDesc named = meshDesc();
  named.params.add(test::texture("alpha", "zero"));
  named.params.add(test::floats("shadowalpha", {1}));
  CreatedShapes c3 = createShapes(named, Transform(), textures);
  ASSERT_NE(c3.mesh->alpha, nullptr);
  EXPECT_EQ(c3.mesh->shadowAlpha, c3.mesh->alpha);
  EXPECT_FALSE(c3.shapes[0]->intersect(down, &t, nullptr));
  EXPECT_FALSE(c3.shapes[0]->intersectP(down));

  // Both given: shadow rays pass where either is 0. Opaque to the camera, alpha 1 as a texture;
  // shadowalpha 0 cuts shadows; and alpha 0 with shadowalpha 0.5 cuts both.
  std::vector<TextureDesc> more = {zero, zero, zero};
  more[1].textureName = "one";
  more[1].params = test::paramSet({test::floats("value", {1})});
  more[2].textureName = "half";
  more[2].params = test::paramSet({test::floats("value", {0.5f})});
  TextureFactory both(more);
  ShapeDesc opaque = meshDesc();
  opaque.params.add(test::texture("alpha", "one"));
  opaque.params.add(test::texture("shadowalpha", "zero"));
  CreatedShapes c4 = createShapes(opaque, Transform(), both);
  EXPECT_TRUE(c4.shapes[0]->intersect(down, &t, nullptr));
  EXPECT_FALSE(c4.shapes[0]->intersectP(down));
  ShapeDesc cutBoth = meshDesc();
  cutBoth.params.add(test::texture("alpha", "zero"));
  cutBoth.params.add(test::texture("shadowalpha", "half"));
  CreatedShapes c5 = createShapes(cutBoth, Transform(), both);
  EXPECT_FALSE(c5.shapes[0]->intersect(down, &t, nullptr));
  EXPECT_FALSE(c5.shapes[0]->intersectP(down));

  // An unknown texture name is an error at the parameter.
  ShapeDesc bad = meshDesc();
  bad.params.add(test::texture("alpha", "nosuch"));
  EXPECT_THROW(createShapes(bad, Transform(), textures), SceneError);
}

}  // namespace
}  // namespace candela
