// The irradiance cache's parameters, from either dialect (pbrt-v2's IrradianceCacheIntegrator,
// pbrt 2e §15.5; the lrt draft's IrradianceCache, draft §16.5). Where both name the same thing
// they share the parameter: nsamples, maxspeculardepth, maxindirectdepth. The rest combine:
// - maxerror (lrt) scales Ward's radius of validity, the harmonic mean distance to the surfaces
//   the estimate's rays hit; pbrt-v2 has no such knob but caps the radius at half the nearest
//   hit, and both caps apply. 0 (lrt) caches nothing: every point gets a fresh estimate.
// - minpixelspacing/maxpixelspacing (pbrt-v2) clamp that radius to a range of pixels on the
//   image; the lrt draft clamped it to fractions of the scene's size instead.
// - minweight and maxangledifference (pbrt-v2, degrees) decide which samples interpolate (the
//   lrt draft's cosine test had no parameter).
// - nfilter (lrt) drops that many brightest radiance values from each estimate; pbrt-v2 keeps
//   all, which nfilter 0 gives.
#pragma once

#include "core/common.h"

namespace candela {

struct IrradianceCacheSettings {
  Float maxError = 0.2f;
  Float minPixelSpacing = 2.5f, maxPixelSpacing = 15;
  Float minWeight = 0.5f;
  Float maxAngleDifference = 10;  // degrees, in (0, 90]
  int nSamples = 4096;
  int nFilter = 8;  // < nSamples
  int maxSpecularDepth = 5;
  int maxIndirectDepth = 3;
};

}  // namespace candela
