// Bidirectional and unidirectional path tracing estimate the same image: on the Cornell box
// (maxdepth 5 for both), the mean luminance of each of 16 regions (4 x 4 pixels of a 16 x 16
// image) agrees between "bdpt" and "path". Each side renders 32 independent replicates (seeds
// 1..32, 8 spp each); a region's statistic is the Welch z of the two replicate means. Per region
// significance: Šidák 0.01 over the 16 regions under the normal approximation (with 31 degrees of
// freedom per side the Student tails make the family-wise level about 0.03). Fixed seeds.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "support/render_scene.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

std::string cornellBox(const std::string& integrator) {
  std::ifstream in(std::string(CANDELA_SOURCE_DIR) + "/scenes/cornell-box/cornell-box.pbrt");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  auto replace = [&](const std::string& from, const std::string& to) {
    size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
  };
  replace("[256]", "[16]");
  replace("[256]", "[16]");
  replace("SurfaceIntegrator \"path\" \"integer maxdepth\" [5]", integrator);
  return s;
}

constexpr int kReplicates = 32, kRegions = 4, kRegionSize = 4;

struct RegionStats {
  double sum[kRegions * kRegions] = {}, sumSq[kRegions * kRegions] = {};
};

RegionStats replicates(const std::string& scene) {
  RegionStats st;
  for (int rep = 0; rep < kReplicates; ++rep) {
    test::TestRenderOptions o;
    o.build.sppOverride = 8;
    o.build.seed = uint64_t(rep + 1);
    auto r = test::renderSceneText(scene, o);
    for (int ry = 0; ry < kRegions; ++ry)
      for (int rx = 0; rx < kRegions; ++rx) {
        double m = 0;
        for (int y = 0; y < kRegionSize; ++y)
          for (int x = 0; x < kRegionSize; ++x)
            m += r.film().pixelValue(Point2i(rx * kRegionSize + x, ry * kRegionSize + y)).y();
        m /= kRegionSize * kRegionSize;
        st.sum[ry * kRegions + rx] += m;
        st.sumSq[ry * kRegions + rx] += m * m;
      }
  }
  return st;
}

TEST(BdptVsPath, CornellBoxRegionsAgree) {
  RegionStats b = replicates(cornellBox("Integrator \"bdpt\" \"integer maxdepth\" [5]"));
  RegionStats p = replicates(cornellBox("SurfaceIntegrator \"path\" \"integer maxdepth\" [5]"));
  const double n = kReplicates;
  for (int k = 0; k < kRegions * kRegions; ++k) {
    double mb = b.sum[k] / n, mp = p.sum[k] / n;
    double vb = (b.sumSq[k] - n * mb * mb) / (n - 1), vp = (p.sumSq[k] - n * mp * mp) / (n - 1);
    double z = (mb - mp) / std::sqrt(vb / n + vp / n);
    EXPECT_GT(stats::normalTwoSidedTail(z), stats::sidak(0.01, kRegions * kRegions))
        << "region " << k << ": bdpt " << mb << ", path " << mp << ", z " << z;
  }
}

}  // namespace
}  // namespace candela
