// The irradiance cache integrator against closed forms and against path tracing (pbrt 2e §15.5;
// lrt draft §16.5), and its parameters' errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "integrators/irradiance/irradiance_cache_integrator.h"
#include "support/render_scene.h"

namespace candela {
namespace {

std::string sceneText(const std::string& integrator, const std::string& camera,
                      const std::string& world, int resolution, const std::string& sampler) {
  std::string res = std::to_string(resolution);
  return camera + "Film \"image\" \"integer xresolution\" [" + res + "] \"integer yresolution\" [" +
         res + "]\n" + sampler + "\nSurfaceIntegrator " + integrator + "\nWorldBegin\n" + world +
         "\nWorldEnd\n";
}

const char* kInsideSphere =
    "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" [60]\n";

// A closed unit sphere, normals inward, Lambertian of albedo rho = 0.5 emitting Le = 0.5.
const char* kFurnace =
    "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
    "AreaLightSource \"diffuse\" \"rgb L\" [0.5 0.5 0.5]\n"
    "ReverseOrientation\n"
    "Shape \"sphere\" \"float radius\" [1]\n";

double worstRelativeError(const Film& film, double expected) {
  double worst = 0;
  Bounds2i b = film.pixelBounds();
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) {
      Spectrum v = film.pixelValue(Point2i(x, y));
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(v[c] - expected) / expected);
    }
  return worst;
}

// In the furnace the radiance is Le / (1 - rho) everywhere, so the irradiance is the same at
// every point and interpolating it costs nothing: whatever maxerror and the spacing clamps say,
// the cache's error is the error of its estimates alone. And those have none: every wall point
// sees the sphere's interior, for which uniform area sampling of the light and cosine sampling
// of the BSDF both give exactly rho Le, and each bounce's f cos / pdf is exactly rho; with at
// most 3 vertices per path no Russian roulette runs (it starts after the third). So the image is
// the series truncated where maxindirectdepth m stops it, Le (1 - rho^(m+2)) / (1 - rho) (direct
// light is one bounce, an estimate's paths add up to m more, reflected once more at the point),
// to rounding: the tolerance, 1e-5, is float rounding (measured: below 2e-7).
TEST(IrradianceCache, FurnaceIsTheTruncatedSeriesForAnyMaxError) {
  const double le = 0.5, rho = 0.5;
  for (int m = 0; m <= 3; ++m)
    for (const char* maxError : {"0", "0.05", "0.2", "1"}) {
      std::string integrator =
          "\"irradiancecache\" \"integer nsamples\" [16] "
          "\"integer maxindirectdepth\" [" +
          std::to_string(m) + "] \"float maxerror\" [" + maxError + "]";
      auto r = test::renderSceneText(sceneText(integrator, kInsideSphere, kFurnace, 12,
                                               "Sampler \"random\" \"integer pixelsamples\" [2]"));
      double expected = le * (1 - std::pow(rho, m + 2)) / (1 - rho);
      EXPECT_LT(worstRelativeError(r.film(), expected), 1e-5)
          << "maxindirectdepth " << m << " maxerror " << maxError;
      auto* ic = dynamic_cast<const IrradianceCacheIntegrator*>(r.job().integrator.get());
      ASSERT_NE(ic, nullptr);
      if (std::string(maxError) == "0")
        EXPECT_EQ(ic->cache(), nullptr);
      else
        EXPECT_GT(ic->cache()->size(), 0u);
    }
}

// With every bounce counted (Russian roulette ends the paths), the furnace's radiance is
// Le / (1 - rho) = 1. Now the estimates have variance, from roulette only, and interpolation
// still adds no error; with 4096 paths per estimate the worst pixel is off by 0.32% (measured),
// so 1% is about three times that.
TEST(IrradianceCache, FurnaceConvergesToGeometricSeries) {
  std::string integrator =
      "\"irradiancecache\" \"integer nsamples\" [4096] \"integer maxindirectdepth\" [200]";
  auto r = test::renderSceneText(sceneText(integrator, kInsideSphere, kFurnace, 12,
                                           "Sampler \"random\" \"integer pixelsamples\" [1]"));
  EXPECT_LT(worstRelativeError(r.film(), 1.0), 0.01);
}

// A room (the box [-1, 1]^3 seen from inside) with a block on the floor, lit by a point light so
// that direct light has no noise: the irradiance cache's error is its indirect light's.
std::string boxMesh(Point3f a, Point3f b) {
  auto v = [&](int i) {
    return std::to_string(i & 1 ? b.x : a.x) + " " + std::to_string(i & 2 ? b.y : a.y) + " " +
           std::to_string(i & 4 ? b.z : a.z) + " ";
  };
  std::string points;
  for (int i = 0; i < 8; ++i) points += v(i);
  return "Shape \"trianglemesh\" \"integer indices\" [0 1 3 0 3 2  4 6 7 4 7 5  0 4 5 0 5 1  "
         "2 3 7 2 7 6  0 2 6 0 6 4  1 5 7 1 7 3] \"point P\" [" +
         points + "]\n";
}

const std::string kRoomCamera =
    "LookAt 0.2 0.1 -0.95  -0.1 -0.4 1  0 1 0\nCamera \"perspective\" \"float fov\" [70]\n";

std::string roomWorld() {
  return "LightSource \"point\" \"point from\" [0.4 0.8 0.2] \"rgb I\" [1.5 1.5 1.5]\n"
         "Material \"matte\" \"rgb Kd\" [0.6 0.6 0.6]\n" +
         boxMesh(Point3f(-1, -1, -1), Point3f(1, 1, 1)) +
         "Material \"matte\" \"rgb Kd\" [0.7 0.3 0.2]\n" +
         boxMesh(Point3f(-0.5f, -1, 0), Point3f(0.1f, -0.3f, 0.6f));
}

