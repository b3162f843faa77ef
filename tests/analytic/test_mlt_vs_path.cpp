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

#include <string>

#include "support/region_agreement.h"
#include "support/render_scene.h"

namespace candela {
namespace {

void expectRegionsAgree(const std::string& transport, int res, int count, int spp) {
  SCOPED_TRACE(transport);
  test::expectRegionsAgree(
      test::renderRegionReplicates(test::cornellBoxText(res, transport), count, spp), "metropolis",
      test::renderRegionReplicates(
          test::cornellBoxText(res, "SurfaceIntegrator \"path\" \"integer maxdepth\" [5]"), count,
          spp),
      "path");
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
