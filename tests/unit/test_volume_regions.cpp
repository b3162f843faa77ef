// pbrt-v2 / lrt draft volume regions (lrt draft ch. 12): Beer's law, the exponential density's
// closed-form optical depth, the grid's trilinear interpolation, the aggregate, and located
// errors for bad Volume statements.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "assembly/volume_factory.h"
#include "core/error.h"
#include "media/aggregate_volume.h"
#include "media/exponential_volume.h"
#include "media/homogeneous_volume.h"
#include "media/tracking.h"
#include "media/volume_grid.h"
#include "support/render_scene.h"

namespace candela {
namespace {

RegionCoefficients coefficients(Spectrum sigmaA, Spectrum sigmaS) {
  RegionCoefficients c;
  c.sigmaA = sigmaA;
  c.sigmaS = sigmaS;
  return c;
}

TEST(VolumeRegions, HomogeneousTransmittanceIsBeersLaw) {
  // A unit box scaled and moved by the region's transform; the ray crosses it diagonally and
  // starts outside: the optical depth is σt times the world length inside.
  Transform toWorld = translate(Vector3f(1, -2, 3)) * scale(2, 3, 4);
  Spectrum sigmaA(0.3f, 0.1f, 0.05f), sigmaS(0.2f, 0.5f, 0.05f);
  HomogeneousVolume v(toWorld, Bounds3f(Point3f(0, 0, 0), Point3f(1, 1, 1)),
                      coefficients(sigmaA, sigmaS));
  Ray ray(Point3f(0, 0.5f, 5), Vector3f(1, 0, 0) * 0.25f);  // along x, |d| = 0.25
  Float t0, t1;
  ASSERT_TRUE(v.intersectP(ray, &t0, &t1));
  EXPECT_FLOAT_EQ(t0, 4);   // x = 1
  EXPECT_FLOAT_EQ(t1, 12);  // x = 3
  Spectrum tr = exp(-v.opticalDepth(ray, 0, ray.tMax, 1, 0.5f));
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(tr[c], std::exp(-(sigmaA[c] + sigmaS[c]) * 2)) << c;
  // Part of the box: from x = 1.5 to 2.5 is one world unit.
  Spectrum tau = v.opticalDepth(ray, 6, 10, 1, 0.5f);
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(tau[c], sigmaA[c] + sigmaS[c]) << c;
  // The default ray marching agrees (σt is constant: any offset is exact).
  Spectrum marched = v.Medium::opticalDepth(ray, 0, 20, 0.01f, 0.37f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(marched[c], 2 * (sigmaA[c] + sigmaS[c]), 2e-2f) << c;
  EXPECT_EQ(v.majorant(ray, 0, 20), sigmaA + sigmaS);
  EXPECT_EQ(v.majorant(ray, 0, 3), Spectrum(0));  // ends before the box
  EXPECT_TRUE(v.at(Point3f(2, -0.5f, 5), 0).sigmaS == sigmaS);
  EXPECT_TRUE(v.at(Point3f(0.9f, -0.5f, 5), 0).sigmaS.isBlack());
}

// Tracking (volpath) through a bounded homogeneous region entered from outside: the closed form
// holds for every ray, also where the entry point rounds to just outside the box (the
// coefficients must not be read at the boundary).
TEST(VolumeRegions, TrackingThroughAHomogeneousBoxFromOutsideIsBeersLaw) {
  Transform toWorld = rotate(30, Vector3f(1, 1, 0)) * scale(2, 1.5f, 1);
  Spectrum sigmaA(0.3f, 0.1f, 0.05f), sigmaS(0.2f, 0.5f, 0.05f);
  HomogeneousVolume v(toWorld, Bounds3f(Point3f(-1, -1, -1), Point3f(1, 1, 1)),
                      coefficients(sigmaA, sigmaS));
  RNG rng(7);
  int crossings = 0;
  for (int i = 0; i < 2000; ++i) {
    Point3f o(6 * rng.uniformFloat() - 3, 6 * rng.uniformFloat() - 3, -5);
    Point3f target(rng.uniformFloat() - 0.5f, rng.uniformFloat() - 0.5f, rng.uniformFloat());
    Ray ray(o, target - o);
    Float t0, t1;
    Spectrum tr = trackedTransmittance(v, ray, rng);
    if (!v.intersectP(ray, &t0, &t1)) {
      EXPECT_EQ(tr, Spectrum(1));
      continue;
    }
    ++crossings;
    Float length = (t1 - t0) * ray.d.length();
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(tr[c], std::exp(-(sigmaA[c] + sigmaS[c]) * length), 1e-5f)
          << "ray " << i << " channel " << c;
    // A free flight that does not scatter leaves with weight 1 (the closed form's T / T).
    FreeFlight f = sampleFreeFlight(v, ray, rng, Spectrum(1));
    ASSERT_GT(f.weight.maxComponent(), 0) << "ray " << i;
  }
  EXPECT_GT(crossings, 1000);
}

// Composite Simpson's rule with n (even) intervals, in double.
template <typename F>
double simpson(F f, double a, double b, int n) {
  double h = (b - a) / n, s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += f(a + i * h) * (i % 2 ? 4 : 2);
  return s * h / 3;
}

TEST(VolumeRegions, ExponentialOpticalDepthMatchesNumericalIntegration) {
  // A tilted up direction and a rotated, scaled region: τ = ∫ σt a e^{-b h(t)} |d| dt over the
  // part of the ray inside the box, integrated numerically from the density itself.
  Transform toWorld = rotate(30, Vector3f(0, 0, 1)) * scale(2, 2, 2);
  Spectrum sigmaA(0.5f), sigmaS(0.25f, 0.5f, 1);
  Bounds3f box(Point3f(-1, 0, -1), Point3f(1, 3, 1));
  ExponentialVolume v(toWorld, box, coefficients(sigmaA, sigmaS), 1.5f, 0.8f,
                      Vector3f(0.2f, 1, 0.1f));
  Transform toVolume = inverse(toWorld);
  for (Ray ray : {Ray(Point3f(-5, 1, 0.3f), Vector3f(1, 0.4f, 0)),
                  Ray(Point3f(0.2f, -3, 0.1f), Vector3f(0.05f, 2, -0.1f)),
                  Ray(Point3f(-1, 8, 0), Vector3f(0.1f, -1, 0.2f))}) {
    Float t0, t1;
    ASSERT_TRUE(v.intersectP(ray, &t0, &t1));
    Spectrum tau = v.opticalDepth(ray, 0, kInfinity, 1, 0.5f);
    double dLength = ray.d.length();
    auto densityAt = [&](double t) {
      Point3f p = toVolume(ray(Float(t)));
      return double(v.density(p)) * dLength;
    };
    double integral = simpson(densityAt, t0, t1, 20000);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(tau[c], (sigmaA[c] + sigmaS[c]) * integral, 2e-5 * std::abs(tau[c]) + 1e-7) << c;
    // A sub-range, and the majorant bounds σt along it.
    Float a = t0 + (t1 - t0) * 0.3f, b = t0 + (t1 - t0) * 0.6f;
    double part = simpson(densityAt, a, b, 20000);
    EXPECT_NEAR(v.opticalDepth(ray, a, b, 1, 0.5f)[0], (sigmaA[0] + sigmaS[0]) * part,
                2e-5 * part + 1e-7);
    Spectrum m = v.majorant(ray, a, b);
    for (int i = 0; i <= 100; ++i) {
      Float t = a + (b - a) * Float(i) / 100;
      EXPECT_LE(v.at(ray(t), 0).sigmaT()[2], m[2] * (1 + 1e-5f));
    }
  }
}

TEST(VolumeRegions, GridInterpolatesCellCentresAndIsZeroOutside) {
  const int nx = 3, ny = 2, nz = 4;
  std::vector<Float> d(nx * ny * nz);
  for (size_t i = 0; i < d.size(); ++i) d[i] = Float(i * 7 % 11) + 0.5f;
  Bounds3f box(Point3f(-1, 0, 2), Point3f(2, 1, 6));  // cells 1 x 0.5 x 1
  Transform toWorld = translate(Vector3f(0, 10, 0));
  VolumeGrid grid(toWorld, box, coefficients(Spectrum(1), Spectrum(2)), nx, ny, nz, d);
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        Point3f centre(-1 + (x + 0.5f) * 1, (y + 0.5f) * 0.5f, 2 + (z + 0.5f) * 1);
        Float stored = d[(z * ny + y) * nx + x];
        EXPECT_FLOAT_EQ(grid.density(centre), stored) << x << " " << y << " " << z;
        // In world space, through the region's transform: σt = 3 x density.
        EXPECT_FLOAT_EQ(grid.at(toWorld(centre), 0).sigmaT()[0], 3 * stored);
      }
  // Midway between two cell centres along x: their mean (an asymmetric index bug would not be).
  Point3f between(-1 + 1.0f, 0.25f, 2 + 1.5f);
  EXPECT_FLOAT_EQ(grid.density(between), (d[(1 * ny + 0) * nx + 0] + d[(1 * ny + 0) * nx + 1]) / 2);
  // Outside the box: zero, however close.
  for (Point3f p : {Point3f(-1.01f, 0.5f, 3), Point3f(0, 1.01f, 3), Point3f(0, 0.5f, 6.01f),
                    Point3f(0, -0.01f, 3)}) {
    EXPECT_EQ(grid.density(p), 0) << p.x << " " << p.y << " " << p.z;
    EXPECT_TRUE(grid.at(toWorld(p), 0).sigmaT().isBlack());
  }
  // The majorant bounds σt along a ray through the grid.
  Ray ray(toWorld(Point3f(-2, 0.3f, 2.5f)), Vector3f(1, 0.1f, 0.8f));
  Spectrum m = grid.majorant(ray, 0, kInfinity);
  for (int i = 0; i <= 400; ++i) EXPECT_LE(grid.at(ray(Float(i) / 80), 0).sigmaT()[0], m[0]);
}

TEST(VolumeRegions, AggregateSumsItsRegions) {
  Bounds3f unit(Point3f(0, 0, 0), Point3f(1, 1, 1));
  RegionCoefficients a = coefficients(Spectrum(0.1f), Spectrum(0.2f));
  a.phase = PhaseFunction::henyeyGreenstein(0.7f);
  a.Le = Spectrum(0.5f);
  RegionCoefficients b = coefficients(Spectrum(0.3f), Spectrum(0.6f));
  b.phase = PhaseFunction::rayleigh();
  std::vector<std::unique_ptr<Medium>> regions;
  regions.push_back(std::make_unique<HomogeneousVolume>(Transform(), unit, a));
  regions.push_back(std::make_unique<ExponentialVolume>(translate(Vector3f(0.5f, 0, 0)), unit, b, 1,
                                                        0.5f, Vector3f(0, 1, 0)));
  const Medium* first = regions[0].get();
  const Medium* second = regions[1].get();
  Point3f both(0.75f, 0.5f, 0.5f), onlyFirst(0.25f, 0.5f, 0.5f);
  MediumPoint m1 = first->at(both, 0), m2 = second->at(both, 0);
  AggregateVolume agg(std::move(regions));
  MediumPoint sum = agg.at(both, 0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_FLOAT_EQ(sum.sigmaA[c], m1.sigmaA[c] + m2.sigmaA[c]);
    EXPECT_FLOAT_EQ(sum.sigmaS[c], m1.sigmaS[c] + m2.sigmaS[c]);
    EXPECT_FLOAT_EQ(sum.Le[c], 0.5f);
  }
  // The phase of the region scattering most at the point.
  EXPECT_EQ(agg.phase(both, 0).kind(), m2.sigmaS[0] > m1.sigmaS[0]
                                           ? PhaseFunction::Kind::Rayleigh
                                           : PhaseFunction::Kind::HenyeyGreenstein);
  EXPECT_EQ(agg.phase(onlyFirst, 0).kind(), PhaseFunction::Kind::HenyeyGreenstein);
  // Optical depth and range: the union of the two boxes, x from 0 to 1.5.
  Ray ray(Point3f(-1, 0.5f, 0.5f), Vector3f(1, 0, 0));
  Float t0, t1;
  ASSERT_TRUE(agg.intersectP(ray, &t0, &t1));
  EXPECT_FLOAT_EQ(t0, 1);
  EXPECT_FLOAT_EQ(t1, 2.5f);
  Spectrum tau = agg.opticalDepth(ray, 0, 10, 1, 0.5f);
  Spectrum expected =
      first->opticalDepth(ray, 0, 10, 1, 0.5f) + second->opticalDepth(ray, 0, 10, 1, 0.5f);
  EXPECT_FLOAT_EQ(tau[0], expected[0]);
  EXPECT_GT(first->opticalDepth(ray, 0, 10, 1, 0.5f)[0], 0);
  EXPECT_GT(second->opticalDepth(ray, 0, 10, 1, 0.5f)[0], 0);
  EXPECT_TRUE(agg.emits());
}

// A Volume statement on line 3 with `parameter` on line 4.
std::string volumeScene(const std::string& statement, const std::string& parameter) {
  return "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
         "WorldBegin\n" +
         statement + "\n  " + parameter +
         "\n"
         "LightSource \"point\" \"point from\" [0 0 -1]\n"
         "Shape \"sphere\" \"float radius\" [0.5]\n"
         "WorldEnd\n";
}

void expectLocatedError(const std::string& statement, const std::string& parameter,
                        const std::string& mention, int line = 4) {
  SCOPED_TRACE(statement + " " + parameter);
  try {
    test::buildSceneText(volumeScene(statement, parameter));
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find(mention), std::string::npos) << e.what();
  }
}

TEST(VolumeRegions, BadParametersAreLocatedErrors) {
  expectLocatedError("Volume \"homogeneous\"", "\"rgb sigma_a\" [0.1 -0.2 0.1]", "sigma_a");
  expectLocatedError("Volume \"exponential\"", "\"color sigma_s\" [-1 0 0]", "sigma_s");
  expectLocatedError("Volume \"homogeneous\"", "\"float g\" [1]", "g");
  expectLocatedError("Volume \"homogeneous\"", "\"string phase\" [\"cardioid\"]", "phase");
  expectLocatedError("Volume \"homogeneous\"", "\"point p1\" [1 0 1]", "p1");
  expectLocatedError("Volume \"exponential\"", "\"vector updir\" [0 0 0]", "updir");
  expectLocatedError("Volume \"volumegrid\"", "\"integer nx\" [2] \"float density\" [1 2 3]",
                     "density");
  expectLocatedError("Volume \"volumegrid\"", "\"integer nx\" [0]", "nx");
  expectLocatedError("Volume \"volumegrid\"", "\"integer nz\" [-3]", "nz");
  expectLocatedError("Volume \"volumegrid\"", "\"float density\" [-1]", "density");
  // The unknown name is at the statement.
  expectLocatedError("\n Volume \"fog\"", "", "fog", 4);
}

TEST(VolumeRegions, SceneWithoutVolumesBuildsNone) {
  test::RenderedScene none = test::buildSceneText(volumeScene("", ""));
  EXPECT_EQ(none.job().scene->volume(), nullptr);
  EXPECT_EQ(none.job().volumeIntegrator, nullptr);
  test::RenderedScene one =
      test::buildSceneText(volumeScene("Volume \"homogeneous\"", "\"rgb sigma_s\" [1 1 1]"));
  ASSERT_NE(one.job().scene->volume(), nullptr);
  EXPECT_NE(one.job().volumeIntegrator, nullptr);  // pbrt-v2's default, "emission"
  test::RenderedScene two = test::buildSceneText(volumeScene(
      "Volume \"homogeneous\" \"rgb sigma_s\" [1 1 1]\nVolume \"exponential\"", "\"float a\" [2]"));
  EXPECT_NE(dynamic_cast<const AggregateVolume*>(two.job().scene->volume()), nullptr);
}

TEST(VolumeRegions, StatementsUseTheirTransformAndPhaseSelection) {
  // The region's box is in the coordinate system of the CTM at its statement.
  test::RenderedScene built = test::buildSceneText(volumeScene(
      "AttributeBegin\nTranslate 5 0 0\nScale 2 2 2\nVolume \"homogeneous\"",
      "\"rgb sigma_s\" [1 2 3] \"string phase\" \"schlick\" \"float g\" [0.5]\nAttributeEnd"));
  const Medium* v = built.job().scene->volume();
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->at(Point3f(6.9f, 1.9f, 1.9f), 0).sigmaS, Spectrum(1, 2, 3));
  EXPECT_TRUE(v->at(Point3f(0.5f, 0.5f, 0.5f), 0).sigmaS.isBlack());
  EXPECT_EQ(v->phase(Point3f(6, 1, 1), 0).kind(), PhaseFunction::Kind::Schlick);
  EXPECT_FLOAT_EQ(v->phase(Point3f(6, 1, 1), 0).g(), 0.5f);
  for (auto [name, kind] : {std::pair{"isotropic", PhaseFunction::Kind::Isotropic},
                            std::pair{"rayleigh", PhaseFunction::Kind::Rayleigh},
                            std::pair{"mie-hazy", PhaseFunction::Kind::MieHazy},
                            std::pair{"mie-murky", PhaseFunction::Kind::MieMurky},
                            std::pair{"hg", PhaseFunction::Kind::HenyeyGreenstein}}) {
    test::RenderedScene one = test::buildSceneText(
        volumeScene("Volume \"exponential\"", std::string("\"string phase\" \"") + name + "\""));
    EXPECT_EQ(one.job().scene->volume()->phase(Point3f(0.5f, 0.5f, 0.5f), 0).kind(), kind) << name;
  }
}

