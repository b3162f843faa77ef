// The anisotropic Trowbridge-Reitz (GGX) microfacet distribution of pbrt-v3 (pbrt 3e §8.4.2)
// with Smith's masking and shadowing (pbrt 3e §8.4.3) and sampling of the distribution of
// visible normals (pbrt 3e §14.1.1; Heitz and d'Eon 2014). alphaX and alphaY are the slope
// roughnesses along the shading frame's x (dp/du) and y axes. Everything is symmetric about the
// surface: a direction below it is treated as its mirror image above.
#pragma once

#include "reflection/bxdf.h"

namespace candela {

// pbrt-v3's map from a user roughness in [0, 1] to alpha, a fit in x = ln(max(r, 1e-3)) (pbrt 3e
// §8.4.2): alpha = 1.62142 + 0.819955 x + 0.1734 x^2 + 0.0171201 x^3 + 0.000640711 x^4.
Float roughnessToAlpha(Float roughness);

class TrowbridgeReitzDistribution {
 public:
  // Alphas below kMinAlpha are raised to it: at 0 the distribution is a delta that D cannot
  // express (smooth surfaces are the specular BxDFs' job).
  static constexpr Float kMinAlpha = 1e-4f;
  TrowbridgeReitzDistribution(Float alphaX, Float alphaY);

  // D(wh) = 1 / (pi ax ay cos^4 theta_h (1 + tan^2 theta_h (cos^2 phi / ax^2 +
  // sin^2 phi / ay^2))^2), normalised over projected area: integral D cos theta_h dwh = 1.
  Float d(const Vector3f& wh) const;
  // Smith's auxiliary function, Lambda(w) = (sqrt(1 + alpha(phi)^2 tan^2 theta) - 1) / 2 with
  // alpha(phi)^2 = ax^2 cos^2 phi + ay^2 sin^2 phi; infinite at the horizon.
  Float lambda(const Vector3f& w) const;
  // Fraction of microfacets visible from w, G1 = 1 / (1 + Lambda(w)).
  Float g1(const Vector3f& w) const { return 1 / (1 + lambda(w)); }
  // Fraction visible from both directions, G = 1 / (1 + Lambda(wo) + Lambda(wi)): the form with
  // correlated heights that pbrt 3e §8.4.3 uses.
  Float g(const Vector3f& wo, const Vector3f& wi) const {
    return 1 / (1 + lambda(wo) + lambda(wi));
  }

  // A microfacet normal drawn from the normals visible from wo, on wo's side of the surface,
  // with density pdf(wo, wh). The construction is Heitz's (2018): stretch wo to the unit-roughness
  // configuration, draw a point on the projected hemisphere seen from there, unstretch.
  Vector3f sampleWh(const Vector3f& wo, const Point2f& u) const;
  // The visible-normal density D_wo(wh) = G1(wo) max(0, wo . wh) D(wh) / |cos theta_o|, with wh
  // taken on wo's side (pbrt 3e §14.1.1).
  Float pdf(const Vector3f& wo, const Vector3f& wh) const;

  Float alphaX() const { return alphaX_; }
  Float alphaY() const { return alphaY_; }

 private:
  Float alphaX_, alphaY_;
};

}  // namespace candela
