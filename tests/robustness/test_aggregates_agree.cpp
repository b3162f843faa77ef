// Every aggregate answers every ray as a brute-force loop does, and as Embree does.
//
// The scene: every quadric the shape factory knows, under nested transforms (non-uniform scales,
// mirrors, ReverseOrientation, partial sweeps); a 100,800-triangle closed lumpy sphere; a floor of
// unit squares with integer vertices (edges and vertices on voxel faces and split planes); and
// instances of two prototypes, static (mirrored and scaled too) and animated.
//
// The rays, in six equal groups: from outside the scene bound toward points inside it; from
// inside it in all directions; spawned from surfaces (hits of other rays, offset by their error
// bounds); grazing surfaces (nearly tangent at a hit); parallel to an axis (some on the floor's
// integer lines); and with one or two zero direction components (of either sign), starting on
// the scene bound's faces, where the slab test meets 0 * inf. Times are uniform in [0, 1).
//
// What must agree, per ray:
// - bvh, kdtree and grid against the brute-force loop: hit or miss, and t exactly (the same
//   shape code runs on the same ray); the primitive, unless another primitive is hit at that
//   same t (a shared edge or vertex);
// - against Embree (whose triangle test and instance transforms are its own): hit or miss, t
//   within kTTolerance * (1 + t), and the primitive, or a point within that tolerance (a tie);
// - intersectP on a segment of random length: exactly as the brute-force loop, and as Embree
//   unless the closest hit lies within kTTolerance * (1 + t) of the segment's end.
// Two different correct routines need not agree where the answer is ill-conditioned: hits within
// ~3 degrees of tangent and hits on a triangle's edge are not compared with Embree (counted, and
// required to be under a tenth of the rays); they are still compared with the brute-force loop.
#include <gtest/gtest.h>

#include <oneapi/tbb/task_arena.h>

#include <atomic>
#include <cstdio>
#include <mutex>

#include "accel/aggregate_factory.h"
#include "accel/embree/embree_device.h"
#include "assembly/shape_factory.h"
#include "core/parallel_for.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "shapes/triangle_mesh.h"
#include "support/param_items.h"
#include "support/random_geometry.h"
#include "support/test_device.h"

namespace candela {
namespace {

// |tA - tB| <= kTTolerance * (1 + t): t of two triangle tests (or an instance's ray with and
// without the origin moved to its error bound) differ by rounding of the coordinates, a few
// ulps (1e-7) of the scene's size (~20), magnified for grazing rays by 1 / cos; 1e-4 covers
// cos down to ~1e-2.
constexpr Float kTTolerance = 1e-4f;
// Hits compared with Embree must be at least this far from tangent (|cos| of the incidence)...
constexpr Float kMinCosine = 0.05f;
// ... and, on a triangle, at least this far from its edges (in barycentric coordinates).
constexpr double kEdgeBarycentric = 1e-5;

Float uniform(RNG& rng, Float lo, Float hi) { return lerp(rng.uniformFloat(), lo, hi); }
// A random nested transform: translation, rotation, non-uniform scale (mirrored 1 time in 4),
// another rotation, as several Transform statements would compose.
Transform nestedTransform(RNG& rng, Float extent) {
  Vector3f t(uniform(rng, -extent, extent), uniform(rng, -extent, extent),
             uniform(rng, -extent, extent));
  Float sx = uniform(rng, 0.5f, 1.5f), sy = uniform(rng, 0.5f, 1.5f), sz = uniform(rng, 0.5f, 1.5f);
  if (rng.uniformUInt32(4) == 0) sx = -sx;
  Float a0 = uniform(rng, 0, 360), a1 = uniform(rng, 0, 360);
  Vector3f ax0 = test::randomDirection(rng), ax1 = test::randomDirection(rng);
  return translate(t) * rotate(a0, ax0) * scale(sx, sy, sz) * rotate(a1, ax1);
}

struct AgreeScene {
  std::vector<std::unique_ptr<TriangleMesh>> meshes;
  std::vector<std::unique_ptr<Shape>> shapes;
  SceneGeometry geometry;
  std::vector<std::string> quadricKinds;  // the ones the factory knows

