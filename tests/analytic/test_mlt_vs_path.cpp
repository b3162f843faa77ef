// Metropolis and path tracing estimate the same image: on the Cornell box (maxdepth 5 for all),
// the mean luminance of each of 16 regions (a 4 x 4 grid over the image) agrees between "path"
// and each of pbrt-v3's "mlt" and pbrt-v2's Renderer "metropolis" (bidirectional and
// unidirectional, direct lighting separate and not). Each renders independent replicates (seeds
// 1..n); a region's statistic is the Welch z of the two replicate means. Per-region
// significance: Šidák 0.01 over the 16 regions under the normal approximation (with 24
// replicates, 23 degrees of freedom per side, the Student tails make the family-wise level about
// 0.04). Fixed seeds. The normal suite's case: 16 x 16, 24 replicates of 8 mutations (path: 8
// spp); the Long one: 32 x 32, 64 replicates of 64.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "support/render_scene.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

std::string cornellBox(const std::string& transport, int res) {
  std::ifstream in(std::string(CANDELA_SOURCE_DIR) + "/scenes/cornell-box/cornell-box.pbrt");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  auto replace = [&](const std::string& from, const std::string& to) {
    size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
  };
  std::string r = "[";
  r.append(std::to_string(res)).append("]");
  replace("[256]", r);
  replace("[256]", r);
  replace("SurfaceIntegrator \"path\" \"integer maxdepth\" [5]", transport);
  return s;
}

constexpr int kRegions = 4;

struct RegionStats {
  double sum[kRegions * kRegions] = {}, sumSq[kRegions * kRegions] = {};
};

// spp is --spp: the path tracer's samples and the Metropolis renderers' mutations per pixel.
RegionStats replicates(const std::string& scene, int count, int regionSize, int spp) {
  RegionStats st;
  for (int rep = 0; rep < count; ++rep) {
    test::TestRenderOptions o;
    o.build.sppOverride = spp;
    o.build.seed = uint64_t(rep + 1);
    auto r = test::renderSceneText(scene, o);
    for (int ry = 0; ry < kRegions; ++ry)
      for (int rx = 0; rx < kRegions; ++rx) {
        double m = 0;
        for (int y = 0; y < regionSize; ++y)
          for (int x = 0; x < regionSize; ++x)
            m += r.film().pixelValue(Point2i(rx * regionSize + x, ry * regionSize + y)).y();
        m /= regionSize * regionSize;
        st.sum[ry * kRegions + rx] += m;
        st.sumSq[ry * kRegions + rx] += m * m;
      }
  }
  return st;
}

void expectRegionsAgree(const std::string& transport, int res, int count, int spp) {
  SCOPED_TRACE(transport);
  int regionSize = res / kRegions;
  RegionStats m = replicates(cornellBox(transport, res), count, regionSize, spp);
  RegionStats p = replicates(cornellBox("SurfaceIntegrator \"path\" \"integer maxdepth\" [5]", res),
                             count, regionSize, spp);
  const double n = count;
  for (int k = 0; k < kRegions * kRegions; ++k) {
    double mm = m.sum[k] / n, mp = p.sum[k] / n;
    double vm = (m.sumSq[k] - n * mm * mm) / (n - 1), vp = (p.sumSq[k] - n * mp * mp) / (n - 1);
    double z = (mm - mp) / std::sqrt(vm / n + vp / n);
    EXPECT_GT(stats::normalTwoSidedTail(z), stats::sidak(0.01, kRegions * kRegions))
        << "region " << k << ": metropolis " << mm << ", path " << mp << ", z " << z;
  }
}

// Bootstrap and chain counts scaled to the image: 16 x 16 pixels need far fewer than the
// defaults (made for whole images).
std::string mlt(int bootstrap) {
  return "Integrator \"mlt\" \"integer maxdepth\" [5] \"integer chains\" [64] "
         "\"integer bootstrapsamples\" [" +
         std::to_string(bootstrap) + "]";
}
std::string metropolis(int bootstrap, const std::string& extra) {
  return "Renderer \"metropolis\" \"integer maxdepth\" [5] \"integer bootstrapsamples\" [" +
         std::to_string(bootstrap) + "] " + extra;
}

TEST(MltVsPath, CornellBoxRegionsAgree) { expectRegionsAgree(mlt(1000), 16, 24, 8); }

TEST(MetropolisVsPath, CornellBoxRegionsAgree) {
  expectRegionsAgree(metropolis(1000, ""), 16, 24, 8);
  expectRegionsAgree(
      metropolis(1000, "\"bool bidirectional\" \"false\" \"bool dodirectseparately\" \"false\""),
      16, 24, 8);
}

TEST(LongMltVsPath, CornellBoxRegionsAgree) { expectRegionsAgree(mlt(20000), 32, 64, 64); }

TEST(LongMetropolisVsPath, CornellBoxRegionsAgree) {
  for (const char* variant :
       {"", "\"bool bidirectional\" \"false\"", "\"bool dodirectseparately\" \"false\"",
        "\"bool bidirectional\" \"false\" \"bool dodirectseparately\" \"false\""})
    expectRegionsAgree(metropolis(20000, variant), 32, 64, 64);
}

}  // namespace
}  // namespace candela
