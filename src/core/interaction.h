// A point where light interacts with a surface, with the error bound of its position so that rays
// spawned from it never re-hit the surface they leave (pbrt 3e §2.10, §3.9.5). The lrt draft's
// DifferentialGeometry (§2.8) is SurfaceInteraction here.
#pragma once

#include "core/ray.h"

namespace candela {

struct Primitive;
class BSDF;

struct Interaction {
  Point3f p;
  Vector3f pError;  // conservative bound on |p - exact p| per axis
  Normal3f n;       // geometric normal; zero for points in free space
  Vector3f wo;      // direction back along the incoming ray (unit)
  Float time = 0;

  Interaction() = default;
  // Geometry left unset (see Uninitialized): only for one that a hit then writes in full.
  explicit Interaction(Uninitialized u) : p(u), pError(u), n(u), wo(u) {}
  Interaction(const Point3f& p_, const Normal3f& n_, const Vector3f& pError_, const Vector3f& wo_,
              Float time_)
      : p(p_), pError(pError_), n(n_), wo(wo_), time(time_) {}
  Interaction(const Point3f& p_, Float time_) : p(p_), time(time_) {}
  bool isSurface() const { return n != Normal3f(); }

  Point3f offsetOrigin(const Vector3f& w) const { return offsetRayOrigin(p, pError, n, w); }
  Ray spawnRay(const Vector3f& d) const { return Ray(offsetOrigin(d), d, kInfinity, time); }
  // A segment ending just short of p2 (shadow rays).
  Ray spawnRayTo(const Point3f& p2) const {
    Point3f o = offsetOrigin(p2 - p);
    Vector3f d = p2 - o;
    return Ray(o, d, 1 - kShadowEpsilon, time);
  }
  Ray spawnRayTo(const Interaction& it) const {
    Point3f o = offsetOrigin(it.p - p);
    Point3f target = it.offsetOrigin(o - it.p);
    Vector3f d = target - o;
    return Ray(o, d, 1 - kShadowEpsilon, time);
  }
};

struct SurfaceInteraction : Interaction {
  Point2f uv;
  Vector3f dpdu, dpdv;
  Normal3f dndu, dndv;
  struct {
    Normal3f n;
    Vector3f dpdu, dpdv;
    Normal3f dndu, dndv;
  } shading;
  const Primitive* primitive = nullptr;
  // Screen-space differentials, filled by computeDifferentials.
  mutable Vector3f dpdx, dpdy;
  mutable Float dudx = 0, dvdx = 0, dudy = 0, dvdy = 0;

  SurfaceInteraction() = default;
  // Geometry left unset, the scalars zeroed: for a hit record that Aggregate::intersect writes in
  // full on a hit and that nothing reads after a miss (the path integrator's per-vertex local).
  explicit SurfaceInteraction(Uninitialized u)
      : Interaction(u),
        uv(u),
        dpdu(u),
        dpdv(u),
        dndu(u),
        dndv(u),
        shading{Normal3f(u), Vector3f(u), Vector3f(u), Normal3f(u), Normal3f(u)},
        dpdx(u),
        dpdy(u) {}
  // n is normalize(dpdu x dpdv), flipped when flipNormal (ReverseOrientation xor handedness swap).
  SurfaceInteraction(const Point3f& p, const Vector3f& pError, const Point2f& uv,
                     const Vector3f& wo, const Vector3f& dpdu, const Vector3f& dpdv,
                     const Normal3f& dndu, const Normal3f& dndv, Float time, bool flipNormal);
  // With the unit geometric normal n given, oriented as the shape orients it (shading.n = n).
  // Inline and with every member in the initialiser list, so that a shape can build a hit in
  // place (std::construct_at) without first zeroing it or copying a temporary.
  SurfaceInteraction(const Point3f& p_, const Vector3f& pError_, const Point2f& uv_,
                     const Vector3f& wo_, const Vector3f& dpdu_, const Vector3f& dpdv_,
                     const Normal3f& dndu_, const Normal3f& dndv_, Float time_, const Normal3f& n_)
      : Interaction(p_, n_, pError_, wo_, time_),
        uv(uv_),
        dpdu(dpdu_),
        dpdv(dpdv_),
        dndu(dndu_),
        dndv(dndv_),
        shading{n_, dpdu_, dpdv_, dndu_, dndv_} {}
  // Shading frame from interpolated normals etc.; the geometric normal is turned to its side
  // when orientationIsAuthoritative, else the shading normal is turned to the geometric side.
  void setShadingGeometry(const Vector3f& dpdus, const Vector3f& dpdvs, const Normal3f& dndus,
                          const Normal3f& dndvs, bool orientationIsAuthoritative);
  // Texture-space differentials from the ray's offset rays (lrt draft §11.1.1).
  void computeDifferentials(const RayDifferential& ray) const;
};

}  // namespace candela
