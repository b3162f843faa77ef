#include "integrators/bdpt.h"

#include <cstdio>
#include "accel/primitive.h"

#include "film/film.h"
#include "film/splat_buffer.h"
#include "filters/box_filter.h"
#include "materials/material.h"
#include "transport/scattering_surface.h"
#include "transport/specular_differentials.h"

namespace candela {

namespace {

Float remap0(Float pdf) { return pdf != 0 ? pdf : 1; }

// Whether camera-path vertices 1 .. end - 1 all scattered specularly (true when there are none).
bool onlySpecularBefore(const PathVertex* cameraPath, int end) {
  for (int i = 1; i < end; ++i)
    if (!cameraPath[i].delta) return false;
  return true;
}

Vector3f directionTo(const PathVertex& from, const PathVertex& to) {
  return normalize(to.p() - from.p());
}

// The shading-normal correction of the adjoint BSDF for light (importance) transport, pbrt 3e
// §16.1.3: |wo·ns| |wi·ng| / (|wo·ng| |wi·ns|), wo toward the light side, wi toward the camera.
Float shadingCorrection(const Vector3f& wo, const Vector3f& wi, const Normal3f& ns,
                        const Normal3f& ng) {
  Float num = absDot(wo, ns) * absDot(wi, ng), den = absDot(wo, ng) * absDot(wi, ns);
  return den == 0 ? 0 : num / den;
}

}  // namespace

BdptIntegrator::BdptIntegrator(const CameraImportance& camera, int maxDepth,
                               LightSampleStrategy lightStrategy, Visualize visualize,
                               const Bounds2i& pixelBounds, const Point3f& lightReference)
    : camera_(camera),
      maxDepth_(maxDepth),
      lightStrategy_(lightStrategy),
      lightReference_(lightReference),
      visualize_(visualize) {
  if (visualize_ == Visualize::None) return;
  pixelBox_ = std::make_unique<BoxFilter>(Vector2f(0.5f, 0.5f));
  int n = strategyIndex(maxDepth_ + 1, 1) + 1;
  // A box of radius 1/2 never reaches past the pixel, so the image edges need no correction.
  Bounds2f area(Point2f(Float(pixelBounds.pMin.x), Float(pixelBounds.pMin.y)),
                Point2f(Float(pixelBounds.pMax.x), Float(pixelBounds.pMax.y)));
  for (int i = 0; i < n; ++i)
    strategyImages_.push_back(std::make_unique<SplatBuffer>(pixelBounds, area, *pixelBox_));
}

BdptIntegrator::~BdptIntegrator() = default;

std::vector<NamedImage> BdptIntegrator::extraImages(const Film& film) const {
  std::vector<NamedImage> images;
  Bounds2i b = film.pixelBounds();
  int w = std::max(0, b.pMax.x - b.pMin.x), h = std::max(0, b.pMax.y - b.pMin.y);
  Float scale = Float(film.splatScale());
  for (int d = 0; d <= maxDepth_ && !strategyImages_.empty(); ++d)
    for (int s = 0; s <= d + 1; ++s) {
      int t = d + 2 - s;
      ImageBuffer img(w, h, {"R", "G", "B"});
      img.xOffset = b.pMin.x;
      img.yOffset = b.pMin.y;
      img.fullWidth = film.fullResolution().x;
      img.fullHeight = film.fullResolution().y;
      const SplatBuffer& buf = *strategyImages_[size_t(strategyIndex(s, t))];
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          Spectrum v = buf.sum(Point2i(b.pMin.x + x, b.pMin.y + y)) * scale;
          for (int c = 0; c < 3; ++c) img.at(x, y, c) = v[c];
        }
      char name[64];
      std::snprintf(name, sizeof name, "bdpt_d%02d_s%02d_t%02d.exr", d, s, t);
      images.push_back({name, std::move(img)});
    }
  return images;
}

void BdptIntegrator::preprocess(const Scene& scene, const PreprocessOptions&) {
  lights_ = scene.lights();
  scene.worldBound().boundingSphere(&sceneCenter_, &sceneRadius_);
  bool tree = lightStrategy_ == LightSampleStrategy::Bvh;
  lightSampler_ = createLightSampler(tree ? LightSampleStrategy::Power : lightStrategy_,
                                     scene.lights(), scene.worldBound());
  vertexLightSampler_.reset();
  if (tree)
    vertexLightSampler_ = createLightSampler(lightStrategy_, scene.lights(), scene.worldBound());
}

