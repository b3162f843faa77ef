// Stochastic progressive photon mapping (Hachisuka & Jensen 2009; pbrt 3e §16.2) against closed
// forms: the furnace, a point light mirrored onto a diffuse floor (a caustic only photons carry),
// and a glass-sphere caustic against a bidirectional reference. SPPM is consistent: its error
// must fall as iterations grow.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/render_scene.h"

namespace candela {
namespace {

std::string sppm(int iterations, const std::string& extra) {
  return "Integrator \"sppm\" \"integer numiterations\" [" + std::to_string(iterations) + "] " +
         extra + "\n";
}

// Inside a closed sphere of Lambertian albedo 0.5 emitting Le = 0.5, L = Le / (1 - rho) = 1
// (lrt draft §16.2). A ball of radius r around a point on the sphere cuts a cap of area pi r^2
// exactly (Archimedes), so the density estimate has no curvature bias. maxdepth 20 truncates the
// series at 0.5^20 (1e-6).
std::string furnace(int iterations) {
  return "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" [60]\n"
         "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16]\n" +
         sppm(iterations, "\"float radius\" [0.2] \"integer maxdepth\" [20]") +
         "WorldBegin\nAreaLightSource \"diffuse\" \"rgb L\" [0.5 0.5 0.5]\n"
         "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\nReverseOrientation\n"
         "Shape \"sphere\" \"float radius\" [1]\nWorldEnd\n";
}

struct FurnaceError {
  double rms = 0, mean = 0;  // relative to 1: per pixel, and of the image mean
};

FurnaceError furnaceError(int iterations, uint64_t seed) {
  test::TestRenderOptions o;
  o.build.seed = seed;
  auto r = test::renderSceneText(furnace(iterations), o);
  const Film& film = r.film();
  Bounds2i b = film.pixelBounds();
  double sq = 0, sum = 0;
  int n = 0;
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) {
      double v = film.pixelValue(Point2i(x, y)).y();
      sq += (v - 1) * (v - 1);
      sum += v;
      ++n;
    }
  return {std::sqrt(sq / n), std::abs(sum / n - 1)};
}

// Error of a consistent SPPM estimate falls as N^-1/3 with alpha = 2/3 (Hachisuka & Jensen 2009
// §4.4): at 4, 16, 64, 256 iterations the per-pixel RMS error times N^(1/3) measured 0.16 to 0.17
// for seeds 1, 2, 3. The bound 0.25 N^-1/3 (1.5 times that) shrinks with the iterations; the
// image mean (a looser check: the pixels share photons) must keep within it too.
TEST(SppmFurnace, ErrorFallsWithIterations) {
  for (uint64_t seed : {1, 2, 3}) {
    SCOPED_TRACE(seed);
    double previous = 1e30;
    for (int it : {4, 16, 64, 256}) {
      FurnaceError e = furnaceError(it, seed);
      double bound = 0.25 / std::cbrt(double(it));
      EXPECT_LT(e.rms, bound) << it << " iterations";
      EXPECT_LT(e.mean, bound) << it << " iterations";
      EXPECT_LT(e.rms, previous) << it << " iterations";
      previous = e.rms;
    }
  }
}

// A point light of intensity I at height 1 over a matte floor (albedo 0.5, y = 0) under a mirror
// ceiling at height 2, seen from above by an orthographic camera covering [-1, 1]^2 of the floor.
// With maxdepth 2 the floor receives the light directly (by light sampling) and once by the
// mirror, as from the light's image at height 3 (by photons only: a point light seen in a mirror
// cannot be sampled): L = rho / pi * I (1 / d1^3 + 3 / d2^3), d1^2 = s^2 + 1, d2^2 = s^2 + 9 at
// horizontal distance s from below the light.
constexpr double kMirrorI = 10, kMirrorRho = 0.5;

std::string mirroredPointLight(int iterations, int resolution, const std::string& radius = "0.1",
                               int photons = 20000) {
  return "LookAt 0 1.5 0  0 0 0  0 0 1\nCamera \"orthographic\"\n"
         "Film \"image\" \"integer xresolution\" [" +
         std::to_string(resolution) + "] \"integer yresolution\" [" + std::to_string(resolution) +
         "]\n" +
         sppm(iterations, "\"float radius\" [" + radius +
                              "] \"integer maxdepth\" [2] \"integer photonsperiteration\" [" +
                              std::to_string(photons) + "]") +
         "WorldBegin\nLightSource \"point\" \"point from\" [0 1 0] \"rgb I\" [10 10 10]\n"
         "AttributeBegin\nMaterial \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" "
         "[-100 0 -100  100 0 -100  100 0 100  -100 0 100]\nAttributeEnd\n"
         "AttributeBegin\nMaterial \"mirror\" \"rgb Kr\" [1 1 1]\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" "
         "[-100 2 -100  100 2 -100  100 2 100  -100 2 100]\nAttributeEnd\nWorldEnd\n";
}

// The two terms of the closed form: direct, and by the mirror.
double directRadiance(double x, double z) {
  double d = std::sqrt(x * x + z * z + 1);
  return kMirrorRho / kPi * kMirrorI / (d * d * d);
}
double mirroredRadiance(double x, double z) {
  double d = std::sqrt(x * x + z * z + 9);
  return kMirrorRho / kPi * kMirrorI * 3 / (d * d * d);
}

// RMS error of block means (block x block pixels) against the closed form integrated over the
// same blocks (8 x 8 points a pixel), relative to the mirrored term: the part photons carry.
double mirrorBlockError(int iterations, uint64_t seed, const std::string& radius = "0.1",
                        int photons = 20000) {
  const int res = 16, block = 4;
  test::TestRenderOptions o;
  o.build.seed = seed;
  auto r = test::renderSceneText(mirroredPointLight(iterations, res, radius, photons), o);
  const Film& film = r.film();
  double sq = 0;
  int n = 0;
  for (int by = 0; by < res; by += block)
    for (int bx = 0; bx < res; bx += block) {
      double got = 0, want = 0, mirrored = 0;
      for (int y = by; y < by + block; ++y)
        for (int x = bx; x < bx + block; ++x) {
          got += film.pixelValue(Point2i(x, y)).y();
          for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) {
              // Raster (x, y) to the floor: the screen window [-1, 1]^2, x to one side, y down.
              double u = -1 + 2 * (x + (i + 0.5) / 8) / res, v = 1 - 2 * (y + (j + 0.5) / 8) / res;
              want += (directRadiance(u, v) + mirroredRadiance(u, v)) / 64;
              mirrored += mirroredRadiance(u, v) / 64;
            }
        }
      sq += (got - want) * (got - want) / (mirrored * mirrored);
      ++n;
    }
  return std::sqrt(sq / n);
}

