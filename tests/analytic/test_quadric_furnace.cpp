// Furnace tests on closed surfaces built from the new quadrics (lrt draft §16.2's closed form):
// inside an enclosure whose every piece is a diffuse emitter (Le = 0.5) of albedo 0.5, a path of
// at most d bounces sees L = 1 - 0.5^(d+1) in every direction. This needs the pieces to meet
// without cracks, their normals turned inward by ReverseOrientation, and each shape's area
// sampling and solid-angle pdf to agree (the path integrator weights light samples by them).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/render_scene.h"

namespace candela {
namespace {

std::string scene(const std::string& eye, const std::string& shapes, int depth, int spp) {
  return "LookAt " + eye + "  0.3 0.2 10  0 1 0\n" +
         "Camera \"perspective\" \"float fov\" [120]\n"
         "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16]\n"
         "Sampler \"random\" \"integer pixelsamples\" [" +
         std::to_string(spp) + "]\n" + "SurfaceIntegrator \"path\" \"integer maxdepth\" [" +
         std::to_string(depth) + "]\nWorldBegin\n" +
         "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
         "AreaLightSource \"diffuse\" \"rgb L\" [0.5 0.5 0.5]\n" +
         shapes + "WorldEnd\n";
}

// A piece of the enclosure; inward: turn its normal inside with ReverseOrientation.
std::string piece(const std::string& shape, bool inward) {
  return std::string("AttributeBegin\n") + (inward ? "ReverseOrientation\n" : "") + "Shape " +
         shape + "\nAttributeEnd\n";
}

struct PixelStats {
  double mean = 0, sd = 0, worst = 0;  // worst: largest |pixel - expected|
  int n = 0;
};

// Over every pixel's first channel (the scene is grey).
PixelStats pixelStats(const Film& film, double expected) {
  PixelStats st;
  double sum = 0, sum2 = 0;
  Bounds2i b = film.pixelBounds();
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) {
      double v = film.pixelValue(Point2i(x, y))[0];
      sum += v;
      sum2 += v * v;
      st.worst = std::max(st.worst, std::abs(v - expected));
      ++st.n;
    }
  st.mean = sum / st.n;
  st.sd = std::sqrt(std::max(0.0, sum2 / st.n - st.mean * st.mean));
  return st;
}

struct Enclosure {
  const char* name;
  std::string eye;
  std::string shapes;
};

std::vector<Enclosure> enclosures() {
  // Partial sweeps are closed by a second piece with the complementary sweep, rotated.
  return {
      {"cylinder + disks", "0 0 0",
       piece("\"cylinder\" \"float radius\" [1] \"float zmin\" [-1] \"float zmax\" [1]", true) +
           piece("\"disk\" \"float height\" [-1] \"float radius\" [1]", false) +
           piece("\"disk\" \"float height\" [1] \"float radius\" [1]", true)},
      {"two half cylinders + annulus + disk", "0 0 0.2",
       piece("\"cylinder\" \"float zmin\" [-1] \"float zmax\" [1] \"float phimax\" [150]", true) +
           "AttributeBegin\nRotate 150 0 0 1\n" +
           piece("\"cylinder\" \"float zmin\" [-1] \"float zmax\" [1] \"float thetamax\" [210]",
                 true) +
           "AttributeEnd\n" +
           piece("\"disk\" \"float height\" [-1] \"float innerradius\" [0.4]", false) +
           piece("\"disk\" \"float height\" [-1] \"float radius\" [0.4]", false) +
           piece("\"disk\" \"float height\" [1]", true)},
      {"cone + disk", "0 0 0.5",
       piece("\"cone\" \"float radius\" [1] \"float height\" [2]", true) +
           piece("\"disk\" \"float height\" [0]", false)},
      {"paraboloid + disk", "0 0 0.5",
       piece("\"paraboloid\" \"float radius\" [1] \"float zmin\" [0] \"float zmax\" [1]", true) +
           piece("\"disk\" \"float height\" [1]", true)},
      {"hyperboloid + disks", "0 0 0",
       piece("\"hyperboloid\" \"point p1\" [1 0 -1] \"point p2\" [0 1 1]", true) +
           piece("\"disk\" \"float height\" [-1]", false) +
           piece("\"disk\" \"float height\" [1]", true)},
      {"heightfield lid on a cylinder", "0 0 0",
       piece("\"cylinder\" \"float radius\" [1] \"float zmin\" [-1] \"float zmax\" [1]", true) +
           piece("\"disk\" \"float height\" [-1] \"float radius\" [1]", false) +
           // A flat 2 x 2 heightfield square at z = 1 over [-1, 1]^2 covers the top.
           "AttributeBegin\nTranslate -1 -1 1\nScale 2 2 1\nReverseOrientation\n"
           "Shape \"heightfield\" \"integer nu\" [3] \"integer nv\" [3] "
           "\"float Pz\" [0 0 0 0 0 0 0 0 0]\nAttributeEnd\n"},
  };
}

TEST(QuadricFurnace, EmissionSeenEverywhere) {
  // maxdepth 0: every camera ray meets an emitter's inner side, so every pixel is exactly 0.5;
  // a crack between the pieces, or a normal facing out, shows as a darker pixel.
  for (const Enclosure& e : enclosures()) {
    auto r = test::renderSceneText(scene(e.eye, e.shapes, 0, 64));
    EXPECT_LT(pixelStats(r.film(), 0.5).worst, 1e-5) << e.name;
  }
}

TEST(QuadricFurnace, PathDepthTwoMatchesTheSeries) {
  // maxdepth 2: L = 0.5 (1 + 0.5 + 0.25) = 0.875. Pixels are independent estimates (256 spp,
  // per-pixel sd 2-4%): the image mean must be within 4.5 standard errors of 0.875 (two-sided
  // significance ~1e-5), which detects a bias of about 1%, and no pixel may lie beyond 5.5 of
  // its sd (an outlier: a crack or a bad light sample).
  for (const Enclosure& e : enclosures()) {
    auto r = test::renderSceneText(scene(e.eye, e.shapes, 2, 256));
    PixelStats st = pixelStats(r.film(), 0.875);
    double se = st.sd / std::sqrt(double(st.n));
    EXPECT_NEAR(st.mean, 0.875, 4.5 * se) << e.name << ": sd " << st.sd;
    EXPECT_LT(st.worst, 5.5 * st.sd) << e.name;
    EXPECT_LT(se, 0.003) << e.name;  // the test has power
  }
}

}  // namespace
}  // namespace candela
