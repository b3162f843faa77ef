// pbrt-v3's "realistic" camera (pbrt 3e §6.4): tracing through the lens elements against the
// thick-lens closed forms of a symmetric biconvex lens, focusing, the aperture stop, the exit
// pupil's bounds, the film's exposure, renders and located errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "cameras/camera.h"
#include "cameras/exit_pupil.h"
#include "cameras/lens_file.h"
#include "cameras/lens_system.h"
#include "cameras/realistic_camera.h"
#include "core/error.h"
#include "core/rng.h"
#include "support/geometry_expect.h"
#include "support/param_items.h"
#include "support/parameter_errors.h"
#include "support/render_scene.h"
#include "support/temp_dir.h"

namespace candela {
namespace {

const std::string kLenses = CANDELA_TEST_DATA_DIR "/lenses/";

// tests/data/lenses/biconvex.dat: a stop 2 mm in front of a lens of radii +-50 mm, 5 mm thick,
// n = 1.5. Its thick-lens figures from the lensmaker's equation (metres).
struct Biconvex {
  static constexpr double n = 1.5, R = 0.050, t = 0.005, stopGap = 0.002;
  // 1/f = (n - 1) (1/R1 - 1/R2 + (n - 1) t / (n R1 R2)) with R1 = R, R2 = -R.
  double f = 1 / ((n - 1) * (2 / R - (n - 1) * t / (n * R * R)));
  // Each principal plane lies f (n - 1) t / (n R) inside its vertex.
  double hInside = f * (n - 1) * t / (n * R);
};

// Where the ray crosses the plane z = z0.
LensVector atPlane(const LensRay& r, double z0) { return r.at((z0 - r.o.z) / r.d.z); }

TEST(RealisticCamera, LensFileReadsInterfacesInMetres) {
  std::vector<LensInterface> lens = readLensFile(kLenses + "biconvex.dat");
  ASSERT_EQ(lens.size(), 3u);
  EXPECT_TRUE(lens[0].isStop());
  EXPECT_DOUBLE_EQ(lens[0].eta, 1);  // the stop's 0 is air
  EXPECT_DOUBLE_EQ(lens[0].apertureRadius, 0.008);
  EXPECT_DOUBLE_EQ(lens[1].curvatureRadius, 0.050);
  EXPECT_DOUBLE_EQ(lens[1].thickness, 0.005);
  EXPECT_DOUBLE_EQ(lens[1].eta, 1.5);
  EXPECT_DOUBLE_EQ(lens[2].curvatureRadius, -0.050);
}

TEST(RealisticCamera, ThickLensMatchesTheLensmakersEquation) {
  Biconvex b;
  LensSystem lens(readLensFile(kLenses + "biconvex.dat"));
  lens.setFilmDistance(0.060);
  ThickLens t = lens.thickLens();
  EXPECT_NEAR(t.focalLength, b.f, 1e-9);
  double rearVertex = -0.060, frontVertex = rearVertex - b.t;
  EXPECT_NEAR(t.principalFilm, rearVertex - b.hInside, 1e-9);
  EXPECT_NEAR(t.principalScene, frontVertex + b.hInside, 1e-9);
  EXPECT_NEAR(t.focalPointFilm, t.principalFilm + b.f, 1e-9);
  EXPECT_NEAR(t.focalPointScene, t.principalScene - b.f, 1e-9);
}

// Rays from one film point, through a small part of the lens, meet again where the Gaussian lens
// equation 1/s + 1/s' = 1/f puts the conjugate point (distances from the principal planes),
// at the lateral magnification -s/s'.
TEST(RealisticCamera, RaysFromAFilmPointConvergeAtTheConjugatePoint) {
  Biconvex b;
  const double d = 0.060;  // film distance
  LensSystem lens(readLensFile(kLenses + "biconvex.dat"));
  lens.setFilmDistance(d);
  double zH2 = -d - b.hInside, zH = -d - b.t + b.hInside;
  double sImage = -zH2, sObject = 1 / (1 / b.f - 1 / sImage);
  double zObject = zH - sObject;
  RNG rng(11);
  for (double xFilm : {0.0, 0.002}) {
    SCOPED_TRACE(xFilm);
    LensVector pFilm{xFilm, 0, 0};
    double expectedX = -xFilm * sObject / sImage;
    int traced = 0;
    for (int i = 0; i < 200; ++i) {
      // Through a disc of radius 0.3 mm on the rear vertex's plane: near-paraxial rays.
      double a = 2 * M_PI * rng.uniformFloat(), rho = 3e-4 * std::sqrt(rng.uniformFloat());
      LensVector pRear{rho * std::cos(a), rho * std::sin(a), -d};
      LensRay out;
      ASSERT_TRUE(lens.traceFromFilm({pFilm, pRear - pFilm}, &out));
      LensVector p = atPlane(out, zObject);
      // Spherical aberration of such rays is (0.3 mm / f)^2 ~ 4e-5 of the conjugate distance.
      EXPECT_NEAR(p.x, expectedX, 2e-4 * sObject);
      EXPECT_NEAR(p.y, 0, 2e-4 * sObject);
      ++traced;
    }
    EXPECT_EQ(traced, 200);
  }
}

RealisticCameraOptions biconvexOptions(double focus, double apertureMm) {
  RealisticCameraOptions o;
  o.fullResolution = {32, 32};
  o.lens = readLensFile(kLenses + "biconvex.dat");
  o.focusDistance = focus;
  o.apertureDiameter = apertureMm * 1e-3;
  return o;
}

RealisticCameraOptions dgaussOptions(double focus, double apertureMm, int res = 32) {
  RealisticCameraOptions o;
  o.fullResolution = {res, res};
  o.lens = readLensFile(kLenses + "dgauss50.dat");
  o.focusDistance = focus;
  o.apertureDiameter = apertureMm * 1e-3;
  return o;
}

// RMS distance from the axis where rays from the film centre, sampled over the exit pupil, cross
// the plane z = -distance.
double spreadAt(const RealisticCamera& cam, double distance) {
  RNG rng(5);
  double sum = 0;
  int n = 0;
  for (int i = 0; i < 4000; ++i) {
    double area;
    LensVector pRear = cam.exitPupil().sample(0, 0, rng.uniformFloat(), rng.uniformFloat(), &area);
    LensRay out;
    if (!cam.lens().traceFromFilm({{0, 0, 0}, pRear}, &out)) continue;
    LensVector p = atPlane(out, -distance);
    sum += p.x * p.x + p.y * p.y;
    ++n;
  }
  EXPECT_GT(n, 1000);
  return std::sqrt(sum / n);
}

TEST(RealisticCamera, FocusDistanceSetsTheFilmWhereThatPlaneIsSharp) {
  Biconvex b;
  const double D = 1.0;
  RealisticCamera cam(AnimatedTransform(Transform()), biconvexOptions(D, 1));
  // Closed form: the object D from the film, s + s' = D - t + 2 hInside whatever the film
  // distance, and s' = d + hInside.
  double L = D - b.t + 2 * b.hInside;
  double sImage = 0.5 * (L - std::sqrt(L * (L - 4 * b.f)));
  EXPECT_NEAR(cam.lens().filmDistance(), sImage - b.hInside, 1e-8);
  double sharp = spreadAt(cam, D);
  EXPECT_LT(sharp, 0.1 * spreadAt(cam, 0.8 * D));
  EXPECT_LT(sharp, 0.1 * spreadAt(cam, 1.25 * D));
}

TEST(RealisticCamera, DoubleGaussFocusesAtFiftyMillimetres) {
  LensSystem lens(readLensFile(kLenses + "dgauss50.dat"));
  // The prescription is scaled to a 50 mm focal length; it is given to 4-5 figures.
  EXPECT_NEAR(lens.thickLens().focalLength, 0.050, 0.0015);
  for (double D : {0.5, 2.0, 10.0}) {
    SCOPED_TRACE(D);
    RealisticCamera cam(AnimatedTransform(Transform()), dgaussOptions(D, 2));
    double sharp = spreadAt(cam, D);
    EXPECT_LT(sharp, 0.2 * spreadAt(cam, 0.8 * D));
    EXPECT_LT(sharp, 0.2 * spreadAt(cam, 1.25 * D));
  }
}

// The fraction of camera rays that get through, over film points across the image.
double passingFraction(const RealisticCamera& cam, int res, bool centreOnly) {
  RNG rng(9);
  int passed = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    Float x = centreOnly ? res / 2.f : rng.uniformFloat() * res;
    Float y = centreOnly ? res / 2.f : rng.uniformFloat() * res;
    Ray r;
    Float w = cam.generateRay(
        test::cameraSample(x, y, Point2f(rng.uniformFloat(), rng.uniformFloat())), &r);
    EXPECT_TRUE(w >= 0 && std::isfinite(w));
    if (w > 0) ++passed;
  }
  return double(passed) / n;
}

TEST(RealisticCamera, ApertureStopBlocksRays) {
  RealisticCamera tiny(AnimatedTransform(Transform()), dgaussOptions(2, 0.001));
  EXPECT_LT(passingFraction(tiny, 32, true), 1e-3);
  EXPECT_LT(passingFraction(tiny, 32, false), 1e-3);
  RealisticCamera open(AnimatedTransform(Transform()), dgaussOptions(2, 8));
  // A disc in its bounding square covers pi/4 of it.
  EXPECT_GT(passingFraction(open, 32, true), 0.6);
}

// Every ray from the film that passes the lens goes through the pupil bounds of its film
// point's radial interval: film points and rear-plane points sampled at random, the latter over
// twice the square the bounds are searched in.
void expectBoundsContainPassingRays(const RealisticCameraOptions& o) {
  RealisticCamera cam(AnimatedTransform(Transform()), o);
  const LensSystem& lens = cam.lens();
  const ExitPupil& pupil = cam.exitPupil();
  double filmRadius = o.filmDiagonal / 2, half = 3 * lens.rearApertureRadius();
  RNG rng(21);
  long passed = 0, outside = 0;
  for (int i = 0; i < 300; ++i) {
    double r = filmRadius * rng.uniformFloat(), a = 2 * M_PI * rng.uniformFloat();
    double c = std::cos(a), s = std::sin(a);
    LensVector pFilm{r * c, r * s, 0};
    const PupilBounds& b = pupil.boundsAt(r);
    for (int k = 0; k < 3000; ++k) {
      double x = half * (2 * rng.uniformFloat() - 1), y = half * (2 * rng.uniformFloat() - 1);
      if (!lens.traceFromFilm({pFilm, LensVector{x, y, lens.rearZ()} - pFilm}, nullptr)) continue;
      ++passed;
      // Turned back to the film point on +x.
      if (!b.contains(c * x + s * y, -s * x + c * y)) ++outside;
    }
  }
  EXPECT_GT(passed, 5000);
  EXPECT_EQ(outside, 0) << "of " << passed;
}

TEST(RealisticCamera, ExitPupilBoundsContainEveryPassingRay) {
  {
    SCOPED_TRACE("double Gauss wide open");
    expectBoundsContainPassingRays(dgaussOptions(2, 17.1));
  }
  {
    SCOPED_TRACE("double Gauss at 6 mm");
    expectBoundsContainPassingRays(dgaussOptions(2, 6));
  }
  {
    SCOPED_TRACE("biconvex");
    expectBoundsContainPassingRays(biconvexOptions(1, 12));
  }
}

TEST(RealisticCamera, ImageIsUprightAndLooksDownPlusZ) {
  Transform toWorld = translate(Vector3f(1, 2, 3));
  RealisticCamera cam(AnimatedTransform(toWorld), dgaussOptions(2, 4));
  Ray r;
  ASSERT_GT(cam.generateRay(test::cameraSample(16, 16), &r), 0);
  EXPECT_GT(r.d.z, 0.999f);
  // The ray leaves the front element, in front of the camera's position.
  EXPECT_GT(r.o.z, 3.f);
  EXPECT_NEAR(r.o.x, 1, 0.02f);
  // The top-left pixel sees up and to camera -x, as the perspective camera's does.
  Float w = 0;
  for (int i = 0; i < 64 && w == 0; ++i)
    w = cam.generateRay(
        test::cameraSample(0.5f, 0.5f, Point2f((i % 8 + 0.5f) / 8, (i / 8 + 0.5f) / 8)), &r);
  ASSERT_GT(w, 0);
  EXPECT_LT(r.d.x, 0);
  EXPECT_GT(r.d.y, 0);
}

// A sky of radiance 1 seen through the camera (16 x 16 pixels, 256 samples each): the scene
// text for an aperture, weighting, lens file and film diagonal (mm).
std::string skyScene(double apertureMm, bool simple, const std::string& lens = "dgauss50.dat",
                     double diagonal = 35) {
  return "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16] "
         "\"float diagonal\" [" +
         std::to_string(diagonal) +
         "]\n"
         "Sampler \"stratified\" \"integer xsamples\" [16] \"integer ysamples\" [16]\n"
         "Camera \"realistic\" \"string lensfile\" \"" +
         kLenses + lens + "\" \"float aperturediameter\" [" + std::to_string(apertureMm) +
         "] \"float focusdistance\" [3] \"bool simpleweighting\" \"" + (simple ? "true" : "false") +
         "\"\n"
         "SurfaceIntegrator \"directlighting\"\n"
         "WorldBegin\n"
         "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
         "WorldEnd\n";
}

test::RenderedScene renderSky(const std::string& scene, int threads) {
  test::TestRenderOptions o;
  o.build.seed = 3;
  o.render.nThreads = threads;
  o.render.tileSize = 8;
  return test::renderSceneText(scene, o);
}

// The mean of the central 4 x 4 pixels' first channel.
double centre(const ImageBuffer& img) {
  double sum = 0;
  for (int y = 6; y < 10; ++y)
    for (int x = 6; x < 10; ++x) sum += img.at(x, y, 0);
  return sum / 16;
}

TEST(RealisticCamera, RenderIsFiniteAndDeterministic) {
  std::string scene = skyScene(8, true);
  ImageBuffer one = renderSky(scene, 1).film().image();
  ImageBuffer two = renderSky(scene, 2).film().image();
  ASSERT_EQ(one.data.size(), two.data.size());
  EXPECT_EQ(0, std::memcmp(one.data.data(), two.data.data(), one.data.size() * sizeof(float)));
  for (float v : one.data) ASSERT_TRUE(std::isfinite(v));
  EXPECT_GT(centre(one), 0.3);
}

// Without simple weighting a pixel is the film's exposure, shutter time x irradiance: for the
// film centre under a uniform sky, pi L sin²(alpha) for the cone of half-angle alpha the exit
// pupil subtends. The exit pupil is the stop's paraxial image in the lens behind it, so it and
// the exposure grow with the stop's area.
TEST(RealisticCamera, ExposureScalesWithApertureArea) {
  double small = centre(renderSky(skyScene(4, false), 2).film().image());
  double large = centre(renderSky(skyScene(8, false), 2).film().image());
  // 4096 camera rays over the 16 centre pixels passing at a rate near pi/4: even unstratified
  // the mean's relative standard deviation is 0.8% (the ratio's 1.1%); the pupil's aberrations
  // and the cos^4 falloff across it differ by under 1% between the two apertures.
  EXPECT_NEAR(large / small, 4.0, 0.12);

  // Simple weighting normalises by the pupil bounds at the centre: near 1 for either aperture.
  double simpleSmall = centre(renderSky(skyScene(4, true), 2).film().image());
  double simpleLarge = centre(renderSky(skyScene(8, true), 2).film().image());
  EXPECT_NEAR(simpleLarge / simpleSmall, 1.0, 0.1);
}

TEST(RealisticCamera, CentreExposureMatchesThePupilsSolidAngle) {
  Biconvex b;
  const double apertureMm = 4;
  // A 3.5 mm film: the centre pixels lie within 0.5 degrees of the axis (cos^4 > 0.9999).
  test::RenderedScene s = renderSky(skyScene(apertureMm, false, "biconvex.dat", 3.5), 2);
  double measured = centre(s.film().image());
  // The film distance the camera chose, checked against the closed form above.
  const auto* cam = dynamic_cast<const RealisticCamera*>(s.job().camera.get());
  ASSERT_NE(cam, nullptr);
  double d = cam->lens().filmDistance();
  // The stop, stopGap + hInside in front of H, imaged by the lens: a virtual image s' (< 0) from
  // H', magnified -s'/s.
  double sObject = b.stopGap + b.hInside;
  double sImage = 1 / (1 / b.f - 1 / sObject);
  double pupilRadius = 0.5e-3 * apertureMm * (-sImage / sObject);
  double Z = d + b.hInside - sImage;  // film to exit pupil
  double expected = M_PI * pupilRadius * pupilRadius / (Z * Z + pupilRadius * pupilRadius);
  // Noise as above: a relative standard deviation of 0.8% at most (2.5 of them).
  EXPECT_NEAR(measured / expected, 1.0, 0.02) << measured << " vs " << expected;
}

TEST(RealisticCamera, BadInputIsLocated) {
  std::string lens = "Camera \"realistic\" \"string lensfile\" \"" + kLenses + "biconvex.dat\"";
  test::expectParameterErrorsLocated(
      lens, {"\"float aperturediameter\" [-1]", "\"float aperturediameter\" [0]",
             "\"float focusdistance\" [-2]", "\"float focusdistance\" [0.1]"});
  // The lens file: missing (named with its path), malformed (file:line), not given at all.
  auto errorOf = [](const std::string& statement, const std::string& parameter) {
    try {
      test::buildSceneText(test::parameterScene(statement, parameter));
    } catch (const SceneError& e) {
      EXPECT_EQ(e.location().line, 3) << e.what();
      return std::string(e.what());
    }
    ADD_FAILURE() << "no error";
    return std::string();
  };
  std::string missing = kLenses + "no-such-lens.dat";
  EXPECT_NE(
      errorOf("Camera \"realistic\"", "\"string lensfile\" \"" + missing + "\"").find(missing),
      std::string::npos);
  EXPECT_NE(errorOf("Camera \"realistic\"", "\"string lensfile\" \"" + kLenses + "malformed.dat\"")
                .find("malformed.dat:3"),
            std::string::npos);
  // No lensfile: at the Camera statement (line 2).
  try {
    test::buildSceneText(test::parameterScene("Camera \"realistic\"", ""));
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 2) << e.what();
    EXPECT_NE(std::string(e.what()).find("lensfile"), std::string::npos) << e.what();
  }
  // The Film's diagonal.
  try {
    test::buildSceneText("Film \"image\"\n  \"float diagonal\" [-35]\n" + lens +
                         "\nWorldBegin\nWorldEnd\n");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 2) << e.what();
  }
}

TEST(RealisticCamera, LensFileErrorsNameTheLine) {
  for (auto [file, what] : {std::pair{"malformed.dat", "found 3"},
                            std::pair{"too-wide.dat", "exceeds the sphere's diameter"}}) {
    try {
      readLensFile(kLenses + file);
      ADD_FAILURE() << "no error";
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(file) + ":3"), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  }
}

TEST(RealisticCamera, LensFilesOfMoreThanAThousandInterfacesAreRefusedAtTheLine) {
  TempDir dir("lens_count");
  auto write = [&](int lines) {
    std::string text = "50 5 1.5 20\n";
    for (int i = 1; i < lines; ++i) text += "0 0.001 0 20\n";
    return dir.write("lens" + std::to_string(lines) + ".dat", text);
  };
  EXPECT_EQ(readLensFile(write(1000)).size(), 1000u);
  try {
    readLensFile(write(1001));
    ADD_FAILURE() << "no error";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("lens1001.dat:1001"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("more than 1000 interfaces"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace candela
