#include "support/reference_agreement.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace candela::test {

double fSurvival(double x, double d1, double d2) {
  if (!(x > 0)) return 1;
  if (std::isinf(x)) return 0;
  const double a = 2 / (9 * d1), b = 2 / (9 * d2);
  const double cube = std::cbrt(x);
  const double z = ((1 - b) * cube - (1 - a)) / std::sqrt(a + cube * cube * b);
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

namespace {

// Half of a half float's spacing at r (10 fraction bits): how far the value stored for r can lie
// from r.
double halfRoundingBound(double r) {
  r = std::abs(r);
  if (r < 6.103515625e-05) return std::ldexp(1.0, -25);  // subnormal halves: spacing 2^-24
  return std::ldexp(1.0, std::ilogb(r) - 11);
}

// The mean of one channel over a block.
double blockMean(const ImageBuffer& image, int bx, int by, int block, int c) {
  double sum = 0;
  for (int y = by * block; y < (by + 1) * block; ++y)
    for (int x = bx * block; x < (bx + 1) * block; ++x) sum += image.at(x, y, c);
  return sum / (block * block);
}

// How far a block mean of half floats can lie from the mean of the values they round: the mean
// of the bounds (the roundings may all go the same way, as they do over a flat colour).
double blockRoundingBound(const ImageBuffer& image, int bx, int by, int block, int c) {
  double sum = 0;
  for (int y = by * block; y < (by + 1) * block; ++y)
    for (int x = bx * block; x < (bx + 1) * block; ++x) sum += halfRoundingBound(image.at(x, y, c));
  return sum / (double(block) * block);
}

}  // namespace

const ReferenceRegion& ReferenceAgreement::worst() const {
  if (regions.empty()) throw std::logic_error("no regions compared");
  return *std::min_element(regions.begin(), regions.end(),
                           [](const auto& x, const auto& y) { return x.pValue < y.pValue; });
}

std::string ReferenceAgreement::describe(const ReferenceRegion& r) const {
  std::ostringstream s;
  s << "region (" << r.regionX << ", " << r.regionY << ") channel "
    << "RGB"[r.channel] << ": render mean " << r.renderMean << ", reference mean "
    << r.referenceMean << ", F " << r.ratio << " with (" << r.degreesOfFreedom << ", "
    << r.denominatorDegreesOfFreedom << ") degrees of freedom, p " << r.pValue
    << " (whole image: mean ratio " << meanRatio << ", relMSE " << relMse << ")";
  return s.str();
}

ReferenceAgreement compareWithReference(const std::vector<const ImageBuffer*>& renders,
                                        const ImageBuffer& reference,
                                        const ReferenceAgreementOptions& o) {
  if (renders.size() < 2) throw std::invalid_argument("at least two renders are needed");
  std::vector<const ImageBuffer*> images = renders;
  images.push_back(&reference);
  for (const ImageBuffer* image : images)
    if (image->width != reference.width || image->height != reference.height ||
        image->channelCount() < 3)
      throw std::invalid_argument("images of different sizes or without RGB");
  if (o.samplesPerPixel <= 0 || o.referenceSamplesPerPixel <= 0 || o.block <= 0 || o.regions <= 0 ||
      reference.width % o.block || reference.height % o.block)
    throw std::invalid_argument("bad comparison options");
  const int blocksX = reference.width / o.block, blocksY = reference.height / o.block;
  if (blocksX % o.regions || blocksY % o.regions)
    throw std::invalid_argument("the region grid does not divide the blocks");
  const int perRegionX = blocksX / o.regions, perRegionY = blocksY / o.regions;
  const double referenceShare = 1 + 2.0 * o.samplesPerPixel / o.referenceSamplesPerPixel;
  const int k = int(renders.size());
  std::vector<double> means(k);

  ReferenceAgreement out;
  double sumRender = 0, sumReference = 0, sumRel = 0;
  long comparedBlocks = 0;
  for (int ry = 0; ry < o.regions; ++ry)
    for (int rx = 0; rx < o.regions; ++rx)
      for (int c = 0; c < 3; ++c) {
        ReferenceRegion region;
        region.regionX = rx;
        region.regionY = ry;
        region.channel = c;
        double numerator = 0, denominator = 0, noiseSquares = 0;
        int blocks = 0;
        for (int by = ry * perRegionY; by < (ry + 1) * perRegionY; ++by)
          for (int bx = rx * perRegionX; bx < (rx + 1) * perRegionX; ++bx) {
            if (o.excludedBlocks.count({bx, by})) continue;
            ++blocks;
            double m = 0;
            for (int i = 0; i < k; ++i) m += means[i] = blockMean(*renders[i], bx, by, o.block, c);
            m /= k;
            double squares = 0;
            for (double mi : means) squares += (mi - m) * (mi - m);
            // The sample variance over K: the variance of m.
            const double noise = squares / (double(k - 1) * k) * referenceShare;
            const double r = blockMean(reference, bx, by, o.block, c);
            // The reference's rounding to its storage is not noise: a difference within it is
            // none.
            const double rounding =
                o.referenceIsHalf ? blockRoundingBound(reference, bx, by, o.block, c) : 0;
            const double beyond = std::max(0.0, std::abs(m - r) - rounding);
            numerator += beyond * beyond;
            denominator += noise;
            noiseSquares += noise * noise;
            region.renderMean += m;
            region.referenceMean += r;
            sumRel += (m - r) * (m - r) / (r * r + 1e-2);
          }
        comparedBlocks += blocks;
        if (blocks == 0) throw std::invalid_argument("every block of a region is excluded");
        region.renderMean /= blocks;
        region.referenceMean /= blocks;
        sumRender += region.renderMean;
        sumReference += region.referenceMean;
        // Light that few samples find (a blurred edge reaching into the sky) can be missed by both
        // renders and leave no noise to measure: differences below the resolution are not counted.
        const double floor = o.resolution * std::abs(region.referenceMean);
        denominator += blocks * floor * floor;
        if (denominator <= 0) {
          region.ratio = numerator > 0 ? INFINITY : 0;
          region.degreesOfFreedom = blocks;
          region.denominatorDegreesOfFreedom = double(k - 1) * blocks;
        } else {
          region.ratio = numerator / denominator;
          // The numerator is a sum of v chi-squares with one degree of freedom each, the
          // denominator of v chi-squares with K - 1 each, scaled by 1 / (K - 1), v unknown.
          // Satterthwaite's nu = 2 E^2 / Var: (sum v)^2 / sum v^2 for the numerator, K - 1 times
          // that for the denominator; and E d^2 = v^2 (K + 1) / (K - 1) estimates sum v^2.
          region.degreesOfFreedom =
              noiseSquares > 0 ? std::min<double>(blocks, double(k + 1) / (k - 1) * denominator *
                                                              denominator / noiseSquares)
                               : blocks;
          region.degreesOfFreedom = std::max(region.degreesOfFreedom, 1.0);
          region.denominatorDegreesOfFreedom = double(k - 1) * region.degreesOfFreedom;
        }
        region.pValue =
            fSurvival(region.ratio, region.degreesOfFreedom, region.denominatorDegreesOfFreedom);
        out.regions.push_back(region);
      }
  out.meanRatio = sumReference > 0 ? sumRender / sumReference : 0;
  out.relMse = sumRel / double(comparedBlocks);
  return out;
}

}  // namespace candela::test
