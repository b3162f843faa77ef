// MIP map pyramid and filters (lrt draft §11.5; seed inventory §24 box-downsample defect, §25
// closed forms: a constant image filters to itself, power-of-two resampling keeps the mean).
#include <gtest/gtest.h>

#include <random>

#include "textures/mipmap.h"
#include "textures/mipmap_filter.h"

using namespace candela;

namespace {

std::vector<Float> constantImage(int w, int h, Float v) {
  return std::vector<Float>(size_t(w * h), v);
}

// 0/1 checks one texel wide.
std::vector<Float> checkerImage(int w, int h) {
  std::vector<Float> img(size_t(w * h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img[size_t(y * w + x)] = Float((x + y) & 1);
  return img;
}

std::vector<Float> randomImage(int w, int h, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Float> u(0, 1);
  std::vector<Float> img(size_t(w * h));
  for (Float& v : img) v = u(rng);
  return img;
}

// A pyramid wrapper for the filter templates that records every texel read, to check that
// lookups read only near their footprint, a bounded number of times, and only valid texels.
struct RecordingPyramid {
  using Value = Float;
  const MIPMap<Float>& m;
  mutable long reads = 0;
  mutable int minS = 0, maxS = 0, minT = 0, maxT = 0, lastLevel = -1;
  int levels() const { return m.levels(); }
  int levelWidth(int l) const { return m.levelWidth(l); }
  int levelHeight(int l) const { return m.levelHeight(l); }
  WrapMode wrapMode() const { return m.wrapMode(); }
  Float texel(int level, int s, int t) const {
    EXPECT_GE(level, 0);
    EXPECT_LT(level, m.levels());
    if (reads == 0 || level != lastLevel) {
      minS = maxS = s;
      minT = maxT = t;
    }
    lastLevel = level;
    minS = std::min(minS, s), maxS = std::max(maxS, s);
    minT = std::min(minT, t), maxT = std::max(maxT, t);
    ++reads;
    return m.texel(level, s, t);
  }
};

}  // namespace

TEST(MIPMap, PyramidLevelSizes) {
  auto sizes = [](int w, int h) {
    MIPMap<Float> m(w, h, constantImage(w, h, 1), WrapMode::Repeat);
    std::vector<std::pair<int, int>> s;
    for (int l = 0; l < m.levels(); ++l) s.emplace_back(m.levelWidth(l), m.levelHeight(l));
    return s;
  };
  using V = std::vector<std::pair<int, int>>;
  EXPECT_EQ(sizes(8, 4), (V{{8, 4}, {4, 2}, {2, 1}, {1, 1}}));
  EXPECT_EQ(sizes(1, 1), (V{{1, 1}}));
  EXPECT_EQ(sizes(1, 16), (V{{1, 16}, {1, 8}, {1, 4}, {1, 2}, {1, 1}}));
  // Non-powers of two are resampled up first.
  EXPECT_EQ(sizes(5, 3), (V{{8, 4}, {4, 2}, {2, 1}, {1, 1}}));
  EXPECT_EQ(sizes(100, 1),
            (V{{128, 1}, {64, 1}, {32, 1}, {16, 1}, {8, 1}, {4, 1}, {2, 1}, {1, 1}}));
  EXPECT_THROW(MIPMap<Float>(0, 4, {}, WrapMode::Repeat), std::invalid_argument);
  EXPECT_THROW(MIPMap<Float>(2, 2, {1, 2, 3}, WrapMode::Repeat), std::invalid_argument);
}

TEST(MIPMap, BoxDownsampleUsesAllFourTexels) {
  // The draft's listing averages texel (2s+1, 2t) twice and never reads (2s+1, 2t+1): it would
  // give 0 here.
  MIPMap<Float> m(2, 2, {0, 0, 0, 4}, WrapMode::Black);
  EXPECT_EQ(m.average(), 1.f);
  // A side already 1 texel long averages only the texels that exist, in every wrap mode.
  for (WrapMode w : {WrapMode::Repeat, WrapMode::Black, WrapMode::Clamp}) {
    MIPMap<Float> row(4, 1, {1, 2, 3, 4}, w);
    EXPECT_EQ(row.texel(1, 0, 0), 1.5f);
    EXPECT_EQ(row.texel(1, 1, 0), 3.5f);
    EXPECT_EQ(row.average(), 2.5f);
  }
}

TEST(MIPMap, WrapModes) {
  MIPMap<Float> repeat(4, 2, {0, 1, 2, 3, 4, 5, 6, 7}, WrapMode::Repeat);
  EXPECT_EQ(repeat.texel(0, -1, 0), 3.f);
  EXPECT_EQ(repeat.texel(0, 5, -1), 5.f);
  EXPECT_EQ(repeat.texel(0, INT32_MIN, INT32_MAX), repeat.texel(0, 0, 1));
  MIPMap<Float> clampMode(4, 2, {0, 1, 2, 3, 4, 5, 6, 7}, WrapMode::Clamp);
  EXPECT_EQ(clampMode.texel(0, -7, 9), 4.f);
  EXPECT_EQ(clampMode.texel(0, INT32_MAX, INT32_MIN), 3.f);
  MIPMap<Float> black(4, 2, {0, 1, 2, 3, 4, 5, 6, 7}, WrapMode::Black);
  EXPECT_EQ(black.texel(0, -1, 0), 0.f);
  EXPECT_EQ(black.texel(0, 3, 1), 7.f);
  EXPECT_EQ(black.texel(0, INT32_MIN, 0), 0.f);
  EXPECT_EQ(parseWrapMode("clamp"), WrapMode::Clamp);
  EXPECT_FALSE(parseWrapMode("mirror"));
}

TEST(MIPMap, ResamplingToPowerOfTwoKeepsTheMeanAndTheRange) {
  const int w = 37, h = 29;
  std::vector<Float> img = randomImage(w, h, 3);
  double mean = 0;
  for (Float v : img) mean += v;
  mean /= img.size();
  MIPMap<Float> m(w, h, img, WrapMode::Repeat);
  EXPECT_NEAR(m.average(), mean, 0.01 * mean);
  for (int t = 0; t < m.levelHeight(0); ++t)
    for (int s = 0; s < m.levelWidth(0); ++s) {
      EXPECT_GE(m.texel(0, s, t), 0.f);
      EXPECT_LE(m.texel(0, s, t), 1.f);
    }
}

TEST(MIPMap, ConstantImageFiltersToItselfEverywhere) {
  const Float v = 0.3f;
  std::mt19937 rng(17);
  std::uniform_real_distribution<Float> pos(-3, 4), angle(0, 2 * kPi);
  for (auto [w, h] : {std::pair{16, 16}, std::pair{37, 23}, std::pair{1, 64}, std::pair{5, 1}})
    for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
      MIPMap<Float> m(w, h, constantImage(w, h, v), wrap);
      for (int l = 0; l < m.levels(); ++l)
        for (int t = 0; t < m.levelHeight(l); ++t)
          for (int s = 0; s < m.levelWidth(l); ++s) ASSERT_NEAR(m.texel(l, s, t), v, 1e-7f);
      for (Float width = 1e-7f; width < 1e3f; width *= 1.7f) {
        Point2f st(pos(rng), pos(rng));
        ASSERT_NEAR(m.lookupTrilinear(st, width), v, 1e-6f) << width;
        Float a = angle(rng);
        for (Float aspect : {1.f, 0.3f, 1e-3f, 0.f}) {
          Vector2f d0(width * std::cos(a), width * std::sin(a));
          Vector2f d1(-aspect * d0.y, aspect * d0.x);
          for (Float aniso : {1.f, 8.f, 64.f})
            ASSERT_NEAR(m.lookupEWA(st, d0, d1, aniso), v, 1e-6f)
                << w << "x" << h << " width " << width << " aspect " << aspect;
        }
      }
    }
}

TEST(MIPMap, FineCheckerboardSeenFarAwayAveragesToHalf) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<Float> pos(0, 1), angle(0, 2 * kPi);
  for (auto [w, h] : {std::pair{64, 64}, std::pair{100, 60}, std::pair{256, 32}}) {
    MIPMap<Float> m(w, h, checkerImage(w, h), WrapMode::Repeat);
    for (int i = 0; i < 200; ++i) {
      Point2f st(pos(rng), pos(rng));
      Float a = angle(rng);
      // Footprints of 10 to 60 texels, isotropic and grazing (the minor axis a hundredth).
      Float len = (10 + 50 * pos(rng)) / Float(std::min(w, h));
      Vector2f major(len * std::cos(a), len * std::sin(a));
      Vector2f iso(-major.y, major.x), grazing = iso * 0.01f;
      EXPECT_NEAR(m.lookupEWA(st, major, iso, 8), 0.5f, 0.005f) << w << "x" << h;
      EXPECT_NEAR(m.lookupEWA(st, major, grazing, 8), 0.5f, 0.005f) << w << "x" << h;
      EXPECT_NEAR(m.lookupTrilinear(st, 2 * len), 0.5f, 0.005f) << w << "x" << h;
    }
  }
}

