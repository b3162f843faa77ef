// The subsurface materials' parameters (pbrt-v2's, pbrt 2e §16.5), the measured media by name,
// and the dipole integrator's hierarchical sum against brute force (Jensen and Buhler 2002).
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "core/sampling.h"
#include "integrators/dipole_subsurface.h"
#include "materials/measured_subsurface.h"
#include "materials/subsurface_scattering.h"
#include "support/parameter_errors.h"
#include "transport/subsurface_points.h"

namespace candela {
namespace {

// A scene whose material statement carries `parameter` alone on line 4.
std::string materialScene(const std::string& material, const std::string& parameter) {
  return "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
         "WorldBegin\nMaterial \"" +
         material + "\"\n  " + parameter +
         "\n"
         "LightSource \"point\" \"point from\" [0 0 -1]\n"
         "Shape \"sphere\" \"float radius\" [0.5]\n"
         "WorldEnd\n";
}

BSSRDFCoefficients coefficientsOf(const std::string& material, const std::string& parameter) {
  auto built = test::buildSceneText(materialScene(material, parameter));
  for (const auto& m : built.job().materials)
    if (const SubsurfaceScattering* s = m->subsurface()) return s->coefficients({});
  ADD_FAILURE() << "no subsurface material built";
  return {};
}

void expectLocatedError(const std::string& material, const std::string& parameter,
                        const std::string& mentions) {
  SCOPED_TRACE(material + " " + parameter);
  try {
    test::buildSceneText(materialScene(material, parameter));
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 4) << e.what();
    EXPECT_NE(std::string(e.what()).find(mentions), std::string::npos) << e.what();
  }
}

TEST(SubsurfaceMaterials, MeasuredNamesResolveToPbrtV2sTable) {
  std::vector<std::string> names = measuredSubsurfaceNames();
  for (const char* n : {"Apple", "Chicken1", "Chicken2", "Cream", "Ketchup", "Marble", "Potato",
                        "Skimmilk", "Skin1", "Skin2", "Spectralon", "Wholemilk"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
    ASSERT_TRUE(measuredSubsurface(n)) << n;
  }
  // Through the scene: Ketchup (sigma_s' .18 .07 .03, sigma_a .061 .97 1.45 per mm), scale 2.
  BSSRDFCoefficients c =
      coefficientsOf("subsurface", "\"string name\" \"Ketchup\" \"float scale\" [2]");
  EXPECT_FLOAT_EQ(c.sigmaPrimeS[0], 0.36f);
  EXPECT_FLOAT_EQ(c.sigmaPrimeS[2], 0.06f);
  EXPECT_FLOAT_EQ(c.sigmaA[1], 1.94f);
  EXPECT_FLOAT_EQ(c.eta, 1.33f);
  // pbrt-v2's additions from Narasimhan et al. 2006, names with spaces and '&' included.
  EXPECT_EQ(names.size(), 47u);
  for (const char* n : {"Lowfat Milk", "Espresso", "Coke", "Merlot", "Head & Shoulders Shampoo",
                        "Pacific Ocean Surface Water"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
  c = coefficientsOf("subsurface", "\"string name\" \"Head & Shoulders Shampoo\"");
  EXPECT_FLOAT_EQ(c.sigmaPrimeS[1], 0.4527f);
  EXPECT_FLOAT_EQ(c.sigmaA[2], 0.2125f);
  c = coefficientsOf("subsurface", "\"string name\" \"Pacific Ocean Surface Water\"");
  EXPECT_FLOAT_EQ(c.sigmaPrimeS[0], 3.3645f);
  EXPECT_FLOAT_EQ(c.sigmaA[0], 3.1845f);
  // An explicit coefficient wins over the named medium's.
  c = coefficientsOf("subsurface", "\"string name\" \"Ketchup\" \"rgb sigma_a\" [1 2 3]");
  EXPECT_FLOAT_EQ(c.sigmaA[2], 3);
  EXPECT_FLOAT_EQ(c.sigmaPrimeS[1], 0.07f);
  // pbrt-v2's defaults: whole milk.
  c = coefficientsOf("subsurface", "\"float index\" [1.5]");
  EXPECT_FLOAT_EQ(c.sigmaPrimeS[0], 2.55f);
  EXPECT_FLOAT_EQ(c.sigmaA[2], 0.014f);
  EXPECT_FLOAT_EQ(c.eta, 1.5f);
}

TEST(SubsurfaceMaterials, KdSubsurfaceReflectsKd) {
  BSSRDFCoefficients c =
      coefficientsOf("kdsubsurface", "\"rgb Kd\" [.2 .5 .8] \"float meanfreepath\" [0.5]");
  Spectrum total = DipoleProfile(c).totalReflectance();
  EXPECT_NEAR(total[0], 0.2, 1e-5);
  EXPECT_NEAR(total[1], 0.5, 1e-5);
  EXPECT_NEAR(total[2], 0.8, 1e-5);
  EXPECT_NEAR(c.sigmaA[1] + c.sigmaPrimeS[1], 2, 1e-5);
}

TEST(SubsurfaceMaterials, BadParametersAreLocatedErrors) {
  expectLocatedError("subsurface", "\"string name\" \"Marmite\"", "Wholemilk");
  expectLocatedError("subsurface", "\"string name\" \"Marmite\"", "Marmite");
  expectLocatedError("subsurface", "\"rgb sigma_a\" [-1 0 0]", "sigma_a");
  expectLocatedError("subsurface", "\"rgb sigma_prime_s\" [1 -0.5 1]", "sigma_prime_s");
  expectLocatedError("subsurface", "\"float scale\" [-1]", "scale");
  expectLocatedError("subsurface", "\"float index\" [0]", "index");
  expectLocatedError("kdsubsurface", "\"float meanfreepath\" [-1]", "meanfreepath");
  expectLocatedError("kdsubsurface", "\"float meanfreepath\" [0]", "meanfreepath");
  expectLocatedError("kdsubsurface", "\"float index\" [-1.3]", "index");
}

TEST(DipoleSubsurfaceIntegrator, BadParametersAreLocatedErrors) {
  test::expectParameterErrorsLocated(
      "SurfaceIntegrator \"dipolesubsurface\"",
      {"\"float maxerror\" [-1]", "\"float minsampledistance\" [0]",
       "\"float minsampledistance\" [-2]", "\"string pointsfile\" \"points.dat\"",
       "\"integer maxdepth\" [-1]"});
}

// Points on the unit sphere with random irradiance and equal areas.
std::vector<SubsurfacePoint> spherePoints(int n) {
  RNG rng(7, 20261125);
  std::vector<SubsurfacePoint> pts;
  for (int i = 0; i < n; ++i) {
    Float u0 = rng.uniformFloat(), u1 = rng.uniformFloat();
    Vector3f d = sampleUniformSphere({u0, u1});
    SubsurfacePoint sp;
    sp.p = Point3f(d.x, d.y, d.z);
    sp.n = Normal3f(d.x, d.y, d.z);
    sp.area = 4 * kPi / Float(n);
    Float e0 = rng.uniformFloat(), e1 = rng.uniformFloat(), e2 = rng.uniformFloat();
    sp.E = Spectrum(e0, e1, e2);
    pts.push_back(sp);
  }
  return pts;
}

TEST(SubsurfaceOctree, HierarchicalSumApproachesBruteForce) {
  SubsurfaceOctree octree(spherePoints(4000));
  EXPECT_GT(octree.nodeCount(), 4000u / 8);
  DipoleProfile profile({Spectrum(0.05f, 0.2f, 0.5f), Spectrum(3, 2, 1), 1.33f});
  const Point3f queries[] = {{1, 0, 0}, {0, -1, 0}, {0.6f, 0.8f, 0}, {0, 0, 1.5f}, {0, 0, 0}};
  auto meanRelativeError = [&](Float maxError) {
    double sum = 0;
    for (const Point3f& q : queries) {
      Spectrum exact = octree.bruteForceSum(q, profile);
      Spectrum approx = octree.sum(q, profile, maxError);
      for (int c = 0; c < 3; ++c) sum += std::abs(approx[c] - exact[c]) / exact[c];
    }
    return sum / (3 * std::size(queries));
  };
  // maxError 0 never stands a node in for its points: the same terms, summed in another order.
  EXPECT_LT(meanRelativeError(0), 1e-5);
  double e001 = meanRelativeError(0.01f), e01 = meanRelativeError(0.1f),
         e1 = meanRelativeError(1.0f), e10 = meanRelativeError(10.0f);
  // Measured: 1e-5 at .01, 9e-4 at pbrt-v2's default .05, 4e-3 at .1, 2e-2 at 1, 0.26 at 10.
  EXPECT_LT(e001, 1e-4);
  EXPECT_LT(meanRelativeError(0.05f), 5e-3);
  EXPECT_LE(e001, e01);
  EXPECT_LE(e01, e1);
  EXPECT_LT(e1, e10);
  EXPECT_GT(e10, 10 * e001);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// Two translucent spheres (radius 1 and 0.5) and an opaque quad: the points lie on the spheres
// only, at least minDistance apart, their areas add up to the spheres' area, and none of it
// depends on the thread count.
TEST(SubsurfacePoints, PoissonSpacedOnTranslucentSurfacesWithTheirArea) {
  auto built = test::buildSceneText(
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
      "WorldBegin\n"
      "AttributeBegin\nMaterial \"subsurface\"\nShape \"sphere\" \"float radius\" [1]\n"
      "Translate 3 0 0\nShape \"sphere\" \"float radius\" [0.5]\nAttributeEnd\n"
      "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
      "  \"point P\" [-5 -2 -5  5 -2 -5  5 -2 5  -5 -2 5]\n"
      "WorldEnd\n");
  SubsurfacePlacementOptions o;
  o.minDistance = 0.1f;
  o.seed = 42;
  o.nThreads = 1;
  SubsurfacePointSet one = placeSubsurfacePoints(*built.job().scene, o);
  o.nThreads = 2;
  SubsurfacePointSet two = placeSubsurfacePoints(*built.job().scene, o);
  ASSERT_EQ(one.points.size(), two.points.size());
  for (size_t i = 0; i < one.points.size(); ++i) {
    EXPECT_EQ(one.points[i].p, two.points[i].p);
    EXPECT_EQ(one.points[i].area, two.points[i].area);
  }
  ASSERT_GT(one.points.size(), 500u);
  EXPECT_FALSE(one.reachedPointLimit);
  const Float trueArea = 4 * kPi * (1 + 0.25f);
  double sum = 0;
  for (const SubsurfacePoint& sp : one.points) {
    sum += sp.area;
    // On one of the spheres, not on the quad.
    Float r1 = distance(sp.p, Point3f(0, 0, 0)), r2 = distance(sp.p, Point3f(3, 0, 0));
    EXPECT_TRUE(std::abs(r1 - 1) < 1e-3f || std::abs(r2 - 0.5f) < 1e-3f) << sp.p;
  }
  // Crofton's estimate from about 32 crossings a point: within 2 %.
  EXPECT_NEAR(sum, trueArea, 0.02 * trueArea);
  EXPECT_NEAR(one.surfaceArea, trueArea, 0.02 * trueArea);
  // Dart throwing: no two points closer than minDistance (brute force over pairs).
  Float closest = kInfinity;
  for (size_t i = 0; i < one.points.size(); ++i)
    for (size_t j = i + 1; j < one.points.size(); ++j)
      closest = std::min(closest, distance(one.points[i].p, one.points[j].p));
  EXPECT_GE(closest, o.minDistance);
  // ... and the surface covered: discs of radius minDistance / 2 around the points do not
  // overlap, and discs of radius minDistance cover the surface.
  EXPECT_LT(double(one.points.size()), trueArea / (kPi * 0.05 * 0.05));
  EXPECT_GT(double(one.points.size()), trueArea / (kPi * 0.1 * 0.1));
}

}  // namespace
}  // namespace candela