Float BdptIntegrator::lightPdf(const Light* light) const {
  return lightSampler_->pmf(lightReference_, *light);
}

Float BdptIntegrator::infiniteLightDensity(const Vector3f& w) const {
  Float pdf = 0;
  Interaction anywhere;
  for (const Light* l : lights_)
    if (l->atInfinity() && !l->isDelta()) pdf += lightPdf(l) * l->pdfLi(anywhere, w);
  return pdf;
}

Spectrum BdptIntegrator::Le(const PathVertex& v, const PathVertex& toward) const {
  if (v.environment) {
    Spectrum L(0);
    RayDifferential ray(toward.p(), directionTo(toward, v));
    for (const Light* l : lights_)
      if (l->atInfinity()) L += l->Le(ray);
    return L;
  }
  if (v.areaLight) return v.areaLight->L(v.it, directionTo(v, toward));
  return Spectrum(0);
}

Spectrum BdptIntegrator::f(const PathVertex& v, const PathVertex& prev, const PathVertex& next,
                           bool importance) const {
  Vector3f wo = directionTo(v, prev), wi = directionTo(v, next);
  Spectrum value = v.bsdf->f(wo, wi);
  if (importance) value *= shadingCorrection(wo, wi, v.ns, v.it.n);
  return value;
}

Float BdptIntegrator::pdf(const PathVertex& v, const PathVertex* prev,
                          const PathVertex& next) const {
  Vector3f wn = directionTo(v, next);
  Float pdfDir = 0;
  if (v.kind == PathVertex::Kind::Camera) {
    Float pdfPos;
    camera_.pdfWe(Ray(v.p(), wn, kInfinity, v.it.time), &pdfPos, &pdfDir);
  } else if (v.bsdf && prev) {
    pdfDir = v.bsdf->pdf(directionTo(v, *prev), wn);
  }
  return solidAngleToArea(pdfDir, v, next);
}

Float BdptIntegrator::pdfLight(const PathVertex& v, const PathVertex& next) const {
  Vector3f w = next.p() - v.p();
  Float d2 = w.lengthSquared();
  if (d2 == 0) return 0;
  w = w / std::sqrt(d2);
  const Light* light = v.light ? v.light : v.areaLight;
  if (v.environment) {
    for (const Light* l : lights_)
      if (l->atInfinity()) light = l;
  }
  if (!light) return 0;
  Float pdfPos = 0, pdfDir = 0;
  light->pdfLe(Ray(v.p(), w, kInfinity, v.it.time), v.it.n, &pdfPos, &pdfDir);
  // From infinity, rays are parallel: the density per area of the disk they cross.
  Float pdf = v.atInfinity() ? pdfPos : pdfDir / d2;
  if (next.onSurface()) pdf *= absDot(next.it.n, w);
  return pdf;
}

Float BdptIntegrator::pdfLightOrigin(const PathVertex& v, const PathVertex& next) const {
  if (v.atInfinity()) return infiniteLightDensity(directionTo(next, v));
  const Light* light = v.light ? v.light : v.areaLight;
  if (!light) return 0;
  Float pdfPos = 0, pdfDir = 0;
  light->pdfLe(Ray(v.p(), directionTo(v, next), kInfinity, v.it.time), v.it.n, &pdfPos, &pdfDir);
  return lightPdf(light) * pdfPos;
}