TEST(MIPMap, TinyFootprintsReproduceTexels) {
  MIPMap<Float> m(8, 4, randomImage(8, 4, 9), WrapMode::Clamp);
  for (int t = 0; t < 4; ++t)
    for (int s = 0; s < 8; ++s) {
      Point2f centre((s + 0.5f) / 8, (t + 0.5f) / 4);
      EXPECT_FLOAT_EQ(m.lookupTrilinear(centre, 1e-6f), m.texel(0, s, t));
      EXPECT_FLOAT_EQ(m.lookupEWA(centre, Vector2f(), Vector2f(), 8), m.texel(0, s, t));
    }
  // Halfway between two texels the bilinear lookup is their mean.
  EXPECT_FLOAT_EQ(m.lookupTrilinear(Point2f(2.f / 8, 0.5f / 4), 0),
                  0.5f * (m.texel(0, 1, 0) + m.texel(0, 2, 0)));
}

TEST(MIPMap, EwaNeverReadsFarFromItsFootprintOrUnboundedly) {
  const Float inf = std::numeric_limits<Float>::infinity(), nan = std::nanf("");
  const std::vector<Float> extremes = {0,     1e-30f, 1e-7f, 0.5f, 3,  1e7f,
                                       1e30f, -1e30f, inf,   -inf, nan};
  const std::vector<Point2f> points = {{0.3f, 0.6f},  {-0.01f, 1.01f}, {1e7f, -1e7f},
                                       {1e30f, 0.5f}, {nan, 0.5f},     {0.5f, inf}};
  for (auto [w, h] : {std::pair{1, 1}, std::pair{64, 1}, std::pair{1, 32}, std::pair{33, 17},
                      std::pair{256, 256}})
    for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Black, WrapMode::Clamp}) {
      MIPMap<Float> m(w, h, randomImage(w, h, 1), wrap);
      Float lo = 1, hi = 0;
      for (int t = 0; t < m.levelHeight(0); ++t)
        for (int s = 0; s < m.levelWidth(0); ++s)
          lo = std::min(lo, m.texel(0, s, t)), hi = std::max(hi, m.texel(0, s, t));
      if (wrap == WrapMode::Black) lo = 0;
      for (Point2f st : points)
        for (Float a : extremes)
          for (Float b : extremes)
            for (Float aniso : {8.f, 64.f, 1e9f, 0.f, nan}) {
              RecordingPyramid rec{m};
              // A grazing footprint: long along (a, b), short across it.
              Float v = mipmap_filter::ewa(rec, st.x, st.y, a, b, b * 1e-6f, -a * 1e-6f, aniso);
              ASSERT_TRUE(std::isfinite(v)) << a << " " << b << " " << st.x;
              ASSERT_GE(v, lo - 1e-5f);
              ASSERT_LE(v, hi + 1e-5f);
              // At most two levels of an ellipse no longer than 2 * 64 texels (plus one).
              ASSERT_LE(rec.reads, 2L * (2 * 130 + 1) * (2 * 130 + 1));
              if (rec.lastLevel < m.levels() - 1 && std::isfinite(st.x) && std::isfinite(st.y)) {
                // Reads stay within the ellipse's box around the reduced coordinate (the top
                // level's single texel is the mean, read wherever the footprint is).
                Float s = mipmap_filter::reduceCoordinate(st.x, wrap) * m.levelWidth(rec.lastLevel);
                Float t =
                    mipmap_filter::reduceCoordinate(st.y, wrap) * m.levelHeight(rec.lastLevel);
                ASSERT_GE(rec.minS, s - 135)
                    << w << "x" << h << " level " << rec.lastLevel << " st " << st.x << " " << st.y
                    << " d " << a << " " << b << " aniso " << aniso << " wrap " << int(wrap);
                ASSERT_LE(rec.maxS, s + 135);
                ASSERT_GE(rec.minT, t - 135);
                ASSERT_LE(rec.maxT, t + 135);
              }
              RecordingPyramid tri{m};
              Float u = mipmap_filter::trilinear(tri, st.x, st.y, a);
              ASSERT_TRUE(std::isfinite(u));
              ASSERT_LE(tri.reads, 8);
            }
    }
}

