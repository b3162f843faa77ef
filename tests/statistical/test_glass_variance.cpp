// Error per sample through glass (issue 33): the per-pixel variance of the integrators that see
// a dielectric is held against what their estimators should give, not only their means.
//
// The bound. Where every path a pixel's samples can take ends at an emitter of radiance M with a
// throughput of at most 1 (a specular chain whose picks each weigh their tint, 1 here, times
// radiance scalings that cancel once the path is out of the glass), every sample lies in [0, M],
// and no set of n such values with mean m spreads more than n m (M - m) (the Bhatia-Davis
// inequality, exact for the two values 0 and M). Film::pixelVariance is that spread over
// n (n - 1), so pixelVariance (n - 1) <= m (M - m) holds for every pixel and every seed, with no
// false alarms: a violation means a sample above M, which half-and-half picks between reflection
// and refraction give (weights 2F and 2(1 - F): 3.7 M through a sphere, the fireflies of the
// Cornell box with a glass sphere). The scenes:
//   - a glass sphere before a large emitter (camera paths only: specular chains to L or to black);
//   - a diffuse floor (albedo rho) under a glass sphere below a small emitter: in the sphere's
//     umbra, where shadow rays and direct hits are blocked, all light is the caustic, rho L per
//     path that reaches the emitter;
//   - the same under a glass slab (a box: refraction through both faces, total internal
//     reflection at its sides).
// Rough glass has next-event estimation at its vertices, so its samples are not bounded so
// simply; there the pooled spread over the sphere's pixels is held to the same bound summed over
// them (its microfacet samples weigh at most 1), which half-and-half picks exceed 4-37 times.
// Integrators that do not keep per-pixel sample sums (sppm) are measured across seeds instead.
// Finally the Cornell box with a glass sphere against a reference and pbrt-v3's figures (path,
// volpath and mlt): relMSE, and the share of it in the worst 1% of the pixels, which fireflies
// drive up.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "film/error_metrics.h"
#include "support/render_scene.h"

