// "infinite": radiance arriving from every direction at infinity, L times an optional
// latitude-longitude map (lrt draft §13.5, sampling §15.4; inventory §16). Light-space direction
// (θ from +z, φ = atan2(y, x)) looks up texel (s, t) = (φ / 2π, θ / π); the map's top row is θ = 0.
//
// Sampling: without a map, directions are uniform over the sphere (pdf 1 / 4π). With a map, a
// piecewise-constant 2D distribution over (s, t) proportional to each texel's luminance times
// sin θ at its centre picks (s, t); the map (θ, φ) -> direction has Jacobian 2π² sin θ, so the
// solid-angle pdf is p(s, t) / (2π² sin θ). The radiance is the texel's own value (no filtering),
// so Le and the sampling density are constant over the same cells: wherever Le > 0 the pdf is too
// (a bilinear lookup would leak light into cells the distribution gives zero probability).
#pragma once

#include <memory>
#include <vector>

#include "core/sampling.h"
#include "core/transform.h"
#include "lights/light.h"

namespace candela {

// A scene-linear lat-long image, row-major, row 0 at θ = 0.
struct LatLongMap {
  int width = 0, height = 0;
  std::vector<Spectrum> texels;
};

class InfiniteAreaLight : public Light {
 public:
  // map may be empty (width 0): uniform radiance L.
  InfiniteAreaLight(const Transform& lightToWorld, const Spectrum& radiance, int nSamples,
                    LatLongMap map);
  Spectrum sampleLi(const Interaction& ref, const Point2f& u, Vector3f* wi, Float* pdf,
                    VisibilityTester* vis) const override;
  Float pdfLi(const Interaction& ref, const Vector3f& wi) const override;
  Spectrum sampleLe(const Point2f& uPos, const Point2f& uDir, Float time, Ray* ray,
                    Normal3f* nLight, Float* pdfPos, Float* pdfDir) const override;
  void pdfLe(const Ray& ray, const Normal3f& nLight, Float* pdfPos, Float* pdfDir) const override;
  // What crosses the scene's bounding disk from all directions: π R² ∫ L dω.
  Spectrum power() const override;
  bool isDelta() const override { return false; }
  bool atInfinity() const override { return true; }
  Spectrum Le(const RayDifferential& ray) const override { return radiance(ray.d); }
  void preprocess(const Bounds3f& sceneBounds) override;
  // The radiance arriving from world direction w (w toward the sky).
  Spectrum radiance(const Vector3f& w) const;

 private:
  // Texel (i, j), i taken modulo the width, j clamped to the rows.
  const Spectrum& texel(int i, int j) const;
  // The map at (s, t), bilinear between texel centres.
  Spectrum interpolated(const Point2f& st) const;
  // (s, t) in [0, 1]^2 of a world direction, and sin θ there.
  Point2f lookupCoordinates(const Vector3f& w, Float* sinTheta) const;

  Transform lightToWorld_, worldToLight_;
  Spectrum radiance_;
  LatLongMap map_;
  std::unique_ptr<Distribution2D> distribution_;  // null without a map
  Point3f sceneCenter_{0, 0, 0};
  Float sceneRadius_ = 1e4f;  // until preprocess (see DistantLight)
};

}  // namespace candela