TEST(MIPMap, EwaWorkIsBoundedByMaxAnisotropy) {
  MIPMap<Float> m(512, 512, randomImage(512, 512, 4), WrapMode::Repeat);
  // A long thin footprint: the eccentricity clamp moves the lookup to a coarser level, so the
  // texels read grow with maxAnisotropy, not with the footprint's length.
  for (Float aniso : {1.f, 8.f, 32.f}) {
    RecordingPyramid rec{m};
    mipmap_filter::ewa(rec, 0.5f, 0.5f, 0.5f, 0.1f, 0, 1e-6f, aniso);
    Float bound = 2 * (4 * aniso + 3) * (4 * aniso + 3);
    EXPECT_LE(rec.reads, long(bound)) << aniso;
    EXPECT_GT(rec.reads, 0);
  }
}

TEST(MIPMap, SpectrumTexels) {
  std::vector<Spectrum> img = {Spectrum(1, 0, 0), Spectrum(0, 1, 0), Spectrum(0, 0, 1),
                               Spectrum(1, 1, 1)};
  MIPMap<Spectrum> m(2, 2, img, WrapMode::Repeat);
  EXPECT_EQ(m.average(), Spectrum(0.5f, 0.5f, 0.5f));
  Spectrum far = m.lookupEWA(Point2f(0.2f, 0.7f), Vector2f(3, 0), Vector2f(0, 3), 8);
  EXPECT_EQ(far, Spectrum(0.5f, 0.5f, 0.5f));
  Spectrum near = m.lookupTrilinear(Point2f(0.25f, 0.75f), 0);
  EXPECT_EQ(near, Spectrum(0, 0, 1));
}