// Integrators whose photons, gather rays or light subpaths cross the volume unattenuated say so
// at the Volume statement; those that attenuate every ray (and volpath) do not.
TEST(VolumeRegions, IntegratorsThatAttenuateOnlyPartOfTheirRaysWarn) {
  auto warningsFor = [](const std::string& integrator) {
    std::string warnings;
    BuildOptions options;
    options.warn = [&](const FileLoc& loc, const std::string& m) {
      warnings += std::to_string(loc.line) + ": " + m + "\n";
    };
    test::buildSceneText("SurfaceIntegrator " + integrator + "\n" +
                             volumeScene("Volume \"homogeneous\"", "\"rgb sigma_s\" [1 1 1]"),
                         options);
    return warnings;
  };
  for (const char* partial :
       {"\"bdpt\"", "\"photonmap\"", "\"irradiancecache\"", "\"igi\"", "\"ambientocclusion\""}) {
    std::string w = warningsFor(partial);
    EXPECT_NE(w.find("4: Volume regions attenuate only the camera rays"), std::string::npos)
        << partial << ": " << w;
  }
  for (const char* full : {"\"path\"", "\"directlighting\"", "\"whitted\"", "\"volpath\""})
    EXPECT_EQ(warningsFor(full).find("Volume regions attenuate only"), std::string::npos) << full;
}

}  // namespace
}  // namespace candela
