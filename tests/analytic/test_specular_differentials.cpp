// Ray differentials carried through specular bounces. On a curved surface (a sphere hit through
// the real shape code, so dndu/dndv and the image-space derivatives are the renderer's own) the
// differentials spawnSpecularRay predicts must match the exactly traced and exactly reflected or
// refracted offset rays to first order; and a surface without a material, which the ray passes
// straight through, must not change what the texture behind it sees.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "accel/primitive.h"
#include "shapes/sphere.h"
#include "support/render_scene.h"
#include "transport/specular_differentials.h"

namespace candela {
namespace {

// The reference is computed in double, so that its own rounding (~1e-16) stays far below the
// second-order errors measured (~1e-6 at the smallest offset).
struct D3 {
  double x, y, z;
};
D3 d3(const Vector3f& v) { return {v.x, v.y, v.z}; }
D3 d3(const Point3f& p) { return {p.x, p.y, p.z}; }
D3 operator+(D3 a, D3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dotD(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double lengthD(D3 a) { return std::sqrt(dotD(a, a)); }
D3 normalizeD(D3 a) { return a * (1 / lengthD(a)); }

const D3 kCentre{0.2, -0.1, 0.3};
constexpr double kRadius = 1.5;

// The nearest hit beyond the origin of the line o + t d (d unit) with the sphere, and the
// outward normal there.
void hitSphere(D3 o, D3 d, D3* p, D3* n) {
  D3 oc = o - kCentre;
  double b = dotD(oc, d), c = dotD(oc, oc) - kRadius * kRadius;
  double s = std::sqrt(b * b - c);
  double t = -b - s > 0 ? -b - s : -b + s;
  *p = o + d * t;
  *n = normalizeD(*p - kCentre);
}

D3 reflectD(D3 d, D3 n) { return d - n * (2 * dotD(d, n)); }

// Snell's law for a unit direction d meeting a surface of normal n (either side) with index
// ratio eta = eta_incident / eta_transmitted; false on total internal reflection.
bool refractD(D3 d, D3 n, double eta, D3* t) {
  if (dotD(d, n) > 0) n = n * -1;
  double cosI = -dotD(d, n);
  double cos2T = 1 - eta * eta * (1 - cosI * cosI);
  if (cos2T <= 0) return false;
  *t = d * eta + n * (eta * cosI - std::sqrt(cos2T));
  return true;
}

enum class Event { Reflect, RefractEnter, RefractLeave };

struct DiffErrors {
  double direction;  // |predicted - exact| / |exact - main|, the worse of x and y
  double origin;     // |predicted - exact hit| / |exact hit - main hit|, likewise
  double minTurn;    // min over x, y of |exact - main|: the offset must be visible
};

// One camera-like ray at the sphere, with an x differential offset in origin by eps (as an
// orthographic camera makes) and a y differential offset in direction by eps (as a perspective
// camera makes), through the sphere shape and spawnSpecularRay; its offset rays against the
// exact ones. Glass of index 1.5. The x offset ray is parallel to the main one, so only the
// normal's change (the dn/dx terms) turns its outgoing direction.
DiffErrors differentialErrors(Event event, double eps) {
  D3 o, d;
  if (event == Event::RefractLeave) {
    o = kCentre + D3{0.1, -0.2, 0.3} * kRadius;
    d = normalizeD({0.35, 0.3, 1});
  } else {
    o = kCentre + D3{0.3, -0.4, 5};
    d = normalizeD(kCentre + normalizeD({0.5, 0.4, 0.75}) * kRadius - o);
  }
  Point3f of(Float(o.x), Float(o.y), Float(o.z));
  Vector3f df = normalize(Vector3f(Float(d.x), Float(d.y), Float(d.z)));
  RayDifferential ray(of, df);
  ray.hasDifferentials = true;
  ray.rxOrigin = of + Vector3f(Float(eps), 0, 0);
  ray.rxDirection = df;
  ray.ryOrigin = of;
  ray.ryDirection = normalize(df + Vector3f(0, Float(eps), 0));

  SphereShape sphere(translate(Vector3f(Float(kCentre.x), Float(kCentre.y), Float(kCentre.z))),
                     false, Float(kRadius), Float(-kRadius), Float(kRadius), 360);
  Float tHit;
  SurfaceInteraction si;
  EXPECT_TRUE(sphere.intersect(ray, &tHit, &si));
  si.computeDifferentials(ray);
  BSDF bsdf(si, 1.5f);
  // The main ray's outgoing direction about the renderer's own normal, as the BSDF samples it.
  D3 n = d3(Vector3f(si.shading.n));
  double eta = event == Event::RefractEnter ? 1 / 1.5 : 1.5;
  auto scatter = [&](D3 dir, D3 normal) {
    D3 out{0, 0, 0};
    if (event == Event::Reflect) return reflectD(dir, normal);
    EXPECT_TRUE(refractD(dir, normal, eta, &out)) << "total internal reflection";
    return out;
  };
  D3 wi = scatter(d3(df), n);
  Vector3f wif(Float(wi.x), Float(wi.y), Float(wi.z));
  RayDifferential out = spawnSpecularRay(si, bsdf, ray, wif, event != Event::Reflect);
  EXPECT_TRUE(out.hasDifferentials);

  DiffErrors e{0, 0, 1e30};
  for (bool isY : {false, true}) {
    D3 oo = d3(isY ? ray.ryOrigin : ray.rxOrigin);
    D3 od = normalizeD(d3(isY ? ray.ryDirection : ray.rxDirection));
    D3 hit, hitN;
    hitSphere(oo, od, &hit, &hitN);
    D3 exact = scatter(od, hitN);
    D3 predicted = normalizeD(d3(isY ? out.ryDirection : out.rxDirection));
    double turn = lengthD(exact - wi);
    e.minTurn = std::min(e.minTurn, turn);
    e.direction = std::max(e.direction, lengthD(predicted - exact) / turn);
    D3 predictedOrigin = d3(isY ? out.ryOrigin : out.rxOrigin);
    e.origin =
        std::max(e.origin, lengthD(predictedOrigin - hit) / lengthD(hit - d3(Point3f(si.p))));
  }
  return e;
}

// First order means the error is O(eps^2), so the error relative to the offset's own effect is
// O(eps) and halves with each halving of eps. An error in a first-order term (a dn/dx of the
// wrong sign or missing, a wrong dmu) leaves a relative error of order one that does not shrink:
// dropping dn gives 1.0 to 1.3 here, the leaving branch's dn/dx left unflipped 2.0. 0.6 per
// halving separates the two with room for the third-order terms and the float rounding of the
// renderer's outputs (~1e-7, against errors of ~1e-5 at the smallest offset). At eps = 4e-3 the
// relative errors measure 1.5e-2 (reflection), 2.5e-2 (entering) and 7e-4 (leaving), about 4, 6
// and 0.2 times eps: the ray runs ~5 radii to the sphere, so the offset hit's second-order shift
// is eps times a few; 0.1 bounds them with room and is still ten times below a first-order error.
void expectFirstOrder(Event event, const char* name) {
  double prevDir = 0, prevOrigin = 0;
  for (double eps : {3.2e-2, 1.6e-2, 8e-3, 4e-3}) {
    DiffErrors e = differentialErrors(event, eps);
    EXPECT_GT(e.minTurn, eps / 4) << name << ": the offset must visibly turn the ray";
    if (prevDir > 0) {
      EXPECT_LT(e.direction / prevDir, 0.6) << name << " direction, eps " << eps;
      EXPECT_LT(e.origin / prevOrigin, 0.6) << name << " origin, eps " << eps;
    }
    prevDir = e.direction;
    prevOrigin = e.origin;
    std::printf("%s eps %.0e: relative direction error %.3e, origin %.3e\n", name, eps, e.direction,
                e.origin);
  }
  EXPECT_LT(prevDir, 0.1) << name;
  EXPECT_LT(prevOrigin, 0.1) << name;
}

TEST(SpecularDifferentials, SphereReflectionIsFirstOrderAccurate) {
  expectFirstOrder(Event::Reflect, "reflect");
}

TEST(SpecularDifferentials, SphereRefractionEnteringIsFirstOrderAccurate) {
  expectFirstOrder(Event::RefractEnter, "enter");
}

// From inside the glass: n and dn/dx must both be turned to wo's side.
TEST(SpecularDifferentials, SphereRefractionLeavingIsFirstOrderAccurate) {
  expectFirstOrder(Event::RefractLeave, "leave");
}

// --- passing through a surface without a material ---

// A matte plane z = 0 under a checkerboard of about a pixel and a half per check, seen from
// z = 3 at one sample per pixel centre; with the quad, a 1.6 x 1.6 square at z = 1 covering the
// whole view. The distant light grazes in from +x so that no shadow ray from the visible plane
// (|x| < 1.1) passes through the quad (it reaches z = 1 only at x > 3.9); its radiance 16 makes
// the white checks' radiance 16 cos / pi = 1.0.
std::string checkerScene(bool withQuad, const char* aaMode, const char* yon,
                         const char* integrator) {
  std::string s(
      "LookAt 0 0 3  0 0 0  0 1 0\n"
      "Camera \"perspective\" \"float fov\" [40] \"float yon\" [");
  s.append(yon).append(
      "]\n"
      "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16]\n"
      "Sampler \"stratified\" \"integer xsamples\" [1] \"integer ysamples\" [1] "
      "\"bool jitter\" [\"false\"]\n"
      "SurfaceIntegrator \"");
  s.append(integrator)
      .append(
          "\" \"integer maxdepth\" [5]\n"
          "WorldBegin\n"
          "LightSource \"distant\" \"rgb L\" [16 16 16] \"point from\" [1 0 0.2] \"point to\" [0 0 "
          "0]\n"
          "Texture \"checks\" \"color\" \"checkerboard\" \"float uscale\" [20] "
          "\"float vscale\" [20] \"color tex1\" [0 0 0] \"color tex2\" [1 1 1] \"string aamode\" "
          "[\"");
  s.append(aaMode).append(
      "\"]\n"
      "Material \"matte\" \"texture Kd\" \"checks\"\n"
      "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] "
      "\"point P\" [-2 -2 0  2 -2 0  2 2 0  -2 2 0] \"float uv\" [0 0 1 0 1 1 0 1]\n");
  if (withQuad)
    s.append(
        "Material \"matte\"\n"
        "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] "
        "\"point P\" [-0.8 -0.8 1  0.8 -0.8 1  0.8 0.8 1  -0.8 0.8 1]\n");
  return s.append("WorldEnd\n");
}

// Builds and renders the scene; the quad (the primitives above z = 0.5) loses its material
// first, since the scene grammar has no way to give a shape none.
test::RenderedScene renderChecker(bool withQuad, const char* aaMode, const char* yon,
                                  const char* integrator) {
  test::RenderedScene r = test::buildSceneText(checkerScene(withQuad, aaMode, yon, integrator));
  RenderJob& job = r.job();
  int cleared = 0;
  for (Primitive& p : job.geometry.primitives) {
    if (p.shape->worldBound().pMin.z > 0.5f) {
      p.material = nullptr;
      ++cleared;
    }
  }
  EXPECT_EQ(cleared, withQuad ? 2 : 0);
  test::PixelPasses renderer(job);
  r.results.push_back(renderer.render(*job.scene, *job.film, RenderOptions{0, 16, true}));
  return r;
}

// The largest per-pixel difference of the two films' values, and alphas when withAlpha.
double maxDifference(const Film& a, const Film& b, bool withAlpha = true) {
  double worst = 0;
  Bounds2i bounds = a.pixelBounds();
  for (int y = bounds.pMin.y; y < bounds.pMax.y; ++y)
    for (int x = bounds.pMin.x; x < bounds.pMax.x; ++x) {
      Point2i p(x, y);
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, double(std::abs(a.pixelValue(p)[c] - b.pixelValue(p)[c])));
      if (withAlpha) worst = std::max(worst, double(std::abs(a.pixelAlpha(p) - b.pixelAlpha(p))));
    }
  return worst;
}

// The ray continues through the quad as the same ray: with its differentials, so the closed-form
// checkerboard is filtered over the same footprints, and with what remains of its extent, so a
// yon plane between quad and plane still clips the plane. Not bit-identical: the continued ray
// starts at the quad, offset by its rounding-error bound, so the plane hit moves by ~1e-7 and the
// closed form (continuous in the hit point, slope ~1 / footprint) by ~1e-5 of full scale at most
// (6.6e-6 measured); dropping the differentials point-samples the checks instead (0.5 measured,
// asserted > 0.1 below), and dropping the extent brings the clipped plane back. Alpha is compared
// only unclipped: a hit on the quad counts as coverage whatever lies behind it.
// The same for the path integrator, which continues such rays in its own loop: its bounces off
// the plane escape (the distant light has no radiance to find), so it renders the same values.
TEST(SpecularRecursion, MaterialLessSurfaceKeepsDifferentialsAndExtent) {
  for (const char* integrator : {"whitted", "path"}) {
    SCOPED_TRACE(integrator);
    test::RenderedScene filtered = renderChecker(false, "closedform", "1e30", integrator);
    test::RenderedScene pointSampled = renderChecker(false, "none", "1e30", integrator);
    double footprintEffect = maxDifference(filtered.film(), pointSampled.film());
    EXPECT_GT(footprintEffect, 0.1) << "the footprint must matter for the test to mean anything";
    test::RenderedScene through = renderChecker(true, "closedform", "1e30", integrator);
    double err = maxDifference(filtered.film(), through.film());
    EXPECT_LT(err, 1e-4);
    std::printf("%s: footprint effect %.3g, difference through the quad %.3g\n", integrator,
                footprintEffect, err);

    test::RenderedScene clipped = renderChecker(false, "closedform", "2.5", integrator);
    EXPECT_EQ(clipped.film().pixelAlpha(Point2i(8, 8)), 0.f) << "yon must clip the plane";
    test::RenderedScene clippedThrough = renderChecker(true, "closedform", "2.5", integrator);
    EXPECT_EQ(maxDifference(clipped.film(), clippedThrough.film(), false), 0.0);
  }
}

}  // namespace
}  // namespace candela
