#include "integrators/dipole_subsurface.h"

#include "accel/primitive.h"
#include "materials/material.h"
#include "materials/subsurface_scattering.h"
#include "reflection/fresnel.h"
#include "transport/light_sampling.h"

namespace candela {

void DipoleSubsurfaceIntegrator::preprocess(const Scene& scene, const PreprocessOptions& options) {
  if (!options.sceneHasSubsurface) {
    if (options.warn)
      options.warn(
          "dipolesubsurface: no material in the scene is \"subsurface\" or \"kdsubsurface\"; it "
          "renders as \"directlighting\"");
    return;
  }
  SubsurfacePointSet set;
  if (!settings_.givenPoints.empty()) {
    set.points = settings_.givenPoints;
    for (const SubsurfacePoint& sp : set.points) set.surfaceArea += sp.area;
    set.time = options.shutterOpen;
  } else {
    SubsurfacePlacementOptions place;
    place.minDistance = settings_.minSampleDistance;
    place.seed = options.seed;
    place.time = options.shutterOpen;
    place.nThreads = options.nThreads;
    set = placeSubsurfacePoints(scene, place);
    if (set.reachedPointLimit && options.warn)
      options.warn("dipolesubsurface: stopped at " + std::to_string(set.points.size()) +
                   " sample points; minsampledistance " + std::to_string(place.minDistance) +
                   " is small for the scene (points cover only part of the surface)");
  }
  if (set.points.empty()) {
    if (options.warn)
      options.warn(
          "dipolesubsurface: no probe line met a translucent surface; no subsurface light");
    return;
  }
  // --quick: a quarter of each light's samples.
  computeDirectIrradiance(scene, options.seed, options.nThreads, options.quick ? 0.25f : 1, &set);
  surfaceArea_ = set.surfaceArea;
  linesTraced_ = set.linesTraced;
  candidates_ = set.candidates;
  prepassRays_ = set.rays.intersectionRays + set.rays.shadowRays;
  octree_ = SubsurfaceOctree(std::move(set.points));
}

std::string DipoleSubsurfaceIntegrator::statsReport() const {
  if (octree_.empty()) return {};
  std::string source =
      settings_.pointsFile.empty() ? std::string() : " (from " + settings_.pointsFile + ")";
  return "Dipole subsurface scattering\n  sample points  " + std::to_string(octree_.pointCount()) +
         source + "\n  translucent surface area  " + std::to_string(surfaceArea_) +
         "\n  probe lines  " + std::to_string(linesTraced_) + "\n  surface crossings  " +
         std::to_string(candidates_) + "\n  prepass rays  " + std::to_string(prepassRays_) +
         "\n  octree nodes  " + std::to_string(octree_.nodeCount()) +
         "\n  octree and point bytes  " + std::to_string(octree_.memoryBytes()) + "\n";
}

Spectrum DipoleSubsurfaceIntegrator::directLight(const SurfaceInteraction& isect, const BSDF& bsdf,
                                                 const Scene& scene, IntegratorContext& ctx) const {
  Spectrum l = uniformSampleAllLights(isect, bsdf, scene, ctx);
  if (octree_.empty()) return l;
  const SubsurfaceScattering* sss = isect.primitive->material->subsurface();
  if (!sss) return l;
  BSSRDFCoefficients c = sss->coefficients(isect);
  DipoleProfile profile(c);
  Spectrum mo = octree_.sum(isect.p, profile, settings_.maxError);
  // pbrt 2e §16.5: out through the boundary with Ft(wo); in with the diffuse transmittance.
  Float ft = 1 - fresnelDielectric(absDot(isect.wo, isect.n), 1, c.eta);
  Float fdt = 1 - diffuseFresnelReflectance(c.eta);
  return l + mo * (ft * fdt * kInvPi);
}

}  // namespace candela
