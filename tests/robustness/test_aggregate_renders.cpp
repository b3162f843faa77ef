// The same scene rendered with each aggregate (Accelerator statement or the --accel override)
// gives Embree's image.
// - Quadrics only: Embree runs each quadric's own intersection as user geometry, so every
//   aggregate finds the same t in the same code and the images are bit-identical.
// - Quadrics, triangle meshes and instances (static, mirrored, animated): Embree's triangle test
//   and its instance transforms round differently from the shapes' own tests (by ~1e-7
//   relative), which moves hit points and so shading by rounding, and may flip a shadow ray that
//   grazes a silhouette. Per pixel and channel |a - b| <= kRelative * (a + b) / 2 + kAbsolute
//   must hold on all but kFlippedPixelFraction of the pixels, and the image means must agree to
//   kMeanRelative.
#include <gtest/gtest.h>

#include "support/image_compare.h"
#include "support/render_scene.h"

namespace candela {
namespace {

constexpr float kRelative = 1e-4f, kAbsolute = 1e-5f;
constexpr double kFlippedPixelFraction = 0.01, kMeanRelative = 1e-3;

const char* kHeader = R"(
LookAt 0 4 -11  0 0.5 0  0 1 0
Camera "perspective" "float fov" [45]
Film "image" "integer xresolution" [72] "integer yresolution" [48]
Sampler "stratified" "integer xsamples" [2] "integer ysamples" [2] "bool jitter" "true"
PixelFilter "box"
)";

const char* kQuadrics = R"(
WorldBegin
LightSource "point" "point from" [3 6 -4] "rgb I" [30 30 30]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [20 18 16]
  Translate -3 5 -1
  Shape "sphere" "float radius" [0.5]
AttributeEnd
Material "matte" "rgb Kd" [0.6 0.5 0.4]
AttributeBegin
  Translate 0 -1 0  Rotate -90 1 0 0
  Shape "disk" "float radius" [9]
AttributeEnd
AttributeBegin
  Translate -3 0.5 0  Rotate -90 1 0 0
  Shape "cylinder" "float radius" [0.6] "float zmin" [-1] "float zmax" [1] "float phimax" [270]
AttributeEnd
AttributeBegin
  Translate -1 0 1  Rotate -90 1 0 0
  Shape "cone" "float radius" [0.8] "float height" [1.8]
AttributeEnd
AttributeBegin
  Translate 1 0.2 -1  Rotate -70 1 0 0  Scale 1 1.5 0.7
  Shape "paraboloid" "float radius" [0.7] "float zmin" [0] "float zmax" [1.2]
AttributeEnd
AttributeBegin
  Translate 3 0 0.5  Rotate -90 1 0 0
  ReverseOrientation
  Shape "hyperboloid" "point p1" [0.3 -0.6 -1] "point p2" [0.8 0.1 1] "float phimax" [300]
AttributeEnd
AttributeBegin
  Translate 0.5 1.6 2  Scale -1 1 1
  Shape "sphere" "float radius" [1] "float zmin" [-0.6] "float zmax" [0.9] "float phimax" [300]
AttributeEnd
)";

const char* kMeshesAndInstances = R"(
AttributeBegin
  Material "matte" "rgb Kd" [0.3 0.5 0.7]
  Translate 0 -0.99 0
  Shape "trianglemesh" "integer indices" [0 1 2 0 2 3 4 5 6]
    "point P" [-4 0 -4  4 0 -4  4 0 4  -4 0 4   -2 0 -2  -1 2 -1.5  0 0 -2.5]
AttributeEnd
ObjectBegin "thing"
  Shape "sphere" "float radius" [0.35]
  Translate 0.5 0 0
  Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
    "point P" [0 0 0  0.6 0 0  0.6 0.6 0.2  0 0.6 0.2]
  Shape "cylinder" "float radius" [0.1] "float zmin" [0] "float zmax" [0.8]
ObjectEnd
AttributeBegin
  Translate -2 2.5 -2
  ObjectInstance "thing"
