// Samplers change the noise of an image, never what it converges to: the Cornell box path traced
// at depth 8 with a box filter (the render benchmark's case) has, region by region, the same
// mean with the scrambled Halton sampler as with independent random samples. Each side renders
// independent replicates (seeds 1..n); a region's statistic is the Welch z of the two replicate
// means, Šidák 0.01 over the 16 regions (support/region_agreement.h). Fixed seeds. The normal
// suite: 16 x 16, 32 replicates of 16 spp; the Long one: 64 x 64, 32 of 64 spp.
#include <gtest/gtest.h>

#include <string>

#include "support/region_agreement.h"

namespace candela {
namespace {

std::string cornellBoxWith(const std::string& sampler, int resolution) {
  return test::cornellBoxText(resolution,
                              "Sampler \"" + sampler +
                                  "\"\nPixelFilter \"box\"\n"
                                  "SurfaceIntegrator \"path\" \"integer maxdepth\" [8]");
}

void expectHaltonAgreesWithRandom(int resolution, int replicates, int spp) {
  test::expectRegionsAgree(
      test::renderRegionReplicates(cornellBoxWith("halton", resolution), replicates, spp), "halton",
      test::renderRegionReplicates(cornellBoxWith("random", resolution), replicates, spp),
      "random");
}

TEST(SamplerAgreement, HaltonAndRandomCornellBoxRegionsAgree) {
  expectHaltonAgreesWithRandom(16, 32, 16);
}

TEST(LongSamplerAgreement, HaltonAndRandomCornellBoxRegionsAgree) {
  expectHaltonAgreesWithRandom(64, 32, 64);
}

}  // namespace
}  // namespace candela