namespace candela {
namespace {

std::string header(int res, int spp, const std::string& sampler, const std::string& camera,
                   const std::string& integrator, int fov = 30) {
  return camera + "Camera \"perspective\" \"float fov\" [" + std::to_string(fov) + "]\n" +
         "Film \"image\" \"integer xresolution\" [" + std::to_string(res) +
         "] \"integer yresolution\" [" + std::to_string(res) + "]\n" + "PixelFilter \"box\"\n" +
         "Sampler \"" + sampler + "\" \"integer pixelsamples\" [" + std::to_string(spp) + "]\n" +
         integrator + "\n";
}

// A quad in the plane y = height (normal -y: it faces down), half-size h, emitting L.
std::string ceilingLight(double height, double h, double L) {
  auto s = [](double v) { return std::to_string(v); };
  return "AttributeBegin\n  Material \"matte\" \"rgb Kd\" [0 0 0]\n  AreaLightSource \"diffuse\" "
         "\"rgb L\" [" +
         s(L) + " " + s(L) + " " + s(L) +
         "]\n"
         "  Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [" +
         s(-h) + " " + s(height) + " " + s(-h) + "  " + s(h) + " " + s(height) + " " + s(-h) +
         "  " + s(h) + " " + s(height) + " " + s(h) + "  " + s(-h) + " " + s(height) + " " + s(h) +
         "]\nAttributeEnd\n";
}

std::string floorQuad(double kd) {
  std::string k = std::to_string(kd);
  return "AttributeBegin\n  Material \"matte\" \"rgb Kd\" [" + k + " " + k + " " + k +
         "]\n"
         "  Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" "
         "[-8 0 -8  -8 0 8  8 0 8  8 0 -8]\nAttributeEnd\n";
}

// A box [x0,x1] x [y0,y1] x [z0,z1] of twelve triangles wound so that every normal points out.
std::string boxMesh(double x0, double x1, double y0, double y1, double z0, double z1) {
  auto s = [](double v) { return std::to_string(v); };
  const double xs[2] = {x0, x1}, ys[2] = {y0, y1}, zs[2] = {z0, z1};
  std::string p;
  for (int i = 0; i < 8; ++i)
    p += s(xs[i & 1]) + " " + s(ys[(i >> 1) & 1]) + " " + s(zs[(i >> 2) & 1]) + "  ";
  // Vertex i has x = bit 0, y = bit 1, z = bit 2; each face counter-clockwise seen from outside.
  return "Shape \"trianglemesh\" \"point P\" [" + p +
         "] \"integer indices\" [0 2 3 0 3 1  4 5 7 4 7 6  0 1 5 0 5 4  2 6 7 2 7 3  0 4 6 0 6 2"
         "  1 3 7 1 7 5]\n";
}

// The glass sphere before an emitter filling the view behind it (facing the camera, L = 1).
std::string sphereBeforeLight(const std::string& head, const std::string& glass) {
  return head +
         "WorldBegin\nAttributeBegin\n  Material \"matte\" \"rgb Kd\" [0 0 0]\n"
         "  AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
         "  Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" "
         "[-10 -10 -3  10 -10 -3  10 10 -3  -10 10 -3]\nAttributeEnd\n"
         "AttributeBegin\n  " +
         glass + "\n  Shape \"sphere\" \"float radius\" [1]\nAttributeEnd\nWorldEnd\n";
}
const char* kSphereCamera = "LookAt 0 0 5  0 0 0  0 1 0\n";

// A floor under a glass sphere (radius 0.5 at y = 1) and a light of half-size 0.25 at y = 3.
const double kFloorRho = 0.5, kCeilingL = 8, kLightHalf = 0.25, kLightY = 3;
std::string floorUnderSphere(const std::string& head) {
  return head + "WorldBegin\n" + ceilingLight(kLightY, kLightHalf, kCeilingL) +
         floorQuad(kFloorRho) +
         "AttributeBegin\n  Material \"glass\" \"float index\" [1.5]\n  Translate 0 1 0\n"
         "  Shape \"sphere\" \"float radius\" [0.5]\nAttributeEnd\nWorldEnd\n";
}
const char* kFloorCamera = "LookAt 0 1.6 3.2  0 0.1 0  0 1 0\n";

// The same floor under a glass slab [-1.2, 1.2] x [1, 1.3] x [-1.2, 1.2].
std::string floorUnderSlab(const std::string& head) {
  return head + "WorldBegin\n" + ceilingLight(kLightY, kLightHalf, kCeilingL) +
         floorQuad(kFloorRho) + "AttributeBegin\n  Material \"glass\" \"float index\" [1.5]\n  " +
         boxMesh(-1.2, 1.2, 1, 1.3, -1.2, 1.2) + "AttributeEnd\nWorldEnd\n";
}
const char* kSlabCamera = "LookAt 0 0.5 3.5  0 0.2 0  0 1 0\n";

// --- geometry for the pixel masks (independent of the renderer's intersection code) ---

struct Vec {
  double x, y, z;
};
Vec sub(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dotv(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Whether the segment from a to b passes within radius r of centre c.
bool segmentNearPoint(Vec a, Vec b, Vec c, double r) {
  Vec d = sub(b, a), ac = sub(c, a);
  double t = std::clamp(dotv(ac, d) / dotv(d, d), 0.0, 1.0);
  Vec q{a.x + t * d.x - c.x, a.y + t * d.y - c.y, a.z + t * d.z - c.z};
  return dotv(q, q) < r * r;
}

// The light's corners and centre, at its height.
std::vector<Vec> lightPoints() {
  const double h = kLightHalf;
  return {{-h, kLightY, -h}, {h, kLightY, -h}, {h, kLightY, h}, {-h, kLightY, h}, {0, kLightY, 0}};
}

// A floor point from which the whole light is hidden behind a sphere of radius r at (0, 1, 0):
// the sphere's shadow is convex, so the corners suffice.
bool inSphereUmbra(Vec p, double r) {
  for (Vec l : lightPoints())
    if (!segmentNearPoint(p, l, {0, 1, 0}, r)) return false;
  return true;
}

// A floor point from which the whole light is seen through the slab's top and bottom faces
// (shrunk by margin).
bool underSlab(Vec p, double margin) {
  for (Vec l : lightPoints())
    for (double y : {1.0, 1.3}) {
      double t = (y - p.y) / (l.y - p.y);
      double x = p.x + t * (l.x - p.x), z = p.z + t * (l.z - p.z);
      if (std::abs(x) > 1.2 - margin || std::abs(z) > 1.2 - margin) return false;
    }
  return true;
}

// Camera rays through a pixel's corners and centre, as the job's camera makes them.
std::vector<Ray> pixelRays(const RenderJob& job, int x, int y) {
  std::vector<Ray> rays;
  for (auto [dx, dy] :
       {std::pair{0.5f, 0.5f}, {0.02f, 0.02f}, {0.98f, 0.02f}, {0.02f, 0.98f}, {0.98f, 0.98f}}) {
    CameraSample s;
    s.pFilm = Point2f(Float(x) + dx, Float(y) + dy);
    s.pLens = Point2f(0.5f, 0.5f);
    Ray r;
    job.camera->generateRay(s, &r);
    rays.push_back(r);
  }
  return rays;
}

// Where a ray meets the floor y = 0 (it must point down).
std::optional<Vec> floorPoint(const Ray& r) {
  if (r.d.y >= 0) return std::nullopt;
  double t = -double(r.o.y) / r.d.y;
  return Vec{r.o.x + t * r.d.x, 0, r.o.z + t * r.d.z};
}

// Whether a ray meets a sphere of radius r at c (before the floor).
bool raySphere(const Ray& ray, Vec c, double r) {
  Vec o{ray.o.x, ray.o.y, ray.o.z}, d{ray.d.x, ray.d.y, ray.d.z};
  Vec oc = sub(o, c);
  double a = dotv(d, d), b = dotv(oc, d), cc = dotv(oc, oc) - r * r;
  return b * b - a * cc > 0 && -b > 0;
}

// Whether a ray passes through the slab's box (any face).
bool raySlab(const Ray& ray) {
  double t0 = 0, t1 = 1e30;
  const double lo[3] = {-1.2, 1, -1.2}, hi[3] = {1.2, 1.3, 1.2};
  for (int k = 0; k < 3; ++k) {
    double o = ray.o[k], d = ray.d[k];
    if (d == 0) {
      if (o < lo[k] || o > hi[k]) return false;
      continue;
    }
    double a = (lo[k] - o) / d, b = (hi[k] - o) / d;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1;
}

// --- the check ---

struct BoundCheck {
  int pixels = 0;      // checked
  int violations = 0;  // pixels whose spread exceeds m (M - m)
  double spread = 0;   // sum over the checked pixels of pixelVariance (n - 1), the green channel
  double bound = 0;    // sum of m (M - m)
  double lit = 0;      // checked pixels with 0 < m < M (where the bound says something)
  std::string worst;
};

// For the pixels mask selects: pixelVariance (n - 1) <= m (M - m) (1 + 1e-4) per channel (the
// tolerance covers float rounding of weights that are 1 in exact arithmetic).
BoundCheck checkBound(const test::RenderedScene& r, double M,
                      const std::function<bool(int, int)>& mask = {}) {
  BoundCheck c;
  const Film& film = r.film();
  Bounds2i b = film.pixelBounds();
  double worstRatio = 0;
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) {
      if (mask && !mask(x, y)) continue;
      Point2i p(x, y);
      double n = double(film.pixelSampleCount(p));
      Spectrum m = film.pixelValue(p), v = film.pixelVariance(p);
      ++c.pixels;
      bool bad = false;
      for (int ch = 0; ch < 3; ++ch) {
        double spread = double(v[ch]) * (n - 1), bound = double(m[ch]) * (M - double(m[ch]));
        if (ch == 1) {
          c.spread += spread;
          c.bound += std::max(0.0, bound);
          if (m[ch] > 0 && m[ch] < M) ++c.lit;
        }
        double ratio = spread / std::max(bound, 1e-12);
        if (spread > bound * (1 + 1e-4) + 1e-9 * M * M) {
          bad = true;
          if (ratio > worstRatio) {
            worstRatio = ratio;
            c.worst = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): mean " +
                      std::to_string(m[ch]) + ", spread " + std::to_string(spread) + " > bound " +
                      std::to_string(bound);
          }
        }
      }
      if (bad) ++c.violations;
    }
  return c;
}

test::TestRenderOptions options(uint64_t seed) {
  test::TestRenderOptions o;
  o.build.seed = seed;
  o.render.nThreads = 1;
  return o;
}

// The integrators and dialects whose camera paths are checked against the bound: pbrt-v3's path
// (roulette off, so that no survival weight 1 / (1 - q) enters: its rule with rrthreshold 0),
// pbrt-v2's path (every path faces roulette from depth 3: maxdepth 4 leaves it none), volpath.
struct Estimator {
  const char* name;
  std::string (*integrator)(int maxDepth);
};
std::string depthParam(int d) { return " \"integer maxdepth\" [" + std::to_string(d) + "]"; }
const Estimator kCameraPathEstimators[] = {
    {"path_v3",
     [](int d) { return "Integrator \"path\"" + depthParam(d) + " \"float rrthreshold\" [0]"; }},
    {"path_v2", [](int d) { return "SurfaceIntegrator \"path\"" + depthParam(std::min(d, 4)); }},
    {"volpath",
     [](int d) { return "Integrator \"volpath\"" + depthParam(d) + " \"float rrthreshold\" [0]"; }},
};

// Integrators that trace both the reflected and the refracted ray at a smooth dielectric, each
// weighted by its Fresnel share (pbrt 2e §1.3.6): their samples lie in [0, M] too.
const Estimator kRecursionEstimators[] = {
    {"whitted", [](int d) { return "SurfaceIntegrator \"whitted\"" + depthParam(d); }},
    {"photonmap", [](int d) { return "SurfaceIntegrator \"photonmap\"" + depthParam(d); }},
};

TEST(GlassVariance, SphereBeforeALightSpreadsNoMoreThanItsTwoValues) {
  std::vector<Estimator> all(std::begin(kCameraPathEstimators), std::end(kCameraPathEstimators));
  all.insert(all.end(), std::begin(kRecursionEstimators), std::end(kRecursionEstimators));
  for (const Estimator& e : all)
    for (const char* sampler : {"random", "halton"})
      for (uint64_t seed : {1, 2}) {
        auto r = test::renderSceneText(
            sphereBeforeLight(header(24, 64, sampler, kSphereCamera, e.integrator(8)),
                              "Material \"glass\" \"float index\" [1.5]"),
            options(seed));
        BoundCheck c = checkBound(r, 1);
        EXPECT_EQ(c.violations, 0)
            << e.name << " " << sampler << " seed " << seed << ": " << c.worst;
        EXPECT_GT(c.lit, 100) << e.name;  // pixels whose samples both reach and miss the light
      }
}

// Pixels whose rays (corners and centre) all meet the sphere of radius 1 at the origin.
std::function<bool(int, int)> insideUnitSphere(const RenderJob& job) {
  return [&job](int x, int y) {
    for (const Ray& ray : pixelRays(job, x, y))
      if (!raySphere(ray, {0, 0, 0}, 1)) return false;
    return true;
  };
}

// The floor scenes: every estimator's pixels whose rays reach the floor past the glass (blocks
// false) at points only the caustic lights (inShadow true) keep within the bound.
void expectFloorCausticBounded(const std::function<std::string(const std::string&)>& scene,
                               const char* camera, int maxDepth, uint64_t seed,
                               const std::function<bool(const Ray&)>& blocks,
                               const std::function<bool(const Vec&)>& inShadow, int minPixels) {
  for (const Estimator& e : kCameraPathEstimators) {
    auto r = test::renderSceneText(scene(header(32, 64, "halton", camera, e.integrator(maxDepth))),
                                   options(seed));
    const RenderJob& job = r.jobs.front();
    auto mask = [&](int x, int y) {
      for (const Ray& ray : pixelRays(job, x, y)) {
        std::optional<Vec> p = floorPoint(ray);
        if (blocks(ray) || !p || !inShadow(*p)) return false;
      }
      return true;
    };
    BoundCheck c = checkBound(r, kFloorRho * kCeilingL, mask);
    EXPECT_GT(c.pixels, minPixels) << e.name;
    EXPECT_GT(c.lit, 10) << e.name;
    EXPECT_EQ(c.violations, 0) << e.name << ": " << c.worst;
  }
}

TEST(GlassVariance, CausticInASphereUmbraSpreadsNoMoreThanItsTwoValues) {
  expectFloorCausticBounded(
      floorUnderSphere, kFloorCamera, 4, 3,
      [](const Ray& ray) {
        return raySphere(ray, {0, 1, 0}, 0.5);
      },
      [](const Vec& p) { return inSphereUmbra(p, 0.48); }, 20);
}

TEST(GlassVariance, LightThroughASlabSpreadsNoMoreThanItsTwoValues) {
  expectFloorCausticBounded(
      floorUnderSlab, kSlabCamera, 6, 4, raySlab, [](const Vec& p) { return underSlab(p, 0.02); },
      50);
}

TEST(GlassVariance, BdptCameraStrategiesInsideTheSphereSpreadNoMoreThanTwoValues) {
  // Inside the sphere's silhouette no light subpath reaches the camera (every connection meets a
  // specular surface), so the film holds only the camera strategy's samples, each 0 or 1.
  auto r = test::renderSceneText(
      sphereBeforeLight(
          header(24, 32, "halton", kSphereCamera, "Integrator \"bdpt\" \"integer maxdepth\" [6]"),
          "Material \"glass\" \"float index\" [1.5]"),
      options(5));
  BoundCheck c = checkBound(r, 1, insideUnitSphere(r.jobs.front()));
  EXPECT_GT(c.pixels, 200);
  EXPECT_EQ(c.violations, 0) << c.worst;
}

// The pooled spread of rough glass before the light over the two-value bound, for one estimator,
// roughness and seed.
double roughGlassRatio(const Estimator& e, const std::string& roughness, uint64_t seed) {
  auto r = test::renderSceneText(
      sphereBeforeLight(header(24, 64, "halton", kSphereCamera, e.integrator(8)),
                        "Material \"glass\" \"float index\" [1.5] \"float uroughness\" [" +
                            roughness + "] \"float vroughness\" [" + roughness + "]"),
      options(seed));
  BoundCheck c = checkBound(r, 1, insideUnitSphere(r.jobs.front()));
  EXPECT_GT(c.bound, 0);
  return c.bound > 0 ? c.spread / c.bound : 0;
}

// path's samples reach the bound's two values only in the smooth limit; volpath's light
// estimate draws its scattering sample apart from the direction the path goes on in (pbrt-v3's
// structure), so a path reflected inside the sphere can meet the light twice and its samples
// reach 2M. Measured over seeds 1-30 (pooled spread over bound, mean and worst): path_v3 0.974 /
// 0.979, 0.879 / 0.883, 0.732 / 0.738 at roughness 0.01, 0.05, 0.2; path_v2 0.988 / 0.992,
// 0.895 / 0.899, 0.736 / 0.741; volpath 1.165 / 1.193, 0.952 / 0.964, 0.772 / 0.781. With the
// two Trowbridge-Reitz lobes picked half and half, and volpath counting only the chosen
// triangle's light: path 4.4-19.7, volpath 9.0-37.1.
double roughGlassLimit(const Estimator& e) { return std::string(e.name) == "volpath" ? 1.25 : 1; }

TEST(GlassVariance, RoughGlassSpreadsWithinTheTwoValueBound) {
  for (const char* roughness : {"0.01", "0.05", "0.2"})
    for (const Estimator& e : kCameraPathEstimators)
      EXPECT_LT(roughGlassRatio(e, roughness, 6), roughGlassLimit(e))
          << "roughness " << roughness << ", " << e.name;
}

// The false-alarm rate of the test above: none of 30 seeds per case exceeds its limit.
TEST(LongGlassVariance, RoughGlassWithinTheBoundForEverySeed) {
  for (const char* roughness : {"0.01", "0.05", "0.2"})
    for (const Estimator& e : kCameraPathEstimators)
      for (uint64_t seed = 1; seed <= 30; ++seed)
        EXPECT_LT(roughGlassRatio(e, roughness, seed), roughGlassLimit(e))
            << "roughness " << roughness << ", " << e.name << ", seed " << seed;
}

// --- the Cornell box with a glass sphere ---

// ../shared/scenes/peer/cornell-glass.pbrt (a Cornell box with a diffuse and a glass sphere),
// written here at res x res with the given integrator statement.
std::string cornellGlass(int res, int spp, const std::string& integrator) {
  std::string head = "Scale -1 1 1\nLookAt 0 1 3.8  0 1 0  0 1 0\n";
  // A quad with its shading normal, as the scene file gives them.
  auto quad = [](const std::string& p, const std::string& n) {
    return "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [" + p +
           "] \"normal N\" [" + n + " " + n + " " + n + " " + n + "]\n";
  };
  auto wall = [&](const std::string& kd, const std::string& p, const std::string& n) {
    return "AttributeBegin\n  Material \"matte\" \"rgb Kd\" [" + kd + "]\n  " + quad(p, n) +
           "AttributeEnd\n";
  };
  const std::string white = "0.725 0.71 0.68";
  return header(res, spp, "halton", head, integrator, 39) + "WorldBegin\n" +
         "AttributeBegin\n  AreaLightSource \"diffuse\" \"rgb L\" [17 12 4]\n"
         "  Material \"matte\" \"rgb Kd\" [0 0 0]\n  " +
         quad("-0.25 1.98 -0.25  0.25 1.98 -0.25  0.25 1.98 0.25  -0.25 1.98 0.25", "0 -1 0") +
         "AttributeEnd\n" + wall(white, "-1 0 -1  1 0 -1  1 0 1  -1 0 1", "0 1 0") +
         wall(white, "-1 2 -1  1 2 -1  1 2 1  -1 2 1", "0 -1 0") +
         wall(white, "-1 0 -1  1 0 -1  1 2 -1  -1 2 -1", "0 0 1") +
         wall("0.63 0.065 0.05", "-1 0 -1  -1 0 1  -1 2 1  -1 2 -1", "1 0 0") +
         wall("0.14 0.45 0.091", "1 0 -1  1 0 1  1 2 1  1 2 -1", "-1 0 0") +
         "AttributeBegin\n  Material \"glass\" \"float eta\" [1.5]\n  Translate 0.4 0.4 0.3\n"
         "  Shape \"sphere\" \"float radius\" [0.4]\nAttributeEnd\n"
         "AttributeBegin\n  Material \"matte\" \"rgb Kd\" [" +
         white +
         "]\n  Translate -0.45 0.35 -0.4\n  Shape \"sphere\" \"float radius\" [0.35]\n"
         "AttributeEnd\nWorldEnd\n";
}

// The integrators as the scene's users run them: roulette on, both dialects, maxdepth 8.
const Estimator kCornellEstimators[] = {
    {"path_v3", [](int d) { return "Integrator \"path\"" + depthParam(d); }},
    {"path_v2", [](int d) { return "SurfaceIntegrator \"path\"" + depthParam(d); }},
    {"volpath", [](int d) { return "Integrator \"volpath\"" + depthParam(d); }},
};

// The error per sample of the integrators users run on the Cornell box with a glass sphere, at
// 64 x 64 and 64 spp (Halton), against a reference bdpt makes (two renders of 128 spp, different
// seeds, whose own noise compareImages takes off): relMSE and the share of it in the worst 1% of
// the pixels (41), each the mean over three seeds. pbrt-v3 3.0 (mmp/pbrt-v3 at 13d871f, built
// here; it has no seed) gives 0.0307 and 0.556 on this scene at this size, the same measure;
// candela gave 0.103-0.137 and 0.94-0.96 (seeds 1-3) before it picked glass's reflection and
// refraction by Fresnel. Over 16 sets of three seeds (1-48) the means measured 0.0284-0.0361
// (path_v3, mean 0.0316, sd 0.0019), 0.0307-0.0373 (path_v2, 0.0333, 0.0021) and 0.0304-0.0352
// (volpath, 0.0326, 0.0014), the outlier shares 0.53-0.64. Held at 1.35 times pbrt-v3's relMSE
// (0.0414, 3.9 sd above path_v2's mean) and an outlier share of 0.75.
constexpr double kPbrtV3CornellGlassRelMse64 = 0.0307;
constexpr double kCornellRelMseLimit = 1.35 * kPbrtV3CornellGlassRelMse64;

struct CornellError {
  double relmse = 0, outlierShare = 0;
};

const std::pair<ImageBuffer, ImageBuffer>& cornellReference() {
  static const std::pair<ImageBuffer, ImageBuffer> reference = [] {
    auto render = [](uint64_t seed) {
      test::TestRenderOptions o = options(seed);
      o.render.nThreads = 0;  // all cores: the reference is the costly part
      return test::renderSceneText(cornellGlass(64, 128,
                                                "Integrator \"bdpt\" \"integer "
                                                "maxdepth\" [8]"),
                                   o)
          .film()
          .image();
    };
    return std::pair{render(1000001), render(1000002)};
  }();
  return reference;
}

CornellError cornellError(const Estimator& e, uint64_t seed) {
  auto r = test::renderSceneText(cornellGlass(64, 64, e.integrator(8)), options(seed));
  const auto& [refA, refB] = cornellReference();
  ImageComparison c = compareImages(r.film().image(), refA, &refB, 41);
  return {c.relmse, c.outlierShare};
}

// The means over a set of three seeds, as the test below takes them.
CornellError cornellErrorOfSeedSet(const Estimator& e, uint64_t firstSeed) {
  CornellError mean;
  for (uint64_t seed = firstSeed; seed < firstSeed + 3; ++seed) {
    CornellError c = cornellError(e, seed);
    mean.relmse += c.relmse / 3;
    mean.outlierShare += c.outlierShare / 3;
  }
  return mean;
}

TEST(GlassVariance, CornellBoxWithAGlassSphereHasPbrtV3sErrorPerSample) {
  for (const Estimator& e : kCornellEstimators) {
    CornellError mean = cornellErrorOfSeedSet(e, 1);
    std::cout << e.name << ": relMSE " << mean.relmse << ", outlier share " << mean.outlierShare
              << "\n";
    EXPECT_LT(mean.relmse, kCornellRelMseLimit) << e.name;
    EXPECT_LT(mean.outlierShare, 0.75) << e.name;
  }
}

// The false-alarm rate of the test above: 15 more sets of three seeds (4-6, ..., 46-48), each
// within the bounds. (A single seed need not be: one of 16 gave 0.0425 for path_v2, fireflies
// being rare events, as they are for pbrt-v3.)
TEST(LongGlassVariance, CornellBoxWithinTheBoundsForEverySeedSet) {
  for (const Estimator& e : kCornellEstimators)
    for (uint64_t first = 4; first <= 46; first += 3) {
      CornellError c = cornellErrorOfSeedSet(e, first);
      std::printf("%s seeds %d-%d: relMSE %.4f, outlier share %.3f\n", e.name, int(first),
                  int(first + 2), c.relmse, c.outlierShare);
      EXPECT_LT(c.relmse, kCornellRelMseLimit) << e.name << ", seeds from " << first;
      EXPECT_LT(c.outlierShare, 0.75) << e.name << ", seeds from " << first;
    }
}

// Metropolis (pbrt-v3's mlt: bdpt's paths, mutated) on the same box at 64 mutations per pixel,
// against the same reference. pbrt-v3 gives 0.0987 and an outlier share of 0.259 here (one run:
// its chains have no seed); candela 0.072-0.107 over seeds 1-24 (mean 0.089, sd 0.009) and
// shares 0.26-0.29, before and after glass picked by Fresnel (its light and camera subpaths
// through glass are bdpt's). Held, as a mean over three seeds (sd about 0.005), at 1.2 times
// pbrt-v3's figure and a share of 0.5.
constexpr double kPbrtV3CornellGlassMltRelMse64 = 0.0987;

TEST(GlassVariance, MetropolisInTheCornellBoxHasPbrtV3sErrorPerMutation) {
  const Estimator mlt{"mlt", [](int d) {
                        return "Integrator \"mlt\"" + depthParam(d) +
                               " \"integer mutationsperpixel\" [64]";
                      }};
  CornellError mean = cornellErrorOfSeedSet(mlt, 1);
  std::cout << "mlt: relMSE " << mean.relmse << ", outlier share " << mean.outlierShare << "\n";
  EXPECT_LT(mean.relmse, 1.2 * kPbrtV3CornellGlassMltRelMse64);
  EXPECT_LT(mean.outlierShare, 0.5);
}

// --- across seeds: integrators without per-pixel sample sums ---

// K renders with seeds 1..K of the sphere before the light, each a mean of n samples per pixel:
// per pixel the K values' sample variance against the two-value bound of such a mean,
// m (1 - m) / n, with m estimated from the K values (times nK / (nK - 1), which makes that
// estimate unbiased for independent samples); both pooled over the pixels. Independent samples
// in [0, 1] give at most 1 in expectation, randomised low-discrepancy ones less.
double acrossSeedRatio(const std::string& integrator, int n, int K) {
  std::vector<std::vector<double>> values;
  for (int k = 1; k <= K; ++k) {
    auto r =
        test::renderSceneText(sphereBeforeLight(header(24, n, "halton", kSphereCamera, integrator),
                                                "Material \"glass\" \"float index\" [1.5]"),
                              options(uint64_t(k)));
    std::vector<double> v;
    for (const Spectrum& p : test::pixelValues(r.film())) v.push_back(p[1]);
    values.push_back(std::move(v));
  }
  double spread = 0, bound = 0, nk = double(n) * K;
  for (size_t p = 0; p < values.front().size(); ++p) {
    double m = 0;
    for (int k = 0; k < K; ++k) m += values[size_t(k)][p] / K;
    double s2 = 0;
    for (int k = 0; k < K; ++k) s2 += (values[size_t(k)][p] - m) * (values[size_t(k)][p] - m);
    spread += s2 / (K - 1);
    bound += std::max(0.0, m * (1 - m)) / n * nk / (nk - 1);
  }
  return bound > 0 ? spread / bound : 0;
}

// SPPM keeps no per-pixel sample sums: its camera paths' emission (the whole image here: no
// surface takes photons) is measured over 8 seeds of 16 iterations. Measured 0.98 (path with
// independent samples at 1 spp: 1.00, its Halton samples at 16 spp 0.53); with half-and-half
// picks 21. The ratio's own spread over seed sets is about 0.04 (the pooled variance of 8
// values over about 300 lit pixels); held at 1.25.
TEST(GlassVariance, SppmCameraPathsAcrossSeedsSpreadWithinTheBound) {
  double ratio = acrossSeedRatio(
      "Integrator \"sppm\" \"integer numiterations\" [16] \"integer maxdepth\" [8]", 16, 8);
  EXPECT_LT(ratio, 1.25);
  EXPECT_GT(ratio, 0.1);  // the pixels do vary: the check has something to measure
}

}  // namespace
}  // namespace candela