// Seeds 1, 2, 3 at 1, 8, 64 iterations measured 0.076-0.083, 0.037-0.040, 0.015-0.021: about
// 0.08 N^-1/3. The bound 0.13 N^-1/3 (1.5 times that) shrinks with the iterations.
TEST(SppmMirroredPointLight, BlockMeansApproachTheClosedForm) {
  for (uint64_t seed : {1, 2, 3}) {
    SCOPED_TRACE(seed);
    double previous = 1e30;
    for (int it : {1, 8, 64}) {
      double e = mirrorBlockError(it, seed);
      EXPECT_LT(e, 0.13 / std::cbrt(double(it))) << it << " iterations";
      EXPECT_LT(e, previous) << it << " iterations";
      previous = e;
    }
  }
}

// A search radius of 1 (the scale on which the mirrored term varies) blurs it: the bias must
// fall as the radius shrinks. Seeds 1, 2, 3 at 1, 16, 256 iterations of 2000 photons measured
// 0.08-0.10, 0.027-0.029, 0.011-0.013; with the radius held fixed (alpha = 1) the error stays at
// the bias, 0.06 from 16 iterations on, so 0.025 at 256 tells the two apart.
TEST(SppmMirroredPointLight, BiasFallsAsTheRadiusShrinks) {
  for (uint64_t seed : {1, 2, 3}) {
    SCOPED_TRACE(seed);
    double previous = 1e30;
    for (int it : {1, 16, 256}) {
      double e = mirrorBlockError(it, seed, "1", 2000);
      EXPECT_LT(e, previous) << it << " iterations";
      previous = e;
    }
    EXPECT_LT(previous, 0.025);
  }
}

// A glass sphere (radius 0.5, centre at height 1.2) under a point light at height 3 focuses a
// caustic onto a matte floor, seen from below the sphere (a camera 0.6 over the floor) (so no
// camera path passes through the glass, which bidirectional path tracing cannot connect to a point
// light). Photons bring the caustic; the reference is bdpt's light tracing.
std::string glassCaustic(const std::string& integrator, int spp) {
  return "LookAt 0 0.6 0  0 0 0  0 0 1\nCamera \"perspective\" \"float fov\" [90]\n"
         "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16]\n"
         "Sampler \"random\" \"integer pixelsamples\" [" +
         std::to_string(spp) + "]\n" + integrator +
         "\nWorldBegin\nLightSource \"point\" \"point from\" [0 3 0] \"rgb I\" [10 10 10]\n"
         "AttributeBegin\nMaterial \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" "
         "[-100 0 -100  100 0 -100  100 0 100  -100 0 100]\nAttributeEnd\n"
         "AttributeBegin\nMaterial \"glass\"\nTranslate 0 1.2 0\n"
         "Shape \"sphere\" \"float radius\" [0.5]\nAttributeEnd\nWorldEnd\n";
}