// Root-mean-square difference of two films' pixels over all channels.
double rmsDifference(const Film& a, const Film& b) {
  double sum = 0;
  int n = 0;
  Bounds2i bounds = a.pixelBounds();
  for (int y = bounds.pMin.y; y < bounds.pMax.y; ++y)
    for (int x = bounds.pMin.x; x < bounds.pMax.x; ++x) {
      Spectrum d = a.pixelValue(Point2i(x, y)) - b.pixelValue(Point2i(x, y));
      for (int c = 0; c < 3; ++c, ++n) sum += double(d[c]) * d[c];
    }
  return std::sqrt(sum / n);
}

// The cache's error against path tracing falls as its parameters tighten: a smaller radius
// (maxerror and the pixel spacings), a smaller angle, more rays per estimate. The path
// reference counts the same bounces (maxdepth = maxindirectdepth + 1: direct light, the
// estimate's paths, then the reflection at the point itself). Its own noise adds to every
// setting's squared error alike; it is measured from a second reference with another seed and
// taken out, so that what is compared is the cache's own error. Measured (seed 0): 0.065,
// 0.019, 0.014 before taking out the reference's 0.009.
TEST(IrradianceCache, ErrorAgainstPathTracingFallsAsTheParametersTighten) {
  const int res = 16;
  auto pathRender = [&](uint64_t seed) {
    test::TestRenderOptions o;
    o.build.seed = seed;
    return test::renderSceneText(
        sceneText("\"path\" \"integer maxdepth\" [4]", kRoomCamera, roomWorld(), res,
                  "Sampler \"random\" \"integer pixelsamples\" [1024]"),
        o);
  };
  auto reference = pathRender(1);
  double referenceNoise = rmsDifference(reference.film(), pathRender(2).film()) / std::sqrt(2.0);
  const char* settings[] = {
      "\"float maxerror\" [1] \"float maxangledifference\" [30] \"integer nsamples\" [16] "
      "\"float minpixelspacing\" [6] \"float maxpixelspacing\" [32]",
      "\"float maxerror\" [0.4] \"float maxangledifference\" [15] \"integer nsamples\" [128] "
      "\"float minpixelspacing\" [2.5] \"float maxpixelspacing\" [15]",
      "\"float maxerror\" [0.1] \"float maxangledifference\" [5] \"integer nsamples\" [1024] "
      "\"float minpixelspacing\" [0.5] \"float maxpixelspacing\" [4]",
  };
  double previous = 0;
  for (int i = 0; i < 3; ++i) {
    SCOPED_TRACE(settings[i]);
    auto r = test::renderSceneText(sceneText(
        std::string("\"irradiancecache\" \"integer maxindirectdepth\" [3] \"integer nfilter\" "
                    "[0] ") +
            settings[i],
        kRoomCamera, roomWorld(), res, "Sampler \"random\" \"integer pixelsamples\" [4]"));
    double difference = rmsDifference(r.film(), reference.film());
    double error =
        std::sqrt(std::max(0.0, difference * difference - referenceNoise * referenceNoise));
    if (i > 0) {
      EXPECT_LT(error, previous) << "reference noise " << referenceNoise;
    }
    previous = error;
  }
}

// Every parameter error is a SceneError at the parameter's line (line 3 of each scene here).
TEST(IrradianceCache, BadParametersAreSceneErrorsAtTheParameter) {
  const char* bad[] = {
      "\"integer nsamples\" [-1]",
      "\"integer nsamples\" [0]",
      "\"integer nfilter\" [-1]",
      "\"float maxerror\" [-0.1]",
      "\"float minweight\" [-1]",
      "\"float maxangledifference\" [0]",
      "\"float maxangledifference\" [-5]",
      "\"float maxangledifference\" [90.5]",
      "\"float minpixelspacing\" [-1]",
      "\"float maxpixelspacing\" [0]",
      "\"float minpixelspacing\" [20]",                               // > the default 15
      "\"float maxpixelspacing\" [2]",                                // < the default 2.5
      "\"float minpixelspacing\" [5] \"float maxpixelspacing\" [4]",  // both given
      "\"integer maxspeculardepth\" [-1]",
      "\"integer maxspeculardepth\" [1001]",
      "\"integer maxindirectdepth\" [-1]",
  };
  for (const char* params : bad) {
    std::string text =
        std::string("Camera \"perspective\"\nSurfaceIntegrator \"irradiancecache\"\n  ")
            .append(params)
            .append("\nWorldBegin\nWorldEnd\n");
    try {
      test::buildSceneText(text);
      ADD_FAILURE() << "accepted " << params;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.location().line, 3) << params << ": " << e.what();
    }
  }
  // The limits themselves are fine, and so are both dialects' names together.
  test::buildSceneText(
      "Camera \"perspective\"\nSurfaceIntegrator \"irradiancecache\" \"float maxangledifference\" "
      "[90] \"float maxerror\" [0] \"integer nfilter\" [100] \"integer nsamples\" [1] "
      "\"float minpixelspacing\" [3] \"float maxpixelspacing\" [3] \"float minweight\" [0] "
      "\"integer maxspeculardepth\" [0] \"integer maxindirectdepth\" [0]\nWorldBegin\nWorldEnd\n");
}

}  // namespace
}  // namespace candela