  void addShapes(CreatedShapes created, std::vector<Primitive>* out) {
    if (created.mesh) meshes.push_back(std::move(created.mesh));
    for (auto& s : created.shapes) {
      out->push_back(Primitive{s.get(), nullptr, nullptr});
      shapes.push_back(std::move(s));
    }
  }
  void addMesh(std::unique_ptr<TriangleMesh> mesh, std::vector<Primitive>* out) {
    meshes.push_back(std::move(mesh));
    for (auto& s : createTriangleShapes(meshes.back().get())) {
      out->push_back(Primitive{s.get(), nullptr, nullptr});
      shapes.push_back(std::move(s));
    }
  }
  // n quadrics of each kind, half of them partial (phimax 250), one in three inside out.
  void addQuadrics(int n, RNG& rng, Float extent, std::vector<Primitive>* out) {
    for (const std::string& kind : quadricKinds)
      for (int i = 0; i < n; ++i) {
        ShapeDesc d;
        d.name = kind;
        d.reverseOrientation = i % 3 == 0;
        if (i % 2 == 1) d.params.add(test::floats("phimax", {250}));
        addShapes(createShapes(d, nestedTransform(rng, extent)), out);
      }
  }
};

// A closed lumpy sphere of radius ~3 with nu x (nv - 1) x 2 triangles.
std::unique_ptr<TriangleMesh> lumpySphere(int nu, int nv) {
  std::vector<Point3f> p;
  auto at = [](Float theta, Float phi) {
    Float r = 3 + 0.3f * std::sin(5 * theta) * std::cos(4 * phi);
    return Point3f(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                   r * std::cos(theta));
  };
  p.push_back(at(0, 0));
  for (int j = 1; j < nv; ++j)
    for (int i = 0; i < nu; ++i) p.push_back(at(kPi * j / nv, 2 * kPi * i / nu));
  p.push_back(at(kPi, 0));
  int south = int(p.size()) - 1;
  auto ring = [&](int j, int i) { return 1 + (j - 1) * nu + (i % nu); };
  std::vector<int> idx;
  for (int i = 0; i < nu; ++i) idx.insert(idx.end(), {0, ring(1, i), ring(1, i + 1)});
  for (int j = 1; j + 1 < nv; ++j)
    for (int i = 0; i < nu; ++i)
      idx.insert(idx.end(), {ring(j, i), ring(j + 1, i), ring(j + 1, i + 1), ring(j, i),
                             ring(j + 1, i + 1), ring(j, i + 1)});
  for (int i = 0; i < nu; ++i) idx.insert(idx.end(), {south, ring(nv - 1, i + 1), ring(nv - 1, i)});
  return std::make_unique<TriangleMesh>(Transform(), false, idx, p);
}

// An n x n floor of unit squares at height z, corners at integer (x, y) in [x0, x0 + n].
std::unique_ptr<TriangleMesh> floorMesh(int n, Float x0, Float z, const Transform& t) {
  std::vector<Point3f> p;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) p.emplace_back(x0 + Float(i), x0 + Float(j), z);
  std::vector<int> idx;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      int v = j * (n + 1) + i;
      idx.insert(idx.end(), {v, v + 1, v + n + 2, v, v + n + 2, v + n + 1});
    }
  return std::make_unique<TriangleMesh>(t, false, idx, p);
}

