// Bidirectional and unidirectional path tracing estimate the same image: on the Cornell box
// (maxdepth 5 for both), the mean luminance of each of 16 regions (a 4 x 4 grid over the image)
// agrees between "bdpt" and "path". Each side renders independent replicates (seeds 1..n); a
// region's statistic is the Welch z of the two replicate means. Per region significance: Šidák
// 0.01 over the 16 regions under the normal approximation (with 32 replicates, 31 degrees of
// freedom per side, the Student tails make the family-wise level about 0.03). Fixed seeds. The
// normal suite's case: 16 x 16, 32 replicates of 8 spp; the Long one: 64 x 64, 64 of 64 spp.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "support/render_scene.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

std::string cornellBox(const std::string& integrator, int res, const std::string& extra = "") {
  return test::cornellBoxText(res, integrator, extra);
}

constexpr int kRegions = 4;

struct RegionStats {
  double sum[kRegions * kRegions] = {}, sumSq[kRegions * kRegions] = {};
};

RegionStats replicates(const std::string& scene, int kReplicates, int kRegionSize, int spp) {
  RegionStats st;
  for (int rep = 0; rep < kReplicates; ++rep) {
    test::TestRenderOptions o;
    o.build.sppOverride = spp;
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

void expectRegionsAgree(int res, int replicateCount, int spp, const std::string& extra = "") {
  int regionSize = res / kRegions;
  RegionStats b = replicates(cornellBox("Integrator \"bdpt\" \"integer maxdepth\" [5]", res, extra),
                             replicateCount, regionSize, spp);
  RegionStats p =
      replicates(cornellBox("SurfaceIntegrator \"path\" \"integer maxdepth\" [5]", res, extra),
                 replicateCount, regionSize, spp);
  const double n = replicateCount;
  for (int k = 0; k < kRegions * kRegions; ++k) {
    double mb = b.sum[k] / n, mp = p.sum[k] / n;
    double vb = (b.sumSq[k] - n * mb * mb) / (n - 1), vp = (p.sumSq[k] - n * mp * mp) / (n - 1);
    double z = (mb - mp) / std::sqrt(vb / n + vp / n);
    EXPECT_GT(stats::normalTwoSidedTail(z), stats::sidak(0.01, kRegions * kRegions))
        << "region " << k << ": bdpt " << mb << ", path " << mp << ", z " << z;
  }
}

TEST(BdptVsPath, CornellBoxRegionsAgree) { expectRegionsAgree(16, 32, 8); }

// Shading normals that differ from the geometric ones: light paths carry importance, whose
// adjoint BSDF needs the shading-normal correction (pbrt 3e §16.1.3). A floor patch whose vertex
// normals lean 30°.
const char* kLeaningShadingNormals =
    "AttributeBegin\nNamedMaterial \"white\"\n"
    "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
    "  \"point P\" [60 1 120  60 1 320  260 1 320  260 1 120]\n"
    "  \"normal N\" [0.5 0.866 0  0.5 0.866 0  0.5 0.866 0  0.5 0.866 0]\nAttributeEnd\n";

TEST(BdptVsPath, ShadingNormalsRegionsAgree) {
  expectRegionsAgree(16, 32, 8, kLeaningShadingNormals);
}

// The same at 64 x 64 with 64 replicates of 64 spp each: standard errors about 8x smaller.
TEST(LongBdptVsPath, CornellBoxRegionsAgree) { expectRegionsAgree(64, 64, 64); }

}  // namespace
}  // namespace candela
