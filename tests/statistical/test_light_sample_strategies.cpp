// pbrt-v3's lightsamplestrategy, and pbrt-v4's light tree ("bvh"), for the path, volpath and bdpt
// integrators: a strip of ground under six disk lights facing it, of radiance 4 to 128, a matte
// sphere among them, path tracing to depth 3 (so that paths also meet the lights after a bounce,
// where path's MIS weight takes the choice probability at the previous vertex). For 8 seeds per
// strategy (16 samples per pixel), the image means of "power", "spatial" and "bvh" agree with
// "uniform": Welch's t of the two samples of 8 means stays below 5.41, the two-sided 0.001
// quantile of Student's t with 7 degrees of freedom, the fewest Welch-Satterthwaite can give here
// (family-wise 0.009 over the nine). And "spatial" and "bvh", whose choices follow the lights
// nearest each point, have less than 0.6 of the per-pixel variance of "uniform" (measured 0.43
// for path, 0.18 for volpath; "power" 0.81 and 0.43; "bvh" 0.44 and 0.52). With path's
// MIS weight of an emission hit taking the uniform choice probability while "spatial" chose the
// light, t was 7.2 and the variance 1.1 of uniform's: both checks failed.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "support/render_scene.h"

namespace candela {
namespace {

std::string scene(const std::string& integrator, const std::string& strategy) {
  std::string s =
      "LookAt 0 9 0.01  0 0 0  0 1 0\n"
      "Camera \"perspective\" \"float fov\" [90]\n"
      "Film \"image\" \"integer xresolution\" [48] \"integer yresolution\" [16]\n"
      "Sampler \"random\" \"integer pixelsamples\" [16]\n"
      "Integrator \"" +
      integrator + "\" \"integer maxdepth\" [3] \"string lightsamplestrategy\" \"" + strategy +
      "\"\n"
      "WorldBegin\n";
  const int x[6] = {-10, -6, -2, 2, 6, 10};
  for (int i = 0; i < 6; ++i) {
    double l = std::ldexp(1.0, i) * 4;
    // Disks facing the ground: the camera above sees only their dark backs.
    s += "AttributeBegin\n  AreaLightSource \"diffuse\" \"rgb L\" [" + std::to_string(l) + " " +
         std::to_string(l) + " " + std::to_string(l) + "]\n  Translate " + std::to_string(x[i]) +
         " 0.5 0\n  Rotate 90 1 0 0\n  Shape \"disk\" \"float radius\" [0.8]\nAttributeEnd\n";
  }
  s += "Material \"matte\" \"rgb Kd\" [0.6 0.5 0.4]\n"
       "AttributeBegin\n  Translate 0 0.5 1\n  Shape \"sphere\" \"float radius\" [0.5]\n"
       "AttributeEnd\n"
       "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
       "  \"point P\" [-12 0 -4  12 0 -4  12 0 4  -12 0 4]\n"
       "WorldEnd\n";
  return s;
}

struct Renders {
  std::vector<double> means;  // image mean per seed
  double pixelVariance = 0;   // per pixel and channel over the seeds, averaged over the image
};

Renders render(const std::string& integrator, const std::string& strategy) {
  std::vector<std::vector<float>> images;
  Renders r;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    test::TestRenderOptions o;
    o.build.seed = seed;
    o.render.nThreads = 1;
    ImageBuffer img = test::renderSceneText(scene(integrator, strategy), o).film().image();
    double sum = 0;
    for (float v : img.data) sum += v;
    r.means.push_back(sum / double(img.data.size()));
    images.push_back(img.data);
  }
  size_t n = images.front().size();
  for (size_t k = 0; k < n; ++k) {
    double mean = 0, var = 0;
    for (const auto& img : images) mean += img[k] / double(images.size());
    for (const auto& img : images) var += (img[k] - mean) * (img[k] - mean);
    r.pixelVariance += var / double(images.size() - 1) / double(n);
  }
  return r;
}

double welchT(const std::vector<double>& a, const std::vector<double>& b) {
  auto moments = [](const std::vector<double>& v, double* mean, double* var) {
    *mean = 0;
    for (double x : v) *mean += x / double(v.size());
    *var = 0;
    for (double x : v) *var += (x - *mean) * (x - *mean) / double(v.size() - 1);
  };
  double ma, va, mb, vb;
  moments(a, &ma, &va);
  moments(b, &mb, &vb);
  return std::abs(ma - mb) / std::sqrt(va / double(a.size()) + vb / double(b.size()));
}

class LightSampleStrategies : public testing::TestWithParam<const char*> {};

TEST_P(LightSampleStrategies, PowerAndSpatialAreUnbiasedAndSpatialIsLessNoisyAmongManyLights) {
  const std::string integrator = GetParam();
  Renders uniform = render(integrator, "uniform"), power = render(integrator, "power"),
          spatial = render(integrator, "spatial"), tree = render(integrator, "bvh");
  double tPower = welchT(power.means, uniform.means);
  double tSpatial = welchT(spatial.means, uniform.means);
  double tTree = welchT(tree.means, uniform.means);
  std::cout << integrator << ": image means' Welch t against uniform: power " << tPower
            << ", spatial " << tSpatial << ", bvh " << tTree
            << "; per-pixel variance against uniform's " << uniform.pixelVariance << ": power "
            << power.pixelVariance / uniform.pixelVariance << "x, spatial "
            << spatial.pixelVariance / uniform.pixelVariance << "x, bvh "
            << tree.pixelVariance / uniform.pixelVariance << "x\n";
  EXPECT_LT(tPower, 5.41);
  EXPECT_LT(tSpatial, 5.41);
  EXPECT_LT(tTree, 5.41);
  // bdpt's light subpaths start from the distribution of the camera's voxel, above these
  // downward-facing lights, which send it nothing: every light gets the floor, as uniform.
  if (integrator != "bdpt") {
    EXPECT_LT(spatial.pixelVariance, 0.6 * uniform.pixelVariance);
    EXPECT_LT(tree.pixelVariance, 0.6 * uniform.pixelVariance);
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, LightSampleStrategies,
                         testing::Values("path", "volpath", "bdpt"));

}  // namespace
}  // namespace candela
