#include "bench_scenes.h"

#include <cmath>

#include "accel/embree/embree_device.h"
#include "assembly/shape_factory.h"
#include "core/rng.h"
#include "parser/parser.h"
#include "parser/scene_builder.h"

namespace candela::bench {

namespace {

std::unique_ptr<Camera> lookAtCamera(const Point3f& eye, const Point3f& at, Float fov,
                                     const Point2i& res) {
  ParamSet params;
  ParamItem f;
  f.type = ParamType::Float;
  f.name = "fov";
  f.typeName = "float";
  f.floats = {fov};
  params.add(f);
  return createCamera("perspective", params, inverse(lookAt(eye, at, Vector3f(0, 1, 0))), res,
                      FileLoc{"bench", 1, 1});
}

void addMesh(BenchScene& s, std::unique_ptr<TriangleMesh> mesh, std::vector<Primitive>* out) {
  s.meshes.push_back(std::move(mesh));
  for (auto& shape : createTriangleShapes(s.meshes.back().get())) {
    out->push_back(Primitive{shape.get(), nullptr, nullptr});
    s.shapes.push_back(std::move(shape));
  }
}

// A box of two-triangle walls (inward facing) from lo to hi: the "stadium".
std::unique_ptr<TriangleMesh> room(const Point3f& lo, const Point3f& hi) {
  std::vector<Point3f> p;
  for (int c = 0; c < 8; ++c)
    p.emplace_back(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
  std::vector<int> idx = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                          2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
  return std::make_unique<TriangleMesh>(Transform(), false, idx, p);
}

void finishGenerated(BenchScene& s, const Point3f& eye, const Point3f& at, Float fov,
                     const Point3f& light) {
  s.geometry = s.ownGeometry.get();
  s.ownCamera = lookAtCamera(eye, at, fov, s.resolution);
  s.camera = s.ownCamera.get();
  s.lightPosition = light;
  for (const Primitive& p : s.geometry->primitives)
    (p.shape->triangleMesh(nullptr) ? s.triangles : s.quadrics) += 1;
  s.instances = long(s.geometry->instances.size());
  for (const Instance& inst : s.geometry->instances)
    for (const Primitive& p : inst.prototype->primitives)
      s.instancedTriangles += p.shape->triangleMesh(nullptr) ? 1 : 0;
}

std::unique_ptr<BenchScene> meshScene(long n) {
  auto s = std::make_unique<BenchScene>();
  s->name = "mesh-" + std::to_string(n);
  s->ownGeometry = std::make_unique<SceneGeometry>();
  addMesh(*s, lumpySphereMesh(n, Transform()), &s->ownGeometry->primitives);
  finishGenerated(*s, Point3f(2, 3, -9), Point3f(0, 0, 0), 40, Point3f(4, 8, -6));
  return s;
}

// 1000 quadrics of every kind, randomly turned, on a 10 x 10 x 10 lattice.
std::unique_ptr<BenchScene> quadricScene() {
  auto s = std::make_unique<BenchScene>();
  s->name = "quadrics";
  s->ownGeometry = std::make_unique<SceneGeometry>();
  const char* kinds[] = {"sphere", "cylinder", "disk", "cone", "paraboloid", "hyperboloid"};
  RNG rng(3);
  for (int i = 0; i < 1000; ++i) {
    ShapeDesc d;
    d.name = kinds[i % 6];
    Vector3f at(Float(i % 10) * 2.5f, Float(i / 10 % 10) * 2.5f, Float(i / 100) * 2.5f);
    Float u = rng.uniformFloat(), v = rng.uniformFloat();
    Transform t = translate(at) * rotate(360 * u, Vector3f(1, v, 1 - v)) * scale(0.8f, 0.8f, 0.8f);
    CreatedShapes created = createShapes(d, t);
    for (auto& shape : created.shapes) {
      s->ownGeometry->primitives.push_back(Primitive{shape.get(), nullptr, nullptr});
      s->shapes.push_back(std::move(shape));
    }
  }
  finishGenerated(*s, Point3f(-14, 30, -30), Point3f(11, 11, 11), 45, Point3f(11, 40, -10));
  return s;
}

// 400 instances (a 20 x 20 field, turned and scaled at random) of one 20,000-triangle mesh
// with a sphere: 8 million triangles as seen by rays, 20,000 in memory.
std::unique_ptr<BenchScene> instanceScene() {
  auto s = std::make_unique<BenchScene>();
  s->name = "instances";
  s->ownGeometry = std::make_unique<SceneGeometry>();
  auto proto = std::make_unique<InstancePrototype>();
  proto->name = "lump";
  addMesh(*s, lumpySphereMesh(20000, Transform()), &proto->primitives);
  ShapeDesc sphere;
  sphere.name = "sphere";
  CreatedShapes created = createShapes(sphere, translate(Vector3f(0, 3.5f, 0)));
  proto->primitives.push_back(Primitive{created.shapes[0].get(), nullptr, nullptr});
  s->shapes.push_back(std::move(created.shapes[0]));
  RNG rng(4);
  for (int i = 0; i < 400; ++i) {
    Vector3f at(Float(i % 20) * 8, 0, Float(i / 20) * 8);
    Float k = 0.6f + 0.6f * rng.uniformFloat();
    Transform t = translate(at) * rotateY(360 * rng.uniformFloat()) * scale(k, k, k);
    s->ownGeometry->instances.push_back(Instance{proto.get(), AnimatedTransform(t)});
  }
  s->ownGeometry->prototypes.push_back(std::move(proto));
  finishGenerated(*s, Point3f(76, 60, -40), Point3f(76, 0, 76), 50, Point3f(76, 100, 76));
  return s;
}

// The grid's worst case ("teapot in a stadium", lrt draft §4.3): 10,000 triangles in a ball of
// radius 1 inside an empty room 400 units wide, all in a few voxels; the camera looks at it.
std::unique_ptr<BenchScene> stadiumScene() {
  auto s = std::make_unique<BenchScene>();
  s->name = "stadium";
  s->ownGeometry = std::make_unique<SceneGeometry>();
  addMesh(*s, lumpySphereMesh(10000, scale(0.3f, 0.3f, 0.3f)), &s->ownGeometry->primitives);
  addMesh(*s, room(Point3f(-200, -1, -200), Point3f(200, 100, 200)), &s->ownGeometry->primitives);
  finishGenerated(*s, Point3f(0.5f, 1, -4), Point3f(0, 0, 0), 30, Point3f(3, 20, -5));
  return s;
}

std::unique_ptr<BenchScene> fileScene(const std::string& path, const EmbreeDevice& device) {
  auto s = std::make_unique<BenchScene>();
  s->name = path.substr(path.find_last_of('/') + 1);
  SceneBuilder builder(
      [&](SceneDescription&& desc) {
        if (s->job) return;  // the first frame only
        BuildOptions options;
        s->job = std::make_unique<RenderJob>(buildRenderJob(desc, options, device));
      },
      {});
  parseFile(path, builder);
  builder.endOfInput(FileLoc{path, 0, 0});
  if (!s->job) throw std::runtime_error(path + ": no WorldEnd");
  s->geometry = &s->job->geometry;
  s->camera = s->job->camera.get();
  s->resolution = s->job->film->fullResolution();
  // Shadow rays go to a point high in the scene's bound (inside it: a closed room stays lit).
  Bounds3f b = s->job->aggregate->worldBound();
  Point3f c = (b.pMin + b.pMax) * 0.5f;
  s->lightPosition = Point3f(c.x, lerp(0.9f, b.pMin.y, b.pMax.y), c.z);
  for (const Primitive& p : s->geometry->primitives)
    (p.shape->triangleMesh(nullptr) ? s->triangles : s->quadrics) += 1;
  s->instances = long(s->geometry->instances.size());
  return s;
}

}  // namespace

std::unique_ptr<TriangleMesh> lumpySphereMesh(long n, const Transform& objectToWorld) {
  constexpr double kPiD = 3.14159265358979323846;
  int nu = std::max(4, int(std::ceil(std::sqrt(double(n)))));
  int nv = int((n + 2L * nu - 1) / (2L * nu)) + 1;
  nv = std::max(nv, 3);
  auto at = [](double theta, double phi) {
    double r = 3 + 0.3 * std::sin(5 * theta) * std::cos(4 * phi);
    return Point3f(Float(r * std::sin(theta) * std::cos(phi)),
                   Float(r * std::sin(theta) * std::sin(phi)), Float(r * std::cos(theta)));
  };
  std::vector<Point3f> p;
  p.push_back(at(0, 0));
  for (int j = 1; j < nv; ++j)
    for (int i = 0; i < nu; ++i) p.push_back(at(kPiD * j / nv, 2 * kPiD * i / nu));
  p.push_back(at(kPiD, 0));
  int south = int(p.size()) - 1;
  auto ring = [&](int j, int i) { return 1 + (j - 1) * nu + (i % nu); };
  std::vector<int> idx;
  idx.reserve(size_t(6) * nu * nv);
  for (int i = 0; i < nu; ++i) idx.insert(idx.end(), {0, ring(1, i), ring(1, i + 1)});
  for (int j = 1; j + 1 < nv; ++j)
    for (int i = 0; i < nu; ++i)
      idx.insert(idx.end(), {ring(j, i), ring(j + 1, i), ring(j + 1, i + 1), ring(j, i),
                             ring(j + 1, i + 1), ring(j, i + 1)});
  for (int i = 0; i < nu; ++i) idx.insert(idx.end(), {south, ring(nv - 1, i + 1), ring(nv - 1, i)});
  return std::make_unique<TriangleMesh>(objectToWorld, false, idx, p);
}

std::vector<std::string> generatedSceneNames() {
  return {"mesh-100000", "quadrics", "instances", "stadium"};
}

std::unique_ptr<BenchScene> makeScene(const std::string& name, const EmbreeDevice& device) {
  if (name.rfind("mesh-", 0) == 0) return meshScene(std::stol(name.substr(5)));
  if (name == "quadrics") return quadricScene();
  if (name == "instances") return instanceScene();
  if (name == "stadium") return stadiumScene();
  if (name.size() > 5 && name.substr(name.size() - 5) == ".pbrt") return fileScene(name, device);
  throw std::runtime_error("unknown scene '" + name + "' (generated: mesh-N, quadrics, " +
                           "instances, stadium; or a .pbrt file)");
}

}  // namespace candela::bench
