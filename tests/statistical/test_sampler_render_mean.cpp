// A small scene rendered with each of pbrt-v3's samplers has the random sampler's image mean: for
// 8 seeds per sampler (16 samples per pixel, 24 x 18 pixels, path tracing to depth 3), Welch's t
// of the two samples of 8 image means stays below 5.41, the two-sided 0.001 quantile of Student's
// t with 7 degrees of freedom, the fewest Welch-Satterthwaite can give here (family-wise 0.003
// over the three samplers). The spread of the means across seeds is reported: the (0,2)-nets
// should not be noisier than independent samples.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "support/render_scene.h"

namespace candela {
namespace {

std::string scene(const std::string& sampler) {
  return "LookAt 0 1.5 -5  0 0.5 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [50]\n"
         "Film \"image\" \"integer xresolution\" [24] \"integer yresolution\" [18]\n"
         "Sampler " +
         sampler +
         "\n"
         "SurfaceIntegrator \"path\" \"integer maxdepth\" [3]\n"
         "WorldBegin\n"
         "LightSource \"point\" \"point from\" [2 4 -2] \"rgb I\" [10 10 10]\n"
         "AttributeBegin\n"
         "  AreaLightSource \"diffuse\" \"rgb L\" [2 2 2]\n"
         "  Translate -1.5 2.5 1\n"
         "  Shape \"sphere\" \"float radius\" [0.4]\n"
         "AttributeEnd\n"
         "Material \"matte\" \"rgb Kd\" [0.6 0.5 0.4]\n"
         "Shape \"sphere\" \"float radius\" [0.7]\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
         "  \"point P\" [-5 -0.7 -5  5 -0.7 -5  5 -0.7 5  -5 -0.7 5]\n"
         "WorldEnd\n";
}

struct Moments {
  double mean = 0, variance = 0;
};

// The image mean over pixels and channels for seeds 1..8: their mean and sample variance.
Moments imageMeans(const std::string& sampler) {
  std::vector<double> means;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    test::TestRenderOptions o;
    o.build.seed = seed;
    o.render.nThreads = 1;
    ImageBuffer img = test::renderSceneText(scene(sampler), o).film().image();
    double sum = 0;
    for (float v : img.data) sum += v;
    means.push_back(sum / double(img.data.size()));
  }
  Moments m;
  for (double v : means) m.mean += v / double(means.size());
  for (double v : means) m.variance += (v - m.mean) * (v - m.mean) / double(means.size() - 1);
  return m;
}

TEST(SamplerRenderMean, PbrtV3SamplersAgreeWithTheRandomSampler) {
  Moments random = imageMeans("\"random\" \"integer pixelsamples\" [16]");
  ASSERT_GT(random.mean, 0);
  ASSERT_GT(random.variance, 0);
  std::cout << "random: mean " << random.mean << ", sd " << std::sqrt(random.variance) << "\n";
  for (const char* sampler : {"\"02sequence\"", "\"maxmindist\"", "\"sobol\""}) {
    Moments m = imageMeans(std::string(sampler) + " \"integer pixelsamples\" [16]");
    double t = (m.mean - random.mean) / std::sqrt((m.variance + random.variance) / 8);
    std::cout << sampler << ": mean " << m.mean << ", sd " << std::sqrt(m.variance) << ", t " << t
              << "\n";
    EXPECT_LT(std::abs(t), 5.41) << sampler;
  }
}

}  // namespace
}  // namespace candela