AgreeScene buildScene() {
  AgreeScene s;
  for (const char* kind : {"sphere", "cylinder", "disk", "cone", "paraboloid", "hyperboloid"}) {
    ShapeDesc probe;
    probe.name = kind;
    try {
      createShapes(probe, Transform());
      s.quadricKinds.push_back(kind);
    } catch (const SceneError&) {
      // not written yet: the scene holds the quadrics that exist
    }
  }
  RNG rng(2024);
  std::vector<Primitive>& world = s.geometry.primitives;
  s.addQuadrics(12, rng, 9, &world);
  s.addMesh(lumpySphere(225, 225), &world);
  s.addMesh(floorMesh(16, -8, -8, Transform()), &world);

  auto cluster = std::make_unique<InstancePrototype>();
  cluster->name = "cluster";
  s.addQuadrics(2, rng, 1, &cluster->primitives);
  s.addMesh(floorMesh(16, -1, 0, scale(0.125f, 0.125f, 1) * rotateX(30)), &cluster->primitives);
  auto ball = std::make_unique<InstancePrototype>();
  ball->name = "ball";
  ShapeDesc sphere;
  sphere.name = "sphere";
  s.addShapes(createShapes(sphere, scale(0.7f, 0.7f, 0.7f)), &ball->primitives);
  auto& inst = s.geometry.instances;
  for (int i = 0; i < 20; ++i)
    inst.push_back(Instance{cluster.get(), AnimatedTransform(nestedTransform(rng, 9))});
  for (int i = 0; i < 10; ++i)
    inst.push_back(Instance{ball.get(), AnimatedTransform(nestedTransform(rng, 9))});
  for (int i = 0; i < 4; ++i) {
    Transform t0 = nestedTransform(rng, 8);
    Transform t1 = translate(Vector3f(uniform(rng, -2, 2), uniform(rng, -2, 2), 1)) * t0 *
                   rotate(uniform(rng, 10, 120), test::randomDirection(rng));
    inst.push_back(Instance{i % 2 ? ball.get() : cluster.get(), AnimatedTransform(t0, 0, t1, 1)});
  }
  s.geometry.prototypes.push_back(std::move(cluster));
  s.geometry.prototypes.push_back(std::move(ball));
  return s;
}

// A hit as the comparisons need it: t, the primitive, the world point (instances of one
// prototype share its primitives; the point tells them apart) and the geometric normal.
struct Hit {
  bool hit = false;
  Float t = 0;
  const Primitive* primitive = nullptr;
  Point3f p;
  Normal3f n;
};

// The brute-force loop: every primitive and every instance's every primitive, closest hit kept.
// To keep 100k triangles affordable, conservative bounding-sphere tests in double (sharing no
// code with the aggregates' boxes) first drop items whose sphere the ray's line misses, for
// groups of kGroupSize consecutive primitives and then for each member. The candidates depend on
// the line only, so one scan serves intersect and intersectP.
class BruteForce {
 public:
  static constexpr size_t kGroupSize = 64;

  explicit BruteForce(const SceneGeometry& g) : g_(g) {
    for (const Primitive& p : g.primitives) addSphere(p.shape->worldBound());
    for (size_t i = 0; i < g.primitives.size(); i += kGroupSize) {
      Bounds3f b;
      for (size_t k = i; k < std::min(i + kGroupSize, g.primitives.size()); ++k)
        b = unionOf(b, g.primitives[k].shape->worldBound());
      groupSpheres_.push_back(sphereOf(b));
    }
    for (const Instance& inst : g.instances) {
      Bounds3f b;
      for (const Primitive& p : inst.prototype->primitives) b = unionOf(b, p.shape->worldBound());
      instanceSpheres_.push_back(sphereOf(inst.instanceToWorld.motionBounds(b)));
    }
  }

  struct Candidates {
    std::vector<uint32_t> primitives, instances;
  };
  Candidates candidates(const Ray& ray) const {
    Candidates c;
    if (ray.hasNaN() || std::isinf(ray.o.x) || std::isinf(ray.o.y) || std::isinf(ray.o.z)) return c;
    double o[3] = {ray.o.x, ray.o.y, ray.o.z}, d[3] = {ray.d.x, ray.d.y, ray.d.z};
    double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    auto lineMeets = [&](double cx, double cy, double cz, double r2) {
      double vx = cx - o[0], vy = cy - o[1], vz = cz - o[2];
      double ax = vy * d[2] - vz * d[1], ay = vz * d[0] - vx * d[2], az = vx * d[1] - vy * d[0];
      return ax * ax + ay * ay + az * az <= r2 * dd;
    };
    size_t n = cx_.size();
    for (size_t group = 0; group < groupSpheres_.size(); ++group) {
      const Sphere& s = groupSpheres_[group];
      if (!lineMeets(s.c[0], s.c[1], s.c[2], s.r * s.r)) continue;
      for (size_t i = group * kGroupSize; i < std::min(n, (group + 1) * kGroupSize); ++i)
        if (lineMeets(cx_[i], cy_[i], cz_[i], r2_[i])) c.primitives.push_back(uint32_t(i));
    }
    for (size_t k = 0; k < instanceSpheres_.size(); ++k) {
      const Sphere& s = instanceSpheres_[k];
      if (lineMeets(s.c[0], s.c[1], s.c[2], s.r * s.r)) c.instances.push_back(uint32_t(k));
    }
    return c;
  }