int BdptIntegrator::randomWalk(RayDifferential ray, Spectrum beta, Float pdfDir, bool fromCamera,
                               const Scene& scene, IntegratorContext& ctx, PathVertex* path,
                               int maxVertices) const {
  int n = 1;  // path[0] is the start
  bool firstHit = fromCamera;
  Float pdfFwd = pdfDir;
  while (n < maxVertices) {
    SurfaceInteraction isect;
    bool hit = intersectScattering(scene, &ray, &isect, ctx.stats);
    PathVertex& prev = path[n - 1];
    PathVertex& v = path[n];
    if (!hit) {
      // A camera ray that escapes ends on the environment, a point far along it.
      if (fromCamera) {
        v = PathVertex();
        v.kind = PathVertex::Kind::Light;
        v.environment = true;
        Float reach = 2 * sceneRadius_ + distance(ray.o, sceneCenter_);
        v.it.p = ray.o + ray.d * (reach > 0 ? reach : Float(1));
        v.it.time = ray.time;
        v.beta = beta;
        v.pdfFwd = pdfFwd;
        ++n;
      }
      break;
    }
    const Primitive& prim = *isect.primitive;
    if (firstHit) {
      isect.computeDifferentials(ray);
      firstHit = false;
    }
    const BSDF* bsdf = prim.material->getBSDF(isect, ctx.arena);
    v = PathVertex();
    v.kind = PathVertex::Kind::Surface;
    v.it = isect;
    v.ns = bsdf->shadingNormal();
    v.bsdf = bsdf;
    v.areaLight = prim.areaLight;
    v.beta = beta;
    v.pdfFwd = solidAngleToArea(pdfFwd, prev, v);
    ++n;
    if (n >= maxVertices) break;

    Vector3f wo = isect.wo, wi;
    Float pdfDirFwd = 0;
    BxDFType type;
    Spectrum fv = bsdf->sampleF(wo, &wi, ctx.sampler.get1D(), ctx.sampler.get2D(), &pdfDirFwd,
                                kAllBxDF, &type);
    if (fv.isBlack() || pdfDirFwd == 0) break;
    beta *= fv * (absDot(wi, v.ns) / pdfDirFwd);
    if (!fromCamera) {
      beta *= shadingCorrection(wo, wi, v.ns, v.it.n);
      // Refraction scales radiance by (η_i/η_t)², not importance (pbrt 3e §16.1.2): undone here.
      if ((type & kSpecular) && (type & kTransmission) && bsdf->eta != 1) {
        Float e2 = bsdf->eta * bsdf->eta;
        beta *= dot(wo, v.it.n) > 0 ? e2 : 1 / e2;
      }
    }
    Float pdfDirRev = bsdf->pdf(wi, wo);
    if (type & kSpecular) {
      v.delta = true;
      pdfDirFwd = pdfDirRev = 0;
    }
    prev.pdfRev = solidAngleToArea(pdfDirRev, v, prev);
    pdfFwd = pdfDirFwd;
    ray = RayDifferential(isect.spawnRay(wi));
    if (!beta.isFinite() || beta.isBlack()) break;
  }
  return n;
}

int BdptIntegrator::cameraSubpath(const RayDifferential& ray, const Scene& scene,
                                  IntegratorContext& ctx, PathVertex* path, int maxVertices) const {
  PathVertex& c = path[0];
  c = PathVertex();
  c.kind = PathVertex::Kind::Camera;
  c.it.p = camera_.lensPoint(ray);
  c.it.time = ray.time;
  c.beta = Spectrum(1);
  Float pdfPos = 0, pdfDir = 0;
  camera_.pdfWe(ray, &pdfPos, &pdfDir);
  c.onFilm = pdfDir > 0;
  return randomWalk(ray, Spectrum(1), pdfDir, true, scene, ctx, path,
                    maxVertices < 0 ? maxDepth_ + 2 : maxVertices);
}

int BdptIntegrator::lightSubpath(const Scene& scene, IntegratorContext& ctx, Float time,
                                 PathVertex* path, int maxVertices) const {
  Float uLight = ctx.sampler.get1D();
  Point2f uPos = ctx.sampler.get2D(), uDir = ctx.sampler.get2D();
  if (lights_.empty()) return 0;
  Float pmf = 0;
  const Light* light = lightSampler_->sample(lightReference_, uLight, &pmf);
  Ray ray;
  Normal3f nLight;
  Float pdfPos = 0, pdfDir = 0;
  Spectrum Le = light->sampleLe(uPos, uDir, time, &ray, &nLight, &pdfPos, &pdfDir);
  if (pmf == 0 || pdfPos == 0 || pdfDir == 0 || Le.isBlack()) return 0;
  PathVertex& q = path[0];
  q = PathVertex();
  q.kind = PathVertex::Kind::Light;
  q.light = light;
  q.areaLight = dynamic_cast<const AreaLight*>(light);
  q.it.p = ray.o;
  q.it.time = time;
  if (q.areaLight) q.it.n = nLight;
  // The positional throughput; the emitted radiance is evaluated per connection.
  q.beta = Spectrum(1 / (pmf * pdfPos));
  q.pdfFwd = light->atInfinity() ? infiniteLightDensity(-ray.d) : pmf * pdfPos;
  Spectrum beta = Le * (absDot(nLight, ray.d) / (pmf * pdfPos * pdfDir));
  int n = randomWalk(RayDifferential(ray), beta, pdfDir, false, scene, ctx, path,
                     maxVertices < 0 ? maxDepth_ + 1 : maxVertices);
  // From infinity the first hit's density is per area of the disk the rays cross.
  if (light->atInfinity() && n > 1) {
    path[1].pdfFwd = pdfPos;
    if (path[1].onSurface()) path[1].pdfFwd *= absDot(path[1].it.n, ray.d);
  }
  return n;
}

