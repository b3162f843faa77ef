// Does a render agree with a reference image made by another renderer with many more samples?
// The tolerance comes from the render's own noise, measured by rendering K >= 2 times with
// different seeds: per block of block x block pixels and per channel, the K block means' sample
// variance over K estimates the variance of their mean m without bias, with K - 1 degrees of
// freedom (K = 2: (a - b)^2 / 4). The reference's own noise adds a share n / N of the per-render
// variance (n, N samples per pixel); differences within the rounding of the reference's storage
// (half floats) are not counted. Over each region of a regions x regions grid, per channel,
//   F = sum (|m - r| - rounding)+^2 / (sum d (1 + 2n/N) + blocks (resolution mean r)^2)
// is a ratio of two sums with the same expectation when the renders agree: an F ratio whose
// degrees of freedom are Satterthwaite's estimates from the blocks' variances (fewer than the
// block count where a few noisy blocks dominate; the denominator's K - 1 times the numerator's).
// Its upper tail comes from Paulson's normal approximation of the F distribution (Johnson, Kotz &
// Balakrishnan, Continuous Univariate Distributions vol. 2, ch. 27).
//
// With K = 2 each block's variance estimate is one chi-square degree of freedom: a quarter of them
// fall below a tenth of the true variance, and where one block carries most of a region's noise
// the test's nominal level is not its real one. Four renders (three degrees of freedom per block)
// make that rare, and their mean has half the noise of two, which finds smaller biases.
#pragma once

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/image_buffer.h"

namespace candela::test {

struct ReferenceRegion {
  int regionX = 0, regionY = 0, channel = 0;
  double ratio = 0;                        // F
  double degreesOfFreedom = 0;             // Satterthwaite's, the numerator's
  double denominatorDegreesOfFreedom = 0;  // (K - 1) times the numerator's
  double pValue = 1;                       // P(F >= ratio) if render and reference agree
  double renderMean = 0, referenceMean = 0;
};

struct ReferenceAgreement {
  std::vector<ReferenceRegion> regions;
  double meanRatio = 0;  // mean of (a + b) / 2 over mean of the reference, all channels
  // mean over blocks and channels of (m - r)^2 / (r^2 + 1e-2) after the block downsample
  double relMse = 0;
  // The smallest p-value and where it is.
  const ReferenceRegion& worst() const;
  std::string describe(const ReferenceRegion& region) const;
};

struct ReferenceAgreementOptions {
  int samplesPerPixel = 0;           // of each of a and b
  int referenceSamplesPerPixel = 0;  // of the reference
  int block = 4;
  int regions = 4;
  // Block differences well below this fraction of the region's mean are not resolved: rare light
  // that both renders missed leaves no noise to measure (see compareWithReference).
  double resolution = 1e-3;
  bool referenceIsHalf = true;  // stored as half floats: ignore differences within their rounding
  // Blocks (x, y on the block grid) left out of their regions: a known difference confined to a
  // few pixels, whose regions are still compared over the rest of their blocks.
  std::set<std::pair<int, int>> excludedBlocks;
};

// renders (at least two, each with its own seed) and reference: the same size, at least 3 channels
// (the first three, R G B, are compared); the block size must divide the image size and the region
// count the block grid.
ReferenceAgreement compareWithReference(const std::vector<const ImageBuffer*>& renders,
                                        const ImageBuffer& reference,
                                        const ReferenceAgreementOptions& options);

inline ReferenceAgreement compareWithReference(const ImageBuffer& a, const ImageBuffer& b,
                                               const ImageBuffer& reference,
                                               const ReferenceAgreementOptions& options) {
  return compareWithReference({&a, &b}, reference, options);
}

// Upper tail of the F distribution with (d1, d2) degrees of freedom at x (Paulson's
// approximation; accurate to a few per cent of the tail probability for d1, d2 >= 10).
double fSurvival(double x, double d1, double d2);

}  // namespace candela::test
