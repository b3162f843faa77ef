// Extreme triangles (issue 15): slivers of aspect 1e6 and triangles 2e9 across. A hit's point,
// barycentrics and normal are checked against the exact crossing of the float ray with the
// float triangle (long double), under Embree and the books' accelerators; the huge triangle
// renders its closed form under a point light, level and tilted. Triangles of zero area get a
// warning naming the statement; degenerate transformations are errors at their statement.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "accel/aggregate_factory.h"
#include "core/error.h"
#include "exact_ray_geometry.h"
#include "plane_under_light.h"
#include "scene_files.h"
#include "shape_zoo.h"
#include "support/render_scene.h"
#include "support/robustness_figures.h"
#include "support/test_device.h"

namespace candela {
namespace {

using namespace test::exact;

const char* const kAccelerators[] = {"embree", "bvh", "kdtree", "grid"};

struct HitFigures {
  long rays = 0, hits = 0, outsideBound = 0;
  // |p - x| in float steps at x, less the rounding of the double arithmetic that computes it
  // (2^-50 of the vertices' magnitude: 9e-7 for vertices at 1e9)
  double worstPoint = 0;
  double worstBary = 0;    // |b - b exact|
  double worstNormal = 0;  // radians between the hit's normal and the exact one
};

// Rays along the triangle's normal from one size away, through points with every barycentric
// >= minB; when nearDistance is set, from that distance through points within 1 of the origin
// instead (for a triangle around it).
HitFigures perpendicularHits(const std::array<Point3f, 3>& v, const Aggregate& agg, Real minB,
                             Real nearDistance, int nRays, uint64_t seed) {
  bool near = nearDistance > 0;
  Random rnd(seed);
  Vec p[3] = {of(v[0]), of(v[1]), of(v[2])};
  Vec n = unit(cross(p[1] - p[0], p[2] - p[0]));
  Real size = std::max({length(p[1] - p[0]), length(p[2] - p[1]), length(p[0] - p[2])});
  Vec s = rnd.perpendicularTo(n), t = cross(n, s);
  Real magnitude = 0;
  for (const Vec& q : p)
    magnitude = std::max({magnitude, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
  HitFigures f;
  for (int i = 0; i < nRays; ++i) {
    Vec x;
    if (near) {
      // The origin's projection on the plane, moved by up to 1 within it.
      Vec foot = n * dot(p[0], n);
      x = foot + s * (2 * rnd.uniform() - 1) + t * (2 * rnd.uniform() - 1);
    } else {
      Real u1 = rnd.uniform(), u2 = rnd.uniform();
      if (u1 + u2 > 1) u1 = 1 - u1, u2 = 1 - u2;
      Real b1 = minB + (1 - 3 * minB) * u1, b2 = minB + (1 - 3 * minB) * u2;
      x = p[0] + (p[1] - p[0]) * b1 + (p[2] - p[0]) * b2;
    }
    Real side = rnd.uniform() < 0.5L ? 1 : -1, distance = near ? nearDistance : size;
    Ray ray(toPoint(x + n * (side * distance)), toVector(n * -side));
    TriangleTruth tt = truth(v, ray);
    SurfaceInteraction si;
    ++f.rays;
    if (!agg.intersect(ray, &si)) continue;
    ++f.hits;
    Vec err = of(si.p) - tt.x;
    Real xMax = std::max({std::abs(tt.x.x), std::abs(tt.x.y), std::abs(tt.x.z)});
    Real xStep = std::ldexp(Real(1), std::ilogb(double(xMax)) - 23);
    Real e = std::max({std::abs(err.x), std::abs(err.y), std::abs(err.z)});
    f.worstPoint =
        std::max(f.worstPoint, double(std::max(Real(0), e - 0x1p-50L * magnitude) / xStep));
    f.outsideBound += std::abs(err.x) > si.pError.x || std::abs(err.y) > si.pError.y ||
                      std::abs(err.z) > si.pError.z;
    // (u, v) = (b1, b2): the vertices' uvs are (0, 0), (1, 0), (0, 1).
    f.worstBary = std::max(
        {f.worstBary, double(std::abs(si.uv.x - tt.b[1])), double(std::abs(si.uv.y - tt.b[2]))});
    Real c = std::min(Real(1), std::abs(dot(unit(of(Vector3f(si.n))), n)));
    f.worstNormal = std::max(f.worstNormal, double(std::acos(c)));
  }
  return f;
}

struct TriangleCase {
  std::string name;
  Transform t;
  std::vector<Point3f> p;
  Real nearDistance;  // > 0: rays from this far to near the origin; 0: through the interior
  bool everyRayHits;  // the rays pass more than 8 float steps inside
};

std::string summary(const std::string& name, const char* accel, const HitFigures& f) {
  char s[200];
  std::snprintf(s, sizeof s, "%s, %s: %ld/%ld hit, point %.2g steps, barycentrics %.2g",
                name.c_str(), accel, f.hits, f.rays, f.worstPoint, f.worstBary);
  return s;
}

// The hit point is the float nearest the exact crossing (half a step, beyond the rounding of
// the double arithmetic that finds it: 9e-7 for vertices at 1e9), the barycentrics agree
// to float rounding and the normal to 1e-6 rad, and the point's error bound holds. Before the
// hit's barycentrics were recomputed in double, Embree's hit points on the rotated sliver were
// 4e5 steps (0.05 of its length) off, and on the huge triangle near the origin tens of units.
// Rays along an axis through an axis-aligned sliver all hit (the watertight test's error bound
// took the shear it had not done into account, and rejected 77% of them).
TEST(ExtremeTriangles, HitsOnSliversAndHugeTrianglesAreAsPreciseAsFloats) {
  const std::vector<Point3f> sliver = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1e-6f, 0}};
  const std::vector<Point3f> huge = {{-1e9f, -1e9f, 0}, {1e9f, -1e9f, 0}, {0, 1e9f, 0}};
  const std::vector<TriangleCase> cases = {
      {"sliver 1 x 1e-6, axis-aligned", Transform(), sliver, 0, true},
      {"sliver 1e4 x 1e-2, axis-aligned", scale(1e4f, 1e4f, 1e4f), sliver, 0, true},
      // Rotated, a sliver is about 8 float steps wide: no ray is 8 steps inside.
      {"sliver, rotated", test::placements()[0].t, sliver, 0, false},
      {"sliver 1e4 x 1e-2, rotated", test::placements()[3].t, sliver, 0, false},
      {"2e9 across, level, rays from 1", Transform(), huge, 1, true},
      // Tilted, its vertices' coordinates relative to a ray's origin round by 64 (the float
      // step at 1e9), so Embree and the watertight test see its plane only to about 100 near
      // the origin: rays from 1e4 (from 1, Embree hits half of them and the watertight test
      // none).
      {"2e9 across, rotated, rays from 1e4", test::placements()[0].t, huge, 1e4, true}};
  std::string figures;
  double worstPoint = 0, worstBary = 0;
  for (const TriangleCase& c : cases) {
    TriangleMesh mesh(c.t, false, {0, 1, 2}, c.p, {}, {}, {{0, 0}, {1, 0}, {0, 1}});
    auto shapes = createTriangleShapes(&mesh);
    std::vector<Primitive> prims = {Primitive{shapes[0].get(), nullptr, nullptr}};
    std::array<Point3f, 3> v = {mesh.p[0], mesh.p[1], mesh.p[2]};
    for (const char* accel : kAccelerators) {
      SCOPED_TRACE(c.name + ", " + accel);
      auto agg = createAggregate(accel, {}, prims, test::embreeDevice(), FileLoc{});
      HitFigures f = perpendicularHits(v, *agg, 0.01L, c.nearDistance, 5000, 5);
      if (c.everyRayHits) {
        EXPECT_EQ(f.hits, f.rays);
      }
      EXPECT_LE(f.worstPoint, 0.51);
      EXPECT_LE(f.worstBary, 1e-7);
      EXPECT_LE(f.worstNormal, 1e-6);
      EXPECT_EQ(f.outsideBound, 0);
      std::printf("%s, normal %.2g rad\n", summary(c.name, accel, f).c_str(), f.worstNormal);
      worstPoint = std::max(worstPoint, f.worstPoint);
      worstBary = std::max(worstBary, f.worstBary);
      if (!c.everyRayHits && c.name == "sliver, rotated" &&
          (std::string(accel) == "embree" || std::string(accel) == "bvh"))
        figures += "; " + c.name + ", " + accel + ": " + std::to_string(f.hits) + "/" +
                   std::to_string(f.rays) + " hit";
    }
  }
  char measured[96];
  std::snprintf(measured, sizeof measured, "worst point %.2g float steps, barycentrics %.2g",
                worstPoint, worstBary);
  test::recordFigure(
      "slivers (aspect 1e6) and 2e9 triangles, rays along the normal, 4 "
      "accelerators: hit point within half a float step of the exact crossing, "
      "barycentrics within 1e-7; axis-aligned slivers: every ray hits",
      measured + figures);
}

// ---- The huge triangle under a point light -----------------------------------------------------

TEST(ExtremeTriangles, A2e9TriangleUnderAPointLightRendersItsClosedForm) {
  const std::string level = test::robustnessScene("huge-plane.pbrt");
  // Tilted, the triangle's plane is resolved only to about 100 near the origin (see above): the
  // same view 1e4 times larger (camera, window, the light's height, and its intensity by 1e8, so
  // that the radiance at corresponding points is the same), turned by 35 degrees about
  // (1, 1, 0.3) with the triangle.
  Transform r = rotate(35, Vector3f(1, 1, 0.3f));
  std::string tilted = level;
  Point3f eye = r(Point3f(0, 0, 5e4f));
  Vector3f up = r(Vector3f(0, 1, 0));
  std::ostringstream look;
  look.precision(9);
  look << "LookAt " << eye.x << " " << eye.y << " " << eye.z << "  0 0 0  " << up.x << " " << up.y
       << " " << up.z;
  test::replaceOnce(&tilted, "LookAt 0 0 5  0 0 0  0 1 0", look.str());
  test::replaceOnce(&tilted, "[-2 2 -2 2]", "[-2e4 2e4 -2e4 2e4]");
  test::replaceOnce(&tilted, "\"point from\" [0 0 1] \"rgb I\" [1 1 1]",
                    "\"point from\" [0 0 1e4] \"rgb I\" [1e8 1e8 1e8]");
  test::replaceOnce(&tilted, "WorldBegin\n", "WorldBegin\nRotate 35 1 1 0.3\n");
  double worst = 0;
  for (const auto& [what, text] : {std::pair{"level", level}, std::pair{"tilted", tilted}})
    for (const char* accel : {"embree", "bvh"}) {
      test::TestRenderOptions options;
      options.build.accelerator = accel;
      worst = std::max(worst, test::worstPixelAgainstClosedForm(
                                  test::renderSceneText(text, options).film(),
                                  test::PlaneUnderLight{}, std::string(what) + ", " + accel));
    }
  test::recordFigure(
      "2e9 triangle under a point light 1 above it (level) and 1e4 above it "
      "(tilted), embree and bvh: every pixel within 5 standard errors of the "
      "closed form",
      "worst pixel %.2f standard errors from it", worst);
}

// ---- Degenerate input --------------------------------------------------------------------------

const std::string kHead =
    "LookAt 0 0 -5 0 0 0 0 1 0\nCamera \"perspective\" \"float fov\" [40]\n"
    "Film \"image\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"
    "Sampler \"random\" \"integer pixelsamples\" [4]\n";

// Zero-area triangles (a repeated index, collinear points, one vertex thrice) in an emitting mesh:
// the statement gets a warning with the count, they make no light, and every integrator
// renders finite.
TEST(ExtremeTriangles, ZeroAreaTrianglesAreSkippedWithAWarningNamingTheStatement) {
  const std::string world =
      "WorldBegin\nAttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [4 4 4]\n"
      "Shape \"trianglemesh\" \"integer indices\" [0 1 2  0 0 1  3 4 5  1 1 1]\n"
      "  \"point P\" [-1 -1 -2  1 -1 -2  0 1 -2  0 0 -2  1 1 -2  2 2 -2]\n"
      "AttributeEnd\nShape \"sphere\"\nWorldEnd\n";
  long lights = -1;
  int reported = 0;
  for (const char* integrator :
       {"SurfaceIntegrator \"path\"", "SurfaceIntegrator \"bidirectional\"",
        "SurfaceIntegrator \"photonmap\" \"integer causticphotons\" [1000] "
        "\"integer indirectphotons\" [1000] \"integer directphotons\" [1000] "
        "\"bool finalgather\" \"false\"",
        "Integrator \"volpath\""}) {
    SCOPED_TRACE(integrator);
    std::vector<std::string> warnings;
    test::TestRenderOptions options;
    options.build.warn = [&](const FileLoc& loc, const std::string& message) {
      warnings.push_back(loc.str() + ": " + message);
    };
    test::RenderedScene r = test::renderSceneText(kHead + integrator + "\n" + world, options);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0],
              "test.pbrt:9:1: shape 'trianglemesh': 3 of 4 triangles have zero area or a "
              "non-finite vertex; they are skipped (never hit, no light)");
    reported += warnings.size();
    lights = r.job().stats.areaLights;
    EXPECT_EQ(lights, 1);
    EXPECT_EQ(r.results.front().nonFiniteSamples, 0u);
    for (float v : r.film().image().data) ASSERT_TRUE(std::isfinite(v));
  }
  test::recordFigure(
      "a mesh with 3 zero-area triangles of 4, as an area light, under 4 "
      "integrators: one warning at its statement, 1 light, no non-finite sample",
      "1 warning in each of " + std::to_string(reported) + " renders, " + std::to_string(lights) +
          " light, 0 non-finite");
}

