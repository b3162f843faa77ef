#include "accel/embree/embree_triangle_filters.h"

#include "accel/embree/embree_geometry.h"
#include "shapes/triangle_mesh.h"

namespace candela {

namespace {

// For each active lane, whether the candidate hit is on a degenerate triangle or cut away by the
// triangle's alpha; if so the lane is made invalid, which tells Embree to ignore the hit and
// continue. In a filter the ray's tfar holds the candidate's distance.
void filterLanes(const RTCFilterFunctionNArguments* args, bool forShadow) {
  const auto* g = static_cast<const EmbreeGeometry*>(args->geometryUserPtr);
  unsigned N = args->N;
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    unsigned primID = RTCHitN_primID(args->hit, N, i);
    const auto* tri = static_cast<const TriangleShape*>(g->primitive(primID).shape);
    if (tri->degenerate()) {
      args->valid[i] = 0;
      continue;
    }
    Point3f o(RTCRayN_org_x(args->ray, N, i), RTCRayN_org_y(args->ray, N, i),
              RTCRayN_org_z(args->ray, N, i));
    Vector3f d(RTCRayN_dir_x(args->ray, N, i), RTCRayN_dir_y(args->ray, N, i),
               RTCRayN_dir_z(args->ray, N, i));
    Float t = RTCRayN_tfar(args->ray, N, i);
    Ray ray(o, d, kInfinity, RTCRayN_time(args->ray, N, i));
    // Embree's (u, v) are the barycentrics of vertices 1 and 2, as interactionAt takes them.
    if (tri->alphaCulls(ray, RTCHitN_u(args->hit, N, i), RTCHitN_v(args->hit, N, i), t, forShadow))
      args->valid[i] = 0;
  }
}

void intersectFilter(const RTCFilterFunctionNArguments* args) { filterLanes(args, false); }
void occludedFilter(const RTCFilterFunctionNArguments* args) { filterLanes(args, true); }

}  // namespace

void setTriangleFilters(RTCGeometry geometry, const TriangleMesh& mesh) {
  bool anyDegenerate = false;
  for (int i = 0; i < mesh.triangleCount() && !anyDegenerate; ++i)
    anyDegenerate = TriangleShape(&mesh, i).degenerate();
  if (mesh.alpha || anyDegenerate) rtcSetGeometryIntersectFilterFunction(geometry, intersectFilter);
  if (mesh.shadowAlpha || anyDegenerate)
    rtcSetGeometryOccludedFilterFunction(geometry, occludedFilter);
}

}  // namespace candela
