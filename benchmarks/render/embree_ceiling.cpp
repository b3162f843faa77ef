#include "embree_ceiling.h"

#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <map>
#include <stdexcept>

#include "accel/embree/embree_device.h"
#include "accel/embree/embree_geometry.h"
#include "core/parallel_for.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"

namespace candela::bench {

namespace {

double threadCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

void commitAndAttach(RTCScene scene, RTCGeometry g, const EmbreeDevice& device) {
  rtcSetGeometryBuildQuality(g, RTC_BUILD_QUALITY_MEDIUM);
  rtcCommitGeometry(g);
  rtcAttachGeometry(scene, g);
  rtcReleaseGeometry(g);
  device.check("building the ceiling's Embree scene");
}

void addTriangles(RTCScene scene, const TriangleMesh& mesh, const std::vector<int>& triangles,
                  const EmbreeDevice& device) {
  RTCGeometry g = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.p.size()));
  auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles.size()));
  for (size_t v = 0; v < mesh.p.size(); ++v)
    for (int a = 0; a < 3; ++a) vb[3 * v + size_t(a)] = mesh.p[v][a];
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      ib[3 * t + size_t(k)] = unsigned(mesh.indices[3 * size_t(triangles[t]) + size_t(k)]);
  commitAndAttach(scene, g, device);
}

void addSpheres(RTCScene scene, const std::vector<float>& balls, const EmbreeDevice& device) {
  RTCGeometry g = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), balls.size() / 4));
  std::copy(balls.begin(), balls.end(), vb);
  commitAndAttach(scene, g, device);
}

// A path vertex: where a closest-hit ray ended, as candela would spawn rays from it.
Interaction vertexOf(const RTCRayHit& rh) {
  Vector3f d(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  Point3f o(rh.ray.org_x, rh.ray.org_y, rh.ray.org_z);
  Point3f p = o + d * rh.ray.tfar;
  Vector3f wo = normalize(-d);
  Normal3f n =
      faceForward(Normal3f(normalize(Vector3f(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z))), wo);
  // The bound of a point interpolated on a triangle (pbrt 3e §3.9.4): generous for o + t d.
  Vector3f err = Vector3f(std::abs(p.x), std::abs(p.y), std::abs(p.z)) * gamma(7);
  return Interaction(p, n, err, wo, rh.ray.time);
}

struct ThreadTotals {
  RayKind camera, bounce, shadow;
  double tileSeconds = 0;  // whole tiles: queries and ray making
};

// One tile's paths, a wavefront per depth: the batches of queries are timed, the rest is not.
void traceTile(RTCScene scene, const Camera& camera, const std::vector<const Light*>& lights,
               const CeilingOptions& o, const Bounds2i& tile, uint64_t tileIndex,
               ThreadTotals* totals) {
  RNG rng(mixBits(o.seed * 0x9e3779b97f4a7c15ULL + tileIndex));
  std::vector<RTCRayHit> paths;
  for (int y = tile.pMin.y; y < tile.pMax.y; ++y)
    for (int x = tile.pMin.x; x < tile.pMax.x; ++x)
      for (int s = 0; s < o.spp; ++s) {
        CameraSample cs;
        Float ux = rng.uniformFloat(), uy = rng.uniformFloat();
        cs.pFilm = Point2f(Float(x) + ux, Float(y) + uy);
        Float lx = rng.uniformFloat(), ly = rng.uniformFloat();
        cs.pLens = Point2f(lx, ly);
        cs.time = rng.uniformFloat();
        Ray ray;
        if (camera.generateRay(cs, &ray) == 0) continue;
        RTCRayHit rh;
        toEmbreeRay(ray, &rh.ray);
        paths.push_back(rh);
      }
  RayKind* kind = &totals->camera;
  std::vector<RTCRay> shadows;
  RTCIntersectContext context;
  for (int depth = 0; !paths.empty(); ++depth) {
    for (RTCRayHit& rh : paths)
      rh.hit.geomID = rh.hit.primID = rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    double start = threadCpuSeconds();
    if (o.streams) {
      rtcInitIntersectContext(&context);
      context.flags =
          depth == 0 ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
      rtcIntersect1M(scene, &context, paths.data(), unsigned(paths.size()), sizeof(RTCRayHit));
    } else {
      for (RTCRayHit& rh : paths) {
        rtcInitIntersectContext(&context);
        rtcIntersect1(scene, &context, &rh);
      }
    }
    kind->cpuSeconds += threadCpuSeconds() - start;
    kind->rays += long(paths.size());
    kind = &totals->bounce;
    if (depth == o.maxDepth) break;
    // Each vertex: a shadow ray to a light point it faces, and a cosine-distributed bounce.
    shadows.clear();
    size_t next = 0;
    for (const RTCRayHit& rh : paths) {
      if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
      Interaction it = vertexOf(rh);
      if (!lights.empty()) {
        Float uc = rng.uniformFloat(), u0 = rng.uniformFloat(), u1 = rng.uniformFloat();
        const Light& light =
            *lights[std::min(size_t(uc * Float(lights.size())), lights.size() - 1)];
        Vector3f wi;
        Float pdf = 0;
        VisibilityTester vis;
        Spectrum li = light.sampleLi(it, Point2f(u0, u1), &wi, &pdf, &vis);
        if (pdf > 0 && !li.isBlack() && dot(wi, it.n) > 0) {
          RTCRay r;
          toEmbreeRay(vis.p0.spawnRayTo(vis.p1), &r);
          shadows.push_back(r);
        }
      }
      Vector3f nv(it.n), s, t;
      coordinateSystem(nv, &s, &t);
      Float u0 = rng.uniformFloat(), u1 = rng.uniformFloat();
      Vector3f local = sampleCosineHemisphere(Point2f(u0, u1));
      RTCRayHit bounce;
      toEmbreeRay(it.spawnRay(s * local.x + t * local.y + nv * local.z), &bounce.ray);
      paths[next++] = bounce;
    }
    paths.resize(next);
    start = threadCpuSeconds();
    if (o.streams) {
      rtcInitIntersectContext(&context);
      context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
      rtcOccluded1M(scene, &context, shadows.data(), unsigned(shadows.size()), sizeof(RTCRay));
    } else {
      for (RTCRay& r : shadows) {
        rtcInitIntersectContext(&context);
        rtcOccluded1(scene, &context, &r);
      }
    }
    totals->shadow.cpuSeconds += threadCpuSeconds() - start;
    totals->shadow.rays += long(shadows.size());
  }
}

void add(RayKind* to, const RayKind& k) {
  to->rays += k.rays;
  to->cpuSeconds += k.cpuSeconds;
}

}  // namespace