  Hit intersect(const Ray& ray, const Candidates& c) const {
    Hit h;
    Ray r = ray;
    const Primitive* best = nullptr;
    int bestInstance = -1;
    forEach(ray, c, [&](const Primitive& p, const Ray& local, Float dt, int instance) {
      Float t;
      Ray lr = local;
      lr.tMax = r.tMax - dt;
      if (!p.shape->intersect(lr, &t, nullptr)) return false;
      Float tw = t + dt;
      r.tMax = tw < r.tMax ? tw : nextFloatDown(r.tMax);
      best = &p;
      bestInstance = instance;
      return false;
    });
    if (!best) return h;
    h = Hit{true, r.tMax, best, ray(r.tMax), {}};
    // The normal, for judging how well conditioned the hit is.
    SurfaceInteraction si;
    Float t;
    Ray full = ray;
    if (bestInstance < 0) {
      if (best->shape->intersect(full, &t, &si)) h.n = si.n;
    } else {
      Transform toWorld = g_.instances[size_t(bestInstance)].instanceToWorld.interpolate(ray.time);
      if (best->shape->intersect(inverse(toWorld)(Ray(ray.o, ray.d)), &t, &si)) h.n = toWorld(si.n);
    }
    return h;
  }
  bool intersectP(const Ray& ray, const Candidates& c) const {
    bool hit = false;
    forEach(ray, c, [&](const Primitive& p, const Ray& local, Float, int) {
      return hit = p.shape->intersectP(local);
    });
    return hit;
  }

 private:
  struct Sphere {
    double c[3], r;
  };
  static Sphere sphereOf(const Bounds3f& b) {
    Sphere s;
    double r2 = 0, m = 0;
    for (int a = 0; a < 3; ++a) {
      s.c[a] = 0.5 * (double(b.pMin[a]) + b.pMax[a]);
      double h = 0.5 * (double(b.pMax[a]) - b.pMin[a]);
      r2 += h * h;
      m = std::max(m, std::abs(s.c[a]));
    }
    s.r = std::sqrt(r2) * (1 + 1e-4) + 1e-4 * m + 1e-6;
    return s;
  }
  void addSphere(const Bounds3f& b) {
    Sphere s = sphereOf(b);
    cx_.push_back(s.c[0]);
    cy_.push_back(s.c[1]);
    cz_.push_back(s.c[2]);
    r2_.push_back(s.r * s.r);
  }
  // visit(primitive, ray in its space, dt, instance or -1) for every candidate until visit
  // returns true. dt moves an instance's ray origin to the edge of its rounding error box, as the
  // reference aggregates do (pbrt 3e §3.9.4).
  template <typename Visit>
  void forEach(const Ray& ray, const Candidates& c, Visit&& visit) const {
    for (uint32_t i : c.primitives)
      if (visit(g_.primitives[i], ray, 0.f, -1)) return;
    for (uint32_t k : c.instances) {
      const Instance& inst = g_.instances[k];
      Transform w2i = inverse(inst.instanceToWorld.interpolate(ray.time));
      Vector3f oErr;
      Point3f o = w2i.apply(ray.o, &oErr);
      Vector3f d = w2i(ray.d);
      Float dt = dot(abs(d), oErr) / d.lengthSquared();
      Ray local(o + d * dt, d, ray.tMax - dt, ray.time);
      for (const Primitive& p : inst.prototype->primitives)
        if (visit(p, local, dt, int(k))) return;
    }
  }

