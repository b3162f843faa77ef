// Scenes with pbrt-v2 Volume regions are a pure function of (scene, spp, seed): the same bits for
// 1 and 2 threads and any tile size, for both volume integrators and a marched (grid) region.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "support/render_scene.h"

namespace candela {
namespace {

std::string fogScene(const std::string& volumeIntegrator, const std::string& surfaceIntegrator) {
  return "LookAt 0 1 -4  0 0.5 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [50]\n"
         "Film \"image\" \"integer xresolution\" [20] \"integer yresolution\" [14]\n"
         "Sampler \"random\" \"integer pixelsamples\" [2]\n"
         "SurfaceIntegrator " +
         surfaceIntegrator + "\nVolumeIntegrator " + volumeIntegrator +
         "\n"
         "WorldBegin\n"
         "LightSource \"spot\" \"point from\" [0 3 0] \"point to\" [0 0 0] \"rgb I\" [20 20 20]\n"
         "AttributeBegin\n"
         "  AreaLightSource \"diffuse\" \"rgb L\" [2 2 2]\n"
         "  Translate -1.5 2 1\n"
         "  Shape \"sphere\" \"float radius\" [0.3]\n"
         "AttributeEnd\n"
         "Volume \"homogeneous\" \"rgb sigma_s\" [0.2 0.2 0.2] \"rgb sigma_a\" [0.05 0.05 0.05]\n"
         "  \"point p0\" [-3 -0.5 -3] \"point p1\" [3 3 3]\n"
         "Volume \"volumegrid\" \"integer nx\" [2] \"integer ny\" [2] \"integer nz\" [2]\n"
         "  \"float density\" [0 1 2 3 1 0 2 1] \"rgb sigma_s\" [0.5 0.4 0.3]\n"
         "  \"rgb Le\" [0.1 0.05 0] \"string phase\" \"schlick\" \"float g\" [-0.3]\n"
         "  \"point p0\" [-1 0 -1] \"point p1\" [1 2 1]\n"
         "Material \"matte\" \"rgb Kd\" [0.6 0.5 0.4]\n"
         "Shape \"sphere\" \"float radius\" [0.5]\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
         "  \"point P\" [-5 -0.5 -5  5 -0.5 -5  5 -0.5 5  -5 -0.5 5]\n"
         "WorldEnd\n";
}

ImageBuffer render(const std::string& text, int threads, int tile) {
  test::TestRenderOptions o;
  o.build.seed = 11;
  o.render.nThreads = threads;
  o.render.tileSize = tile;
  return test::renderSceneText(text, o).film().image();
}

class VolumeDeterminism : public testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(VolumeDeterminism, SameBitsForOneAndTwoThreads) {
  std::string text = fogScene(GetParam().first, GetParam().second);
  ImageBuffer one = render(text, 1, 16);
  ImageBuffer two = render(text, 2, 5);
  ASSERT_EQ(one.data.size(), two.data.size());
  EXPECT_EQ(0, std::memcmp(one.data.data(), two.data.data(), one.data.size() * sizeof(float)));
  bool finite = true, nonzero = false;
  for (float v : one.data) {
    finite &= std::isfinite(v);
    nonzero |= v > 0;
  }
  EXPECT_TRUE(finite);
  EXPECT_TRUE(nonzero);
}

INSTANTIATE_TEST_SUITE_P(
    Integrators, VolumeDeterminism,
    testing::Values(std::pair{"\"single\" \"float stepsize\" [0.2]", "\"path\""},
                    std::pair{"\"emission\" \"float stepsize\" [0.3]", "\"directlighting\""},
                    std::pair{"\"single\" \"float stepsize\" [0.25]", "\"whitted\""}));

}  // namespace
}  // namespace candela