// What pbrt-v3 reports for a singular matrix (and then renders with infinities) is here an error
// at the statement, in the world, in an object and before the camera; a transformation that
// only flattens (scale 1e-30 along z) is invertible and renders finite.
TEST(ExtremeTriangles, DegenerateTransformationsAreErrorsAtTheirStatement) {
  const std::string world = "WorldBegin\nLightSource \"point\" \"rgb I\" [10 10 10]\n";
  const std::pair<std::string, std::string> cases[] = {
      {world + "Scale 0 0 0\nShape \"sphere\"\nWorldEnd\n", "test.pbrt:7:1"},
      {world + "AttributeBegin\n  Scale 1 0 1\nShape \"sphere\"\nAttributeEnd\nWorldEnd\n",
       "test.pbrt:8:3"},
      {world + "ConcatTransform [1 0 0 0  0 1 0 0  1 1 0 0  0 0 0 1]\nShape \"sphere\"\n"
               "WorldEnd\n",
       "test.pbrt:7:1"},
      {world + "ObjectBegin \"a\"\nTransform [0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0]\nObjectEnd\n"
               "WorldEnd\n",
       "test.pbrt:8:1"},
  };
  int located = 0;
  for (const auto& [text, loc] : cases) {
    try {
      test::renderSceneText(kHead + text);
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const SceneError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(loc + ": error: invalid transformation", 0), 0u)
          << e.what();
      located += std::string(e.what()).rfind(loc, 0) == 0;
    }
  }
  try {
    test::renderSceneText("Scale 0 1 1\n" + kHead + world + "WorldEnd\n");
    ADD_FAILURE() << "no error for a singular camera transformation";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("test.pbrt:1:1: error: invalid transformation", 0), 0u)
        << e.what();
  }
  test::RenderedScene flat =
      test::renderSceneText(kHead + world + "Scale 1 1 1e-30\nShape \"sphere\"\nWorldEnd\n");
  for (float v : flat.film().image().data) ASSERT_TRUE(std::isfinite(v));
  test::recordFigure(
      "Scale 0 0 0, Scale 1 0 1, a rank-2 ConcatTransform, a zero Transform in an "
      "object: error at file:line:col; Scale 1 1 1e-30 renders finite",
      std::to_string(located) + " of 4 located");
}

}  // namespace
}  // namespace candela