  const SceneGeometry& g_;
  std::vector<double> cx_, cy_, cz_, r2_;
  std::vector<Sphere> groupSpheres_, instanceSpheres_;
};

enum Group { kOutside, kInside, kOnSurface, kGrazing, kAxisParallel, kZeroComponents, kGroups };
const char* kGroupNames[kGroups] = {"outside", "inside",        "on surface",
                                    "grazing", "axis-parallel", "zero components"};

// Ray i of group i % kGroups, from its own random stream (so any subset is reproducible).
// probe finds surface points for the surface-bound groups.
Ray makeRay(uint64_t i, const Bounds3f& b, const Aggregate& probe) {
  RNG rng(i, 77);
  Point3f c = (b.pMin + b.pMax) * 0.5f;
  Float radius = distance(b.pMin, b.pMax) * 0.5f;
  auto inside = [&] {
    return Point3f(uniform(rng, b.pMin.x, b.pMax.x), uniform(rng, b.pMin.y, b.pMax.y),
                   uniform(rng, b.pMin.z, b.pMax.z));
  };
  Float time = rng.uniformFloat();
  auto withTime = [&](Ray r) {
    r.time = time;
    return r;
  };
  switch (Group(i % kGroups)) {
    case kOutside: {
      Point3f o = c + test::randomDirection(rng) * (radius * uniform(rng, 1.05f, 4));
      return withTime(Ray(o, (inside() - o) * uniform(rng, 0.1f, 3)));
    }
    case kInside:
      return withTime(Ray(inside(), test::randomDirection(rng)));
    case kOnSurface:
    case kGrazing: {
      for (int attempt = 0; attempt < 16; ++attempt) {
        Ray r = withTime(Ray(inside(), test::randomDirection(rng)));
        SurfaceInteraction si;
        if (!probe.intersect(r, &si)) continue;
        Vector3f n = normalize(Vector3f(si.n));
        if (i % kGroups == kOnSurface) return withTime(si.spawnRay(test::randomDirection(rng)));
        // Nearly tangent at the hit, passing over it from a little way back.
        // Half within 0.002 of tangent, half at cosines 0.05 to 0.2 (compared with Embree).
        Vector3f t = normalize(cross(n, test::randomDirection(rng)));
        Float lift = (i / kGroups) % 2
                         ? uniform(rng, -2e-3f, 2e-3f)
                         : uniform(rng, 0.06f, 0.2f) * (rng.uniformUInt32(2) ? 1 : -1);
        Vector3f d = normalize(t + n * lift);
        return withTime(Ray(si.p - d * uniform(rng, 0.05f, 2), d));
      }
      return withTime(Ray(inside(), test::randomDirection(rng)));
    }
    case kAxisParallel: {
      Point3f o = inside();
      int axis = int(rng.uniformUInt32(3));
      if (rng.uniformUInt32(2) == 0) {  // on the floor's integer lines, above or below it
        o.x = std::round(o.x);
        if (rng.uniformUInt32(2) == 0) o.y = std::round(o.y);
      }
      Vector3f d(0, 0, 0);
      d[axis] = rng.uniformUInt32(2) ? 1.f : -1.f;
      for (int a = 0; a < 3; ++a)
        if (a != axis && rng.uniformUInt32(2)) d[a] = -0.f;
      return withTime(Ray(o, d));
    }
    default: {  // zero components, from the bound's faces
      Point3f o = inside();
      int face = int(rng.uniformUInt32(3));
      o[face] = rng.uniformUInt32(2) ? b.pMin[face] : b.pMax[face];
      Vector3f d = test::randomDirection(rng);
      int zero = int(rng.uniformUInt32(3));
      d[zero] = rng.uniformUInt32(2) ? 0.f : -0.f;
      if (rng.uniformUInt32(3) == 0) d[(zero + 1) % 3] = 0;
      if (d == Vector3f(0, 0, 0)) d[(zero + 2) % 3] = 1;
      return withTime(Ray(o, d));
    }
  }
}