Spectrum BdptIntegrator::connect(const Scene& scene, PathVertex* light, PathVertex* camera, int s,
                                 int t, IntegratorContext& ctx, Point2f* pRaster,
                                 Float* weight) const {
  *weight = 0;
  PathVertex sampled;
  Spectrum L(0);
  // Only the camera path can end on the environment (s = 0).
  if (s > 0 && camera[t - 1].environment) return L;
  if (s == 0) {
    const PathVertex& pt = camera[t - 1];
    if (pt.areaLight || pt.environment) L = pt.beta * Le(pt, camera[t - 2]);
  } else if (t == 1) {
    const PathVertex& qs = light[s - 1];
    if (!qs.connectible()) return L;
    CameraWiSample cs = camera_.sampleWi(qs.it, ctx.sampler.get2D());
    if (cs.pdf == 0 || cs.We.isBlack()) return L;
    sampled.kind = PathVertex::Kind::Camera;
    sampled.it.p = cs.pLens.p;
    sampled.it.time = qs.it.time;
    sampled.beta = cs.We / cs.pdf;
    *pRaster = cs.pRaster;
    if (s == 1) {
      // The emitter seen directly through the lens: only area lights have a point to see.
      if (!qs.areaLight || qs.light->isDelta()) return L;
      L = qs.beta * Le(qs, sampled) * absDot(qs.it.n, cs.wi) * sampled.beta;
    } else {
      L = qs.beta * f(qs, light[s - 2], sampled, true) * sampled.beta * absDot(cs.wi, qs.ns);
    }
    if (!L.isBlack() && !scene.unoccluded(VisibilityTester{qs.it, cs.pLens}, ctx.stats))
      L = Spectrum(0);
  } else if (s == 1) {
    const PathVertex& pt = camera[t - 1];
    Float uChoice = ctx.sampler.get1D();
    Point2f uLight = ctx.sampler.get2D();
    if (!pt.connectible() || lights_.empty()) return L;
    Float pmf = 0;
    const Light* l = vertexLightSampler_
                         ? vertexLightSampler_->sample(LightSampleContext(pt.it), uChoice, &pmf)
                         : lightSampler_->sample(lightReference_, uChoice, &pmf);
    if (!l) return L;
    Vector3f wi;
    Float pdf = 0;
    VisibilityTester vis;
    Spectrum Li = l->sampleLi(pt.it, uLight, &wi, &pdf, &vis);
    if (pdf == 0 || pmf == 0 || Li.isBlack()) return L;
    sampled.kind = PathVertex::Kind::Light;
    sampled.light = l;
    sampled.areaLight = dynamic_cast<const AreaLight*>(l);
    static_cast<Interaction&>(sampled.it) = vis.p1;
    if (!sampled.areaLight) sampled.it.n = Normal3f();
    sampled.beta = Li / (pdf * pmf);
    sampled.pdfFwd = pdfLightOrigin(sampled, pt);
    L = pt.beta * f(pt, camera[t - 2], sampled, false) * sampled.beta * absDot(wi, pt.ns);
    if (!L.isBlack() && !scene.unoccluded(vis, ctx.stats)) L = Spectrum(0);
  } else {
    const PathVertex& qs = light[s - 1];
    const PathVertex& pt = camera[t - 1];
    if (!qs.connectible() || !pt.connectible()) return L;
    Vector3f d = pt.p() - qs.p();
    Float d2 = d.lengthSquared();
    if (d2 == 0) return L;
    Vector3f w = d / std::sqrt(d2);
    Float g = absDot(qs.ns, w) * absDot(pt.ns, w) / d2;
    L = qs.beta * f(qs, light[s - 2], pt, true) * f(pt, camera[t - 2], qs, false) * pt.beta * g;
    if (!L.isBlack() && !scene.unoccluded(VisibilityTester{qs.it, pt.it}, ctx.stats))
      L = Spectrum(0);
  }
  if (L.isBlack()) return L;
  *weight = misWeight(light, camera, sampled, s, t);
  return L;
}

