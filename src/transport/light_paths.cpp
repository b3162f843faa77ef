#include "transport/light_paths.h"

#include "lights/light_sampler.h"

namespace candela {

std::optional<Distribution1D> lightPowerDistribution(const Scene& scene) {
  Distribution1D lights(lightPowerWeights(scene.lights()));
  if (!(lights.integral() > 0)) return std::nullopt;
  return lights;
}

std::optional<LightPathStart> startLightPath(const Scene& scene, const Distribution1D& lightChoice,
                                             Float uLight, const Point2f& uPos, const Point2f& uDir,
                                             Float time) {
  Float lightPmf;
  int li = lightChoice.sampleDiscrete(uLight, &lightPmf);
  if (lightPmf == 0) return std::nullopt;
  LightPathStart start;
  Normal3f nLight;
  Float pdfPos, pdfDir;
  Spectrum le =
      scene.lights()[li]->sampleLe(uPos, uDir, time, &start.ray, &nLight, &pdfPos, &pdfDir);
  if (le.isBlack() || pdfPos == 0 || pdfDir == 0) return std::nullopt;
  // The emission cosine belongs in the weight (pbrt-v2's code has it, the book's text leaves it
  // out); point-like lights report their direction as nLight, so theirs is 1.
  Float cosTheta = nLight == Normal3f(0, 0, 0) ? 1 : absDot(nLight, normalize(start.ray.d));
  start.beta = le * (cosTheta / (lightPmf * pdfPos * pdfDir));
  if (start.beta.isBlack() || !start.beta.isFinite()) return std::nullopt;
  return start;
}

}  // namespace candela