struct Tally {
  std::atomic<long> rays{0}, hits{0}, ties{0}, illConditioned{0}, failures{0};
  std::mutex mutex;
  std::vector<std::string> examples;
  void fail(const std::string& what) {
    ++failures;
    std::lock_guard<std::mutex> lock(mutex);
    if (examples.size() < 12) examples.push_back(what);
  }
};

std::string describe(uint64_t i, const Ray& r, const std::string& who, const Hit& a, const Hit& b) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "ray %llu (%s) o=(%.9g %.9g %.9g) d=(%.9g %.9g %.9g) tMax %.9g time %.3g: %s "
                "hit=%d t=%.9g prim=%p, reference hit=%d t=%.9g prim=%p",
                (unsigned long long)i, kGroupNames[i % kGroups], r.o.x, r.o.y, r.o.z, r.d.x, r.d.y,
                r.d.z, r.tMax, r.time, who.c_str(), a.hit, a.t, (const void*)a.primitive, b.hit,
                b.t, (const void*)b.primitive);
  return buf;
}

Hit query(const Aggregate& agg, const Ray& ray) {
  Ray r = ray;
  SurfaceInteraction si;
  Hit h;
  if (agg.intersect(r, &si)) h = Hit{true, r.tMax, si.primitive, si.p, si.n};
  return h;
}

bool near(Float a, Float b) { return std::abs(a - b) <= kTTolerance * (1 + std::abs(b)); }
bool nearPoint(const Point3f& a, const Point3f& b) {
  Float scale = 1 + std::max({std::abs(b.x), std::abs(b.y), std::abs(b.z)});
  return std::abs(a.x - b.x) <= kTTolerance * scale && std::abs(a.y - b.y) <= kTTolerance * scale &&
         std::abs(a.z - b.z) <= kTTolerance * scale;
}

// Whether two different correct intersection routines must agree on a hit: not within ~3 degrees
// of tangent (there a quadric's t moves by the square root of the rounding error and a
// triangle's by rounding / cos), and not on the edge of a world-space triangle (edges count as
// inside for one triangle test and outside for another, as they may).
bool wellConditioned(const Hit& h, const Ray& ray, const SceneGeometry& g) {
  if (!h.hit) return true;
  Float cosine = std::abs(dot(normalize(Vector3f(h.n)), normalize(ray.d)));
  if (!(cosine >= kMinCosine)) return false;
  int tri = 0;
  const TriangleMesh* mesh = h.primitive->shape->triangleMesh(&tri);
  bool isStatic =
      h.primitive >= g.primitives.data() && h.primitive < g.primitives.data() + g.primitives.size();
  if (!mesh || !isStatic) return true;
  double v[3][3], p[3] = {h.p.x, h.p.y, h.p.z};
  for (int k = 0; k < 3; ++k)
    for (int a = 0; a < 3; ++a) v[k][a] = mesh->p[size_t(mesh->indices[3 * tri + k])][a];
  auto crossDot = [&](const double* a, const double* b, const double* c, const double* n) {
    double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double x[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    return x[0] * n[0] + x[1] * n[1] + x[2] * n[2];
  };
  double e1[3] = {v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]};
  double e2[3] = {v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]};
  double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                 e1[0] * e2[1] - e1[1] * e2[0]};
  double area2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  double b0 = crossDot(p, v[1], v[2], n) / area2, b1 = crossDot(v[0], p, v[2], n) / area2;
  double b2 = 1 - b0 - b1;
  return std::min({b0, b1, b2}) > kEdgeBarycentric;
}

