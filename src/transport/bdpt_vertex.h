// A vertex of a bidirectional path-tracing subpath (Veach's thesis §10.2; pbrt 3e §16.3.1): the
// camera or light it starts from, or a surface where the path scattered, with the throughput
// up to it and the two area densities multiple importance sampling needs: of generating it from
// its own subpath's side (pdfFwd) and from the other side (pdfRev).
#pragma once

#include "core/interaction.h"
#include "core/spectrum.h"
#include "lights/light.h"
#include "reflection/bsdf.h"

namespace candela {

struct PathVertex {
  enum class Kind { Camera, Light, Surface };
  Kind kind = Kind::Surface;
  Spectrum beta;          // throughput of the subpath up to and including this vertex
  SurfaceInteraction it;  // p, geometric n, time; the whole surface record for Surface
  Normal3f ns;            // shading normal of a Surface (zero elsewhere)
  const BSDF* bsdf = nullptr;
  const Light* light = nullptr;          // the light of a Light vertex
  const AreaLight* areaLight = nullptr;  // an emitting Surface, or a Light vertex's area light
  // A Light vertex for what a camera ray that escaped sees: every infinite light at once.
  bool environment = false;
  bool delta = false;  // scattered by a specular BSDF: cannot be connected
  // A Camera vertex whose ray lands on the film. A pixel filter wider than a pixel draws camera
  // rays past the film's edges too; no light path connected to the lens lands there (the camera's
  // importance is zero off the film), so for such a path that strategy does not exist.
  bool onFilm = true;
  Float pdfFwd = 0, pdfRev = 0;

  const Point3f& p() const { return it.p; }
  bool onSurface() const { return it.n != Normal3f(); }
  // A point at infinity: only its direction from the other vertices matters.
  bool atInfinity() const { return environment || (light && light->atInfinity()); }
  bool connectible() const {
    if (kind == Kind::Light) return !environment;
    if (kind == Kind::Camera) return true;
    return bsdf && !delta;
  }
};

// A solid-angle density at `from` toward `to` as an area density at `to` (pbrt 3e §16.3.1);
// points at infinity keep the solid-angle density.
inline Float solidAngleToArea(Float pdfDir, const PathVertex& from, const PathVertex& to) {
  if (to.atInfinity()) return pdfDir;
  Vector3f w = to.p() - from.p();
  Float d2 = w.lengthSquared();
  if (d2 == 0) return 0;
  Float pdf = pdfDir / d2;
  if (to.onSurface()) pdf *= absDot(to.it.n, w / std::sqrt(d2));
  return pdf;
}

}  // namespace candela
