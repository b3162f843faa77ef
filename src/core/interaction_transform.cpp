#include "core/interaction_transform.h"

namespace candela {

SurfaceInteraction transformSurfaceInteraction(const Transform& t, const SurfaceInteraction& si,
                                               const Vector3f& worldRayD) {
  SurfaceInteraction r = si;
  r.p = t.apply(si.p, si.pError, &r.pError);
  Float len = worldRayD.length();
  r.wo = len > 0 ? -worldRayD / len : Vector3f();
  r.n = normalize(t(si.n));
  r.dpdu = t(si.dpdu);
  r.dpdv = t(si.dpdv);
  r.dndu = t(si.dndu);
  r.dndv = t(si.dndv);
  r.shading.n = faceForward(normalize(t(si.shading.n)), Vector3f(r.n));
  r.shading.dpdu = t(si.shading.dpdu);
  r.shading.dpdv = t(si.shading.dpdv);
  r.shading.dndu = t(si.shading.dndu);
  r.shading.dndv = t(si.shading.dndv);
  return r;
}

}  // namespace candela