void runAgreement(uint64_t nRays) {
  AgreeScene scene = buildScene();
  ASSERT_GE(scene.quadricKinds.size(), 1u);
  const SceneGeometry& g = scene.geometry;
  FileLoc loc{"test", 1, 1};
  auto embree = createAggregate("embree", {}, g, test::embreeDevice(), loc);
  std::vector<std::pair<std::string, std::unique_ptr<Aggregate>>> aggs;
  for (const char* kind : {"bvh", "kdtree", "grid"})
    aggs.emplace_back(kind, createAggregate(kind, {}, g, test::embreeDevice(), loc));
  BruteForce brute(g);
  Bounds3f bounds = embree->worldBound();
  for (const auto& [name, agg] : aggs) {
    Bounds3f b = agg->worldBound();
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(b.pMin[a], bounds.pMin[a]) << name;
      EXPECT_GE(b.pMax[a], bounds.pMax[a]) << name;
    }
  }

  Tally tally;
  tbb::task_arena arena;
  parallelFor(arena, uint64_t(0), nRays, [&](uint64_t i) {
    enableFlushToZero();
    Ray ray = makeRay(i, bounds, *embree);
    BruteForce::Candidates candidates = brute.candidates(ray);
    Hit ref = brute.intersect(ray, candidates);
    Hit e = query(*embree, ray);
    ++tally.rays;
    tally.hits += ref.hit;
    bool conditioned = wellConditioned(ref, ray, g) && wellConditioned(e, ray, g);
    tally.illConditioned += !conditioned;
    if (conditioned &&
        (e.hit != ref.hit || (e.hit && !(near(e.t, ref.t) && nearPoint(e.p, ref.p)))))
      tally.fail(describe(i, ray, "embree", e, ref));
    for (const auto& [name, agg] : aggs) {
      Hit a = query(*agg, ray);
      if (a.hit != ref.hit || (a.hit && a.t != ref.t)) {
        tally.fail(describe(i, ray, name, a, ref));
        continue;
      }
      if (a.hit && a.primitive != ref.primitive) ++tally.ties;  // the same t: a shared edge
      if (conditioned && (a.hit != e.hit || (a.hit && !near(a.t, e.t)) ||
                          (a.hit && a.primitive != e.primitive && !nearPoint(a.p, e.p))))
        tally.fail(describe(i, ray, name + " vs embree", a, e));
    }
    // Occlusion on a segment of random length.
    Ray seg = ray;
    RNG segmentRng(i, 99);
    seg.tMax = uniform(segmentRng, 0, 2) * distance(bounds.pMin, bounds.pMax) / ray.d.length();
    bool refP = brute.intersectP(seg, candidates);
    if (refP != (ref.hit && ref.t < seg.tMax)) tally.fail(describe(i, seg, "brute P", ref, ref));
    bool ambiguous = ref.hit && std::abs(ref.t - seg.tMax) <= kTTolerance * (1 + ref.t);
    bool eP = embree->intersectP(seg);
    for (const auto& [name, agg] : aggs) {
      bool p = agg->intersectP(seg);
      if (p != refP || (conditioned && !ambiguous && p != eP)) {
        Hit hp{p, seg.tMax, nullptr, {}, {}}, rp{refP, seg.tMax, nullptr, {}, {}};
        tally.fail(describe(i, seg, name + " P (embree " + std::to_string(eP) + ")", hp, rp));
      }
    }
  });

  std::printf(
      "%ld rays, %ld hits, %ld ties at shared edges, %ld grazing or edge-on (not "
      "compared with Embree)\n",
      tally.rays.load(), tally.hits.load(), tally.ties.load(), tally.illConditioned.load());
  for (const std::string& e : tally.examples) ADD_FAILURE() << e;
  EXPECT_EQ(tally.failures.load(), 0);
  EXPECT_GT(tally.hits.load(), long(nRays) / 3);  // the rays do meet the geometry
  // Embree is compared on nearly all rays: the extreme half of the grazing group, and a few
  // edge-on rays, are not.
  EXPECT_LE(tally.illConditioned.load(), long(nRays) / 10);
}

TEST(AggregatesAgree, TwentyThousandRays) { runAgreement(20000); }

TEST(LongAggregatesAgree, TwoHundredThousandRays) { runAgreement(200000); }

}  // namespace
}  // namespace candela