AttributeEnd
AttributeBegin
  Translate 2 2.6 -2.5  Scale -1.2 1.2 1.2  Rotate 30 0 1 0
  ObjectInstance "thing"
AttributeEnd
AttributeBegin
  Translate 0 3.2 -1  Rotate 50 1 1 0  Scale 0.8 1.4 0.8
  ObjectInstance "thing"
AttributeEnd
AttributeBegin
  ActiveTransform StartTime
  Translate -0.5 2.3 -3
  ActiveTransform EndTime
  Translate 0.5 2.6 -3  Rotate 40 0 0 1
  ActiveTransform All
  ObjectInstance "thing"
AttributeEnd
AttributeBegin
  ActiveTransform StartTime
  Translate 3.5 0.5 -3
  ActiveTransform EndTime
  Translate 3.5 1.5 -3
  ActiveTransform All
  Shape "sphere" "float radius" [0.4]
AttributeEnd
)";

ImageBuffer render(const std::string& scene, const std::string& flag) {
  test::TestRenderOptions o;
  o.build.seed = 11;
  o.build.accelerator = flag;
  o.render.nThreads = 2;
  test::RenderedScene r = test::renderSceneText(scene, o);
  EXPECT_EQ(r.job().stats.aggregate.name, flag.empty() ? "embree" : flag);
  return r.film().image();
}

TEST(AggregateRenders, QuadricsAreBitIdenticalToEmbree) {
  std::string scene = std::string(kHeader) + kQuadrics + "WorldEnd\n";
  ImageBuffer embree = render(scene, "");
  double sum = 0;
  for (float v : embree.data) sum += v;
  EXPECT_GT(sum, 0);
  for (const char* kind : {"bvh", "kdtree", "grid"}) {
    ImageBuffer img = render(scene, kind);
    ASSERT_EQ(img.data.size(), embree.data.size());
    size_t differing = 0;
    for (size_t i = 0; i < img.data.size(); ++i) differing += img.data[i] != embree.data[i];
    EXPECT_EQ(differing, 0u) << kind;
  }
}

TEST(AggregateRenders, MeshesAndInstancesMatchEmbreeUpToRounding) {
  std::string scene = std::string(kHeader) +
                      "SurfaceIntegrator \"path\" \"integer maxdepth\" [3]\n" + kQuadrics +
                      kMeshesAndInstances + "WorldEnd\n";
  ImageBuffer embree = render(scene, "");
  for (const char* kind : {"bvh", "kdtree", "grid"}) {
    ImageBuffer img = render(scene, kind);
    ASSERT_EQ(img.data.size(), embree.data.size());
    test::RoundingComparison c = test::compareUpToRounding(img, embree, kRelative, kAbsolute);
    std::printf("%s: %zu of %zu pixels beyond rounding, %zu of %zu values identical\n", kind,
                c.flipped, c.pixels, c.identicalValues, c.values);
    EXPECT_LE(double(c.flipped), kFlippedPixelFraction * double(c.pixels)) << kind;
    EXPECT_NEAR(c.sumA, c.sumB, kMeanRelative * c.sumB) << kind;
  }
}

TEST(AggregateRenders, AcceleratorStatementSelectsAndTheFlagWins) {
  std::string scene = std::string(kHeader) + "Accelerator \"kdtree\" \"integer maxprims\" [2]\n" +
                      kQuadrics + "WorldEnd\n";
  test::TestRenderOptions o;
  EXPECT_EQ(test::buildSceneText(scene, o.build).job().stats.aggregate.name, "kdtree");
  o.build.accelerator = "grid";
  EXPECT_EQ(test::buildSceneText(scene, o.build).job().stats.aggregate.name, "grid");
  o.build.accelerator = "nonesuch";
  EXPECT_THROW(test::buildSceneText(scene, o.build), SceneError);
  std::string bad = std::string(kHeader) + "Accelerator \"octree\"\n" + kQuadrics + "WorldEnd\n";
  EXPECT_THROW(test::buildSceneText(bad, {}), SceneError);
}

}  // namespace
}  // namespace candela