std::vector<double> blockMeans(const Film& film, int block) {
  Bounds2i b = film.pixelBounds();
  std::vector<double> means;
  for (int by = b.pMin.y; by + block <= b.pMax.y; by += block)
    for (int bx = b.pMin.x; bx + block <= b.pMax.x; bx += block) {
      double s = 0;
      for (int y = by; y < by + block; ++y)
        for (int x = bx; x < bx + block; ++x) s += film.pixelValue(Point2i(x, y)).y();
      means.push_back(s / (block * block));
    }
  return means;
}

// The caustic (the central 8 x 8 pixels) and the ring around it: their mean radiances.
std::vector<double> regionMeans(const Film& film) {
  std::vector<double> blocks = blockMeans(film, 4);
  double centre = 0, ring = 0;
  for (int i = 0; i < 16; ++i) {
    bool inner = (i / 4 == 1 || i / 4 == 2) && (i % 4 == 1 || i % 4 == 2);
    (inner ? centre : ring) += blocks[size_t(i)];
  }
  return {centre / 4, ring / 12};
}

double worstRelative(const std::vector<double>& a, const std::vector<double>& ref) {
  double w = 0;
  for (size_t i = 0; i < a.size(); ++i) w = std::max(w, std::abs(a[i] / ref[i] - 1));
  return w;
}

const char* kBdpt = "Integrator \"bdpt\" \"integer maxdepth\" [12]";

std::vector<double> sppmCausticErrors(const std::vector<double>& ref, uint64_t seed,
                                      const std::vector<int>& iterations) {
  test::TestRenderOptions o;
  o.build.seed = seed;
  std::vector<double> e;
  for (int it : iterations) {
    auto r =
        test::renderSceneText(glassCaustic(sppm(it,
                                                "\"float radius\" [0.1] \"integer maxdepth\" [12] "
                                                "\"integer photonsperiteration\" [20000]"),
                                           1),
                              o);
    e.push_back(worstRelative(regionMeans(r.film()), ref));
  }
  return e;
}

// Against 8192 spp of bdpt (whose ring differs by 2.6% between seeds 7 and 8). Photons and
// camera paths that pick the sphere's reflection or refraction by Fresnel carry their weight
// through it unchanged, so one iteration is already within 2-7% (seeds 1, 2, 3; it was 17-40%
// when the picks were half and half, against 2048 spp of bdpt) and the fall is measured in the
// mean over the three seeds, from one iteration (0.052) to 64 (0.013; each seed 0.009-0.017).
// Held: the mean falls, and every seed's error at 64 iterations is below 5%.
TEST(SppmGlassCaustic, RegionMeansApproachABidirectionalReference) {
  test::TestRenderOptions o;
  o.build.seed = 7;
  std::vector<double> ref = regionMeans(test::renderSceneText(glassCaustic(kBdpt, 8192), o).film());
  double first = 0, last = 0;
  for (uint64_t seed : {1, 2, 3}) {
    std::vector<double> e = sppmCausticErrors(ref, seed, {1, 64});
    first += e[0] / 3;
    last += e[1] / 3;
    EXPECT_LT(e[1], 0.05) << "seed " << seed;
  }
  EXPECT_LT(last, first);
}

// Against 32768 spp of bdpt (reference noise about 1%), four settings to 512 iterations.
TEST(LongSppmGlassCaustic, RegionMeansApproachABidirectionalReference) {
  test::TestRenderOptions o;
  o.build.seed = 7;
  std::vector<double> ref =
      regionMeans(test::renderSceneText(glassCaustic(kBdpt, 32768), o).film());
  std::vector<double> e = sppmCausticErrors(ref, 1, {1, 8, 64, 512});
  std::printf("long caustic errors %g %g %g %g\n", e[0], e[1], e[2], e[3]);
  for (size_t i = 1; i < e.size(); ++i) EXPECT_LT(e[i], e[i - 1]) << i;
  EXPECT_LT(e.back(), 0.03);
}

}  // namespace
}  // namespace candela