// Veach's thesis §10.2 with the power heuristic: the path x_0 (on a light) ... x_{n-1} (camera)
// was made by strategy s (s light vertices); strategy s' would have made it with density p_s',
// and p_{s'+1} / p_s' = pL[s'] / pE[s'], pL and pE being the area densities of making x_s' from
// the light side and from the camera side. The weight is 1 / Σ (p_s' / p_s)² over the strategies
// that exist for this path: s' = 0 needs a light that is not a delta; other s' join x_{s'-1} and
// x_s', so neither may be specular; (1, 1) needs an area light; t' = 1 (s' = n - 1) needs the
// camera ray on the film (a pixel filter's reach past the edges is the camera strategies' alone).
Float BdptIntegrator::misWeight(const PathVertex* light, const PathVertex* camera,
                                const PathVertex& sampled, int s, int t) const {
  const int n = s + t;
  constexpr int kMax = 64;
  if (n > kMax) return 0;
  const PathVertex* x[kMax];
  // The strategy's fresh vertex: the lens point for t = 1, else the light sample for s = 1.
  for (int k = 0; k < s; ++k) x[k] = (s == 1 && t > 1 && k == 0) ? &sampled : &light[k];
  for (int k = s; k < n; ++k) x[k] = (t == 1 && k == n - 1) ? &sampled : &camera[n - 1 - k];
  Float pL[kMax], pE[kMax];
  bool delta[kMax];
  for (int k = 0; k < n; ++k) {
    bool lightSide = k < s;
    pL[k] = lightSide ? x[k]->pdfFwd : x[k]->pdfRev;
    pE[k] = lightSide ? x[k]->pdfRev : x[k]->pdfFwd;
    delta[k] = x[k]->delta;
  }
  // The densities around the connection, which the subpaths could not know.
  if (s == 0) {
    pL[0] = pdfLightOrigin(*x[0], *x[1]);
    pL[1] = pdfLight(*x[0], *x[1]);
  } else {
    pL[s] = s == 1 ? pdfLight(*x[0], *x[1]) : pdf(*x[s - 1], x[s - 2], *x[s]);
    if (t > 1) pL[s + 1] = pdf(*x[s], x[s - 1], *x[s + 1]);
    pE[s - 1] = pdf(*x[s], t > 1 ? x[s + 1] : nullptr, *x[s - 1]);
    if (s > 1) pE[s - 2] = pdf(*x[s - 1], x[s], *x[s - 2]);
    delta[s - 1] = delta[s] = false;
  }
  // The light's own vertex: delta for point-like and distant lights.
  const PathVertex& origin = *x[0];
  bool deltaLight = !origin.environment && origin.light && origin.light->isDelta();
  bool areaOrigin = origin.areaLight != nullptr && !origin.atInfinity();
  auto exists = [&](int sp) {
    if (sp == 0) return !deltaLight && (origin.areaLight || origin.atInfinity());
    if (sp == 1 && n == 2) return areaOrigin && x[n - 1]->onFilm;
    if (sp == n - 1 && !x[n - 1]->onFilm) return false;  // t' = 1 lands off the film
    return !delta[sp - 1] && !delta[sp];
  };
  Float sum = 0, r = 1;
  for (int sp = s + 1; sp < n; ++sp) {
    r *= remap0(pL[sp - 1]) / remap0(pE[sp - 1]);
    if (exists(sp)) sum += r * r;
  }
  r = 1;
  for (int sp = s - 1; sp >= 0; --sp) {
    r *= remap0(pE[sp]) / remap0(pL[sp]);
    if (exists(sp)) sum += r * r;
  }
  return 1 / (1 + sum);
}

