// Metropolis images are a pure function of (scene, mutations, seed): chain c's numbers depend
// only on (seed, c), the bootstrap's on its sample index, and splats are order-independent
// fixed-point sums. So 1 and 2 threads render the same bits, and a crop window renders the same
// bits as that region of the full image (every chain runs; only what lands in the crop is kept).
// Every pixel of a closed scene has alpha 1, with or without a direct-lighting pass.
#include <gtest/gtest.h>

#include <cstring>
#include <optional>
#include <string>

#include "support/render_scene.h"

namespace candela {
namespace {

// A small box with a light in it: paths of every length, light splatting across the image.
std::string scene(const std::string& transport) {
  return "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [50]\n"
         "Film \"image\" \"integer xresolution\" [12] \"integer yresolution\" [10]\n"
         "PixelFilter \"gaussian\"\n" +
         transport +
         "\nWorldBegin\n"
         "Material \"matte\" \"rgb Kd\" [0.6 0.5 0.4]\n"
         "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [4 4 4]\n"
         "Translate 0 0.8 0\nShape \"sphere\" \"float radius\" [0.2]\nAttributeEnd\n"
         "Shape \"sphere\" \"float radius\" [0.4]\n"
         "ReverseOrientation\nShape \"sphere\" \"float radius\" [5]\n"
         "WorldEnd\n";
}

const char* kMlt =
    "Integrator \"mlt\" \"integer bootstrapsamples\" [300] \"integer chains\" [13] "
    "\"integer mutationsperpixel\" [16]";
const char* kMetropolis =
    "Renderer \"metropolis\" \"integer bootstrapsamples\" [300] \"integer samplesperpixel\" [16] "
    "\"integer maxdepth\" [4] \"integer maxconsecutiverejects\" [3]";

test::RenderedScene render(const std::string& transport, int threads,
                           std::optional<Bounds2f> crop = std::nullopt) {
  test::TestRenderOptions o;
  o.build.seed = 7;
  o.build.cropWindow = crop;
  o.render.nThreads = threads;
  return test::renderSceneText(scene(transport), o);
}

bool sameBits(const Spectrum& a, const Spectrum& b) {
  for (int c = 0; c < 3; ++c) {
    Float x = a[c], y = b[c];
    if (std::memcmp(&x, &y, sizeof(Float)) != 0) return false;
  }
  return true;
}

void expectDeterministic(const std::string& transport) {
  auto one = render(transport, 1), two = render(transport, 2);
  const Film& a = one.film();
  const Film& b = two.film();
  double total = 0;
  Bounds2i full = a.pixelBounds();
  for (int y = full.pMin.y; y < full.pMax.y; ++y)
    for (int x = full.pMin.x; x < full.pMax.x; ++x) {
      Point2i p(x, y);
      total += a.pixelValue(p).y();
      EXPECT_EQ(a.pixelAlpha(p), 1) << x << "," << y;  // the camera is inside a closed sphere
      EXPECT_TRUE(sameBits(a.pixelValue(p), b.pixelValue(p))) << x << "," << y;
    }
  EXPECT_GT(total, 0);  // the scene is lit: the comparison is not of two black images
  auto cropped = render(transport, 2, Bounds2f(Point2f(0.25f, 0.3f), Point2f(0.75f, 0.9f)));
  const Film& c = cropped.film();
  Bounds2i crop = c.pixelBounds();
  EXPECT_LT(crop.pMax.x - crop.pMin.x, full.pMax.x - full.pMin.x);
  for (int y = crop.pMin.y; y < crop.pMax.y; ++y)
    for (int x = crop.pMin.x; x < crop.pMax.x; ++x) {
      Point2i p(x, y);
      EXPECT_TRUE(sameBits(a.pixelValue(p), c.pixelValue(p))) << "crop " << x << "," << y;
    }
}

TEST(MltDeterminism, SameBitsForThreadsAndCropWindow) { expectDeterministic(kMlt); }

TEST(MetropolisDeterminism, SameBitsForThreadsAndCropWindow) {
  expectDeterministic(kMetropolis);
  expectDeterministic(std::string(kMetropolis) +
                      " \"bool bidirectional\" \"false\" \"bool dodirectseparately\" \"false\"");
}

}  // namespace
}  // namespace candela