EmbreeCeiling::EmbreeCeiling(const EmbreeDevice& device, const SceneGeometry& geometry) {
  if (!geometry.instances.empty())
    throw std::runtime_error("the Embree ceiling does not take object instances");
  scene_ = rtcNewScene(device.handle());
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);  // as candela's aggregate
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_MEDIUM);
  std::map<const TriangleMesh*, std::vector<int>> meshes;
  std::vector<const TriangleMesh*> order;
  std::vector<float> balls;
  for (const Primitive& prim : geometry.primitives) {
    int tri = 0;
    Point3f centre;
    Float radius;
    if (const TriangleMesh* mesh = prim.shape->triangleMesh(&tri)) {
      if (dynamic_cast<const TriangleShape*>(prim.shape) &&
          static_cast<const TriangleShape*>(prim.shape)->degenerate())
        continue;
      if (!meshes.count(mesh)) order.push_back(mesh);
      meshes[mesh].push_back(tri);
    } else if (const auto* sphere = dynamic_cast<const SphereShape*>(prim.shape);
               sphere && sphere->worldBall(&centre, &radius)) {
      balls.insert(balls.end(), {centre.x, centre.y, centre.z, radius});
    } else {
      rtcReleaseScene(scene_);
      throw std::runtime_error(std::string("the Embree ceiling takes triangles and whole spheres, "
                                           "not a '") +
                               prim.shape->kind() + "'");
    }
  }
  try {
    for (const TriangleMesh* mesh : order) addTriangles(scene_, *mesh, meshes[mesh], device);
    if (!balls.empty()) addSpheres(scene_, balls, device);
    rtcCommitScene(scene_);
    device.check("rtcCommitScene");
  } catch (...) {
    rtcReleaseScene(scene_);
    throw;
  }
}

EmbreeCeiling::~EmbreeCeiling() { rtcReleaseScene(scene_); }

CeilingResult EmbreeCeiling::run(const Camera& camera, const std::vector<const Light*>& lights,
                                 const CeilingOptions& o) const {
  const int tile = std::max(1, o.tileSize);
  const Bounds2i& b = o.pixels;
  const int nx = (b.pMax.x - b.pMin.x + tile - 1) / tile;
  const int ny = (b.pMax.y - b.pMin.y + tile - 1) / tile;
  tbb::enumerable_thread_specific<ThreadTotals> totals;
  auto start = std::chrono::steady_clock::now();
  tbb::task_arena arena(std::max(1, o.threads));
  parallelFor(
      arena, 0, nx * ny,
      [&](int i) {
        enableFlushToZero();
        int x0 = b.pMin.x + (i % nx) * tile, y0 = b.pMin.y + (i / nx) * tile;
        Bounds2i t(Point2i(x0, y0),
                   Point2i(std::min(x0 + tile, b.pMax.x), std::min(y0 + tile, b.pMax.y)));
        ThreadTotals& mine = totals.local();
        double tileStart = threadCpuSeconds();
        traceTile(scene_, camera, lights, o, t, uint64_t(i), &mine);
        mine.tileSeconds += threadCpuSeconds() - tileStart;
      },
      tbb::simple_partitioner());
  CeilingResult r;
  r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const ThreadTotals& t : totals) {
    add(&r.camera, t.camera);
    add(&r.bounce, t.bounce);
    add(&r.shadow, t.shadow);
    r.makingSeconds += t.tileSeconds;
  }
  r.makingSeconds = std::max(0.0, r.makingSeconds - r.cpuSeconds());
  return r;
}

}  // namespace candela::bench
