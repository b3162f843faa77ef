// Scenes for the accelerator benchmark: pbrt files (their geometry and camera, as the renderer
// builds them) and generated ones (a mesh of N triangles, a field of quadrics, many instances of
// one mesh, a small dense mesh in a large empty room), each with a camera and a light position
// for shadow rays.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accel/scene_geometry.h"
#include "assembly/render_job.h"
#include "cameras/camera.h"
#include "shapes/triangle_mesh.h"

namespace candela {

class EmbreeDevice;

namespace bench {

struct BenchScene {
  std::string name;
  const SceneGeometry* geometry = nullptr;
  const Camera* camera = nullptr;
  Point2i resolution{256, 256};
  Point3f lightPosition;  // shadow rays end here
  long triangles = 0, quadrics = 0, instances = 0, instancedTriangles = 0;

  // Owners of what geometry and camera point into.
  std::vector<std::unique_ptr<TriangleMesh>> meshes;
  std::vector<std::unique_ptr<Shape>> shapes;
  std::unique_ptr<SceneGeometry> ownGeometry;
  std::unique_ptr<Camera> ownCamera;
  std::unique_ptr<RenderJob> job;
};

// The names makeScene knows besides file paths: "mesh-N" (N triangles, e.g. mesh-100000),
// "quadrics", "instances", "stadium".
std::vector<std::string> generatedSceneNames();
// A generated scene, or a pbrt file (a path ending in .pbrt). Throws on errors.
std::unique_ptr<BenchScene> makeScene(const std::string& name, const EmbreeDevice& device);
// The closed lumpy sphere used by "mesh-N", with about n triangles (at least n).
std::unique_ptr<TriangleMesh> lumpySphereMesh(long n, const Transform& objectToWorld);

}  // namespace bench
}  // namespace candela
