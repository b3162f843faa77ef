// The Halton sampler (lrt draft §7.5.2; pbrt-v2 "halton"): coordinate c of sample i of a pixel is
// the radical inverse Phi_b(i) in the c-th prime base b, its digits scrambled by random
// permutations chosen per pixel and coordinate (radical_inverse.h). The image plane takes bases 2
// and 3; the other dimensions take 5, 7, 11, ... in the order they are asked for, a 2D dimension
// two of them. pbrt-v2 spreads one Halton sequence over the whole image, which cannot be
// computed one pixel at a time; per pixel, scrambling decorrelates neighbouring pixels and the
// high bases' leading digits. Past the 1024th prime the values are independent uniform ones.
//
// A pixel's samples share its permutations: each coordinate's are made on its first use in the
// pixel, with the small table that makes its values cheap (FastScrambledRadicalInverse), and
// kept while the samples asked for are the same pixel's (the renderer takes a pixel's samples one
// after another).
#pragma once

#include <vector>

#include "samplers/radical_inverse.h"
#include "samplers/sampler.h"

namespace candela {

class HaltonSampler final : public Sampler {
 public:
  HaltonSampler(int samplesPerPixel, uint64_t seed);
  int samplesPerPixel() const override { return samplesPerPixel_; }
  std::unique_ptr<Sampler> clone() const override;
  void startPixelSample(const Point2i& pixel, int sampleIndex) override;
  Float get1D() override {
    uint64_t c = coordinate_++;
    return c < fastEnd_ ? tabulatedValue(c) : slowValue(c);
  }
  Point2f get2D() override {
    uint64_t c = coordinate_;
    coordinate_ += 2;
    return pair(c);
  }
  Point2f getPixel2D() override { return pair(0); }
  // The coordinates passed over without being computed (their values do not depend on whether
  // they were computed).
  void skip1D() override { ++coordinate_; }
  void skip2D() override { coordinate_ += 2; }

  // The key of the digit permutations of one coordinate in one pixel: coordinate c of sample i
  // there is scrambledRadicalInverse(i, kPrimes[c], coordinateKey(pixel, c, seed)).
  static uint64_t coordinateKey(const Point2i& pixel, uint64_t coordinate, uint64_t seed);

 private:
  struct Coordinate {
    FastScrambledRadicalInverse inverse;
    uint32_t tableOffset = 0;  // where its table starts in tables_
  };

  HaltonSampler(int samplesPerPixel, uint64_t seed,
                std::shared_ptr<const std::vector<Coordinate>> prototype);

  // Coordinates c and c + 1; the slow path out of line, so that the fast one needs no frame.
  Point2f pair(uint64_t c) {
    if (c + 1 < fastEnd_) return Point2f(tabulatedValue(c), tabulatedValue(c + 1));
    return slowPair(c);
  }
  Point2f slowPair(uint64_t c);
  // The value of a coordinate below fastEnd_: keyed for this pixel, the sample index tabulated.
  Float tabulatedValue(uint64_t coordinate) const {
    const Coordinate& c = coordinates_[coordinate];
    return c.inverse.tabulatedValue(sampleIndex_, &tables_[c.tableOffset]);
  }
  // Any other: keys the coordinates up to it, or past the prime table a random value.
  Float slowValue(uint64_t coordinate);
  Float randomValue(uint64_t coordinate) const;

  int samplesPerPixel_;
  uint64_t seed_;
  // The coordinates before any key is set, shared by the clones.
  std::shared_ptr<const std::vector<Coordinate>> prototype_;
  Point2i pixel_;
  bool started_ = false;  // a pixel sample was started
  uint32_t sampleIndex_ = 0;
  uint64_t coordinate_ = 2;  // the next coordinate after the image plane's two
  // A pixel's samples ask for coordinates 0, 1, 2, ... in order, so the ones keyed for the
  // current pixel are always the first keyedEnd_; fastEnd_ is keyedEnd_ while the sample index
  // is below the tables' count, else 0 (one comparison decides the fast path).
  uint64_t keyedEnd_ = 0, fastEnd_ = 0;
  uint64_t pixelKey_ = 0;  // the current pixel's, from which its coordinates' keys derive
  std::vector<Coordinate> coordinates_;  // one per prime base
  std::vector<uint64_t> tables_;         // the coordinates' tables
};

// getCameraSample with the sampler's values called directly, not through virtual calls.
CameraSample getCameraSample(HaltonSampler& sampler, const Point2i& pixel, const Filter& filter,
                             bool lens = true);

}  // namespace candela