Spectrum BdptIntegrator::Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                            Float* alpha) const {
  const int maxVerts = maxDepth_ + 2;
  std::vector<PathVertex> cameraPath(static_cast<size_t>(maxVerts));
  std::vector<PathVertex> lightPath(static_cast<size_t>(maxVerts));
  int nCamera = cameraSubpath(ray, scene, ctx, cameraPath.data());
  int nLight = lightSubpath(scene, ctx, ray.time, lightPath.data());
  *alpha = (nCamera > 1 && !cameraPath[1].environment) ? 1 : 0;
  Spectrum L(0);
  // Where this camera sample's own strategies (t >= 2) land, for the visualisation images.
  Point2f pCamera(-1, -1);
  if (visualize_ != Visualize::None) camera_.We(ray, &pCamera);
  for (int t = 1; t <= nCamera; ++t)
    for (int s = 0; s <= nLight; ++s) {
      int depth = t + s - 2;
      if (depth < 0 || depth > maxDepth_) continue;
      Point2f pRaster;
      Float weight = 0;
      Spectrum unweighted =
          connect(scene, lightPath.data(), cameraPath.data(), s, t, ctx, &pRaster, &weight);
      Spectrum c = unweighted * weight;
      if (c.isBlack() || !c.isFinite()) continue;
      if (visualize_ != Visualize::None)
        strategyImages_[size_t(strategyIndex(s, t))]->add(
            t == 1 ? pRaster : pCamera, visualize_ == Visualize::Weights ? c : unweighted);
      if (t == 1)
        ctx.splats->add(pRaster, c);
      else
        L += c;
    }
  return L;
}

Spectrum BdptIntegrator::fixedLengthContribution(const RayDifferential& ray, int depth, int s,
                                                 Weighting weighting, bool excludeDirect,
                                                 const Scene& scene, const PathSamplers& samplers,
                                                 MemoryArena& arena, RayStats& stats,
                                                 Point2f* pRaster, bool* elsewhere) const {
  *elsewhere = false;
  const int n = depth + 2;
  if (depth < 0 || depth > maxDepth_) return Spectrum(0);
  if (excludeDirect && depth == 0) return Spectrum(0);
  std::vector<PathVertex> cameraPath(static_cast<size_t>(n));
  std::vector<PathVertex> lightPath(static_cast<size_t>(n));
  IntegratorContext cameraCtx{samplers.camera, arena, stats, nullptr};
  IntegratorContext lightCtx{samplers.light, arena, stats, nullptr};
  IntegratorContext connectCtx{samplers.connection, arena, stats, nullptr};
  // The direct-lighting integrator's specular recursion stops at maxdepth - 1 bounces: an emitter
  // seen through maxdepth specular bounces is left to the chains.
  auto emitterBeyondDirect = [&](const PathVertex* camera, int nVertices) {
    return depth == maxDepth_ && nVertices >= 3 && camera[nVertices - 2].delta;
  };
  Float weight = 0;
  if (weighting == Weighting::Mis) {
    s = std::clamp(s, 0, n);
    const int t = n - s;
    // Both subpaths must reach exactly their lengths for this strategy to make the path.
    if (cameraSubpath(ray, scene, cameraCtx, cameraPath.data(), t) != t) return Spectrum(0);
    if (s > 0 && lightSubpath(scene, lightCtx, ray.time, lightPath.data(), s) != s)
      return Spectrum(0);
    // Beyond depth 1, strategies that connect two light vertices or reach the lens (t = 1) have
    // a non-specular vertex other than the one next to the light: never direct lighting.
    if (excludeDirect &&
        (depth == 1 || (s <= 1 && t >= 2 && onlySpecularBefore(cameraPath.data(), n - 2))) &&
        !(s == 0 && emitterBeyondDirect(cameraPath.data(), n)))
      return Spectrum(0);
    Spectrum L =
        connect(scene, lightPath.data(), cameraPath.data(), s, t, connectCtx, pRaster, &weight);
    *elsewhere = t == 1;
    return L * weight;
  }
  // Unidirectional: the camera subpath of n vertices ends on an emitter (s = 0), or its first
  // n - 1 vertices connect to a light sample (s = 1).
  Spectrum L(0);
  int nCamera = cameraSubpath(ray, scene, cameraCtx, cameraPath.data(), n);
  bool direct = excludeDirect && nCamera >= n - 1 && onlySpecularBefore(cameraPath.data(), n - 2);
  if (nCamera == n && !(direct && !emitterBeyondDirect(cameraPath.data(), n))) {
    bool afterSpecular = n == 2 || cameraPath[size_t(n - 2)].delta;
    if (afterSpecular)
      L += connect(scene, lightPath.data(), cameraPath.data(), 0, n, connectCtx, pRaster, &weight);
  }
  if (nCamera >= n - 1 && n - 1 >= 2 && !direct)
    L +=
        connect(scene, lightPath.data(), cameraPath.data(), 1, n - 1, connectCtx, pRaster, &weight);
  return L;
}

}  // namespace candela
