// Photon mapping is biased but consistent (pbrt 2e §15.6): on a small closed room with indirect
// light and a caustic (a glass sphere under an area light), its error against a path-traced
// reference falls as the photon counts grow and nused / maxdist tighten.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "film/error_metrics.h"
#include "support/photon_scenes.h"
#include "support/render_scene.h"

namespace candela {
namespace {

struct Setting {
  int caustic, indirect, nused;
  float maxdist;
};

std::string photonMap(const Setting& s) {
  return "\"photonmap\" \"integer causticphotons\" [" + std::to_string(s.caustic) +
         "] \"integer indirectphotons\" [" + std::to_string(s.indirect) + "] \"integer nused\" [" +
         std::to_string(s.nused) + "] \"float maxdist\" [" + std::to_string(s.maxdist) +
         "] \"integer maxphotondepth\" [100]";
}

// Relative mean squared error of block averages of block x block pixels: averaging cuts the
// pixel noise of both images (by block^2 in variance), not the photon map's bias, which is
// smooth at that scale.
double blockRelMse(const ImageBuffer& a, const ImageBuffer& ref, int block) {
  double sum = 0;
  int n = 0;
  for (int by = 0; by + block <= a.height; by += block)
    for (int bx = 0; bx + block <= a.width; bx += block)
      for (int c = 0; c < 3; ++c) {
        double x = 0, r = 0;
        for (int y = by; y < by + block; ++y)
          for (int xx = bx; xx < bx + block; ++xx) {
            x += a.at(xx, y, c);
            r += ref.at(xx, y, c);
          }
        x /= block * block;
        r /= block * block;
        sum += (x - r) * (x - r) / (r * r + kRelMseEpsilon);
        ++n;
      }
  return sum / n;
}

std::vector<double> errors(int resolution, int referenceSpp, int spp,
                           const std::vector<Setting>& settings) {
  test::TestRenderOptions o;
  o.build.seed = 3;
  auto reference = test::renderSceneText(
      test::causticRoom(resolution, referenceSpp, "\"path\" \"integer maxdepth\" [50]"), o);
  ImageBuffer ref = reference.film().image();
  std::vector<double> e;
  for (const Setting& s : settings) {
    auto r = test::renderSceneText(test::causticRoom(resolution, spp, photonMap(s)), o);
    e.push_back(blockRelMse(r.film().image(), ref, 4));
  }
  return e;
}

// Photons 5000 -> 20000 -> 80000 (a fifth caustic), nused 100 -> 60 -> 40, maxdist 0.5 -> 0.3
// -> 0.15, against 1024 spp of path tracing, over 4 x 4 blocks. With seed 3 the block relMSE is
// 0.0105, 0.0018, 0.00084; seeds 5, 11 and 17 fall by similar factors (2 to 6 per step), so the
// order is not an accident of the noise.
TEST(PhotonMapConvergence, ErrorFallsAsPhotonsGrowAndLookupsTighten) {
  std::vector<double> e = errors(
      16, 1024, 8, {{1000, 4000, 100, 0.5f}, {4000, 16000, 60, 0.3f}, {16000, 64000, 40, 0.15f}});
  for (size_t i = 1; i < e.size(); ++i)
    EXPECT_LT(e[i], e[i - 1]) << e[0] << " " << e[1] << " " << e[2];
}

// The same at 32 x 32 against 4096 spp, over four settings up to 320,000 photons (long suite).
// Seed 3: 0.0089, 0.0014, 0.00042, 0.00030; the last step nears the reference's own noise.
TEST(LongPhotonMapConvergence, ErrorFallsOverFourSettings) {
  std::vector<double> e = errors(32, 4096, 16,
                                 {{1000, 4000, 100, 0.5f},
                                  {4000, 16000, 60, 0.3f},
                                  {16000, 64000, 40, 0.15f},
                                  {64000, 256000, 40, 0.08f}});
  for (size_t i = 1; i < e.size(); ++i)
    EXPECT_LT(e[i], e[i - 1]) << e[0] << " " << e[1] << " " << e[2] << " " << e[3];
}

}  // namespace
}  // namespace candela
