// Two renderers estimate the same image: the mean luminance of each region of a 4 x 4 grid over
// the image, over independent replicate renders (seeds 1..n), compared region by region by
// Welch's t of the two replicate means, with Student's tails at the Welch-Satterthwaite degrees of
// freedom. Per-region significance: Šidák 0.01 over the 16 regions. (The normal's tails, used
// before, made the family-wise level about 0.03 at 24 replicates, when one renderer's noise
// dominates and the degrees of freedom are n - 1.) Each replicate's region mean must be close to
// normal: an estimator of infinite variance (a point light inside a scattering medium, for one)
// breaks the test however many replicates there are.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/render_scene.h"
#include "support/tail_probabilities.h"

namespace candela::test {

inline constexpr int kAgreementRegions = 4;

struct RegionReplicates {
  int count = 0;
  double sum[kAgreementRegions * kAgreementRegions] = {};
  double sumSq[kAgreementRegions * kAgreementRegions] = {};
};

// Renders scene `count` times (seeds 1..count) at --spp spp; the image must be square with a side
// that the grid divides.
inline RegionReplicates renderRegionReplicates(const std::string& scene, int count, int spp) {
  RegionReplicates st;
  st.count = count;
  for (int rep = 0; rep < count; ++rep) {
    TestRenderOptions o;
    o.build.sppOverride = spp;
    o.build.seed = uint64_t(rep + 1);
    auto r = renderSceneText(scene, o);
    const int size = r.film().fullResolution().x / kAgreementRegions;
    for (int ry = 0; ry < kAgreementRegions; ++ry)
      for (int rx = 0; rx < kAgreementRegions; ++rx) {
        double m = 0;
        for (int y = 0; y < size; ++y)
          for (int x = 0; x < size; ++x)
            m += r.film().pixelValue(Point2i(rx * size + x, ry * size + y)).y();
        m /= size * size;
        st.sum[ry * kAgreementRegions + rx] += m;
        st.sumSq[ry * kAgreementRegions + rx] += m * m;
      }
  }
  return st;
}

inline void expectRegionsAgree(const RegionReplicates& a, const std::string& nameA,
                               const RegionReplicates& b, const std::string& nameB) {
  constexpr int kCount = kAgreementRegions * kAgreementRegions;
  const double n = a.count, m = b.count;
  for (int k = 0; k < kCount; ++k) {
    double ma = a.sum[k] / n, mb = b.sum[k] / m;
    double va = (a.sumSq[k] - n * ma * ma) / (n - 1), vb = (b.sumSq[k] - m * mb * mb) / (m - 1);
    const double sa = va / n, sb = vb / m;
    const double t = (ma - mb) / std::sqrt(sa + sb);
    const double dof = (sa + sb) * (sa + sb) / (sa * sa / (n - 1) + sb * sb / (m - 1));
    EXPECT_GT(stats::studentTwoSidedTail(t, dof), stats::sidak(0.01, kCount))
        << "region " << k << ": " << nameA << " " << ma << ", " << nameB << " " << mb << ", t " << t
        << " (" << dof << " dof)";
  }
}

}  // namespace candela::test
