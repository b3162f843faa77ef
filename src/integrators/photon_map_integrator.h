// "photonmap" (alias "exphotonmap"): Jensen's photon mapping as pbrt 2e §15.6 presents it, with the
// lrt draft's options. The integrand is partitioned (pbrt 2e eq. 15.18): emission and perfectly
// specular bounces are traced as in Whitted's method; direct lighting is sampled from the lights
// (or estimated from the direct photon map); caustics (light reaching a diffuse surface through
// specular bounces only) come from the caustic map; the rest of the indirect light from the
// indirect map, read directly or through a final gather.
#pragma once

#include "integrators/specular_recursion.h"
#include "transport/final_gather.h"
#include "transport/photon_density.h"
#include "transport/photon_map.h"
#include "transport/photon_shooting.h"

namespace candela {

struct PhotonMapSettings {
  int causticPhotons = 20000;    // photons wanted in the caustic map
  int indirectPhotons = 100000;  // ... in the indirect map
  int directPhotons = 100000;    // ... in the direct map (lrt draft; only with directWithPhotons)
  int nUsed = 50;                // photons per density estimate
  Float maxDist = 0.1f;          // largest search radius
  int nFilter = 0;               // lrt draft: brightest photons dropped from each estimate
  int maxSpecularDepth = 5;      // specular recursion depth, as whitted's maxdepth
  int maxPhotonDepth = 5;        // surface interactions per photon path
  bool finalGather = true;
  int finalGatherSamples = 32;     // split evenly between BSDF and photon-guided directions
  Float gatherAngle = 10;          // degrees, half-angle of the photon-guided cones
  bool directWithPhotons = false;  // lrt draft: direct lighting from the direct map
};

class PhotonMapIntegrator : public SpecularRecursionIntegrator {
 public:
  explicit PhotonMapIntegrator(const PhotonMapSettings& settings);
  void preprocess(const Scene& scene, const PreprocessOptions& options) override;
  // What preprocess built: name -> count (maps left unbuilt are absent).
  std::map<std::string, long> buildCounts() const;
  std::string statsReport() const override;
  const PhotonMapSettings& settings() const { return settings_; }
  const PhotonMap& causticMap() const { return caustic_; }
  const PhotonMap& indirectMap() const { return indirect_; }
  const PhotonMap& directMap() const { return direct_; }
  const RadiancePhotonMap& radianceMap() const { return radiance_; }

 protected:
  // Everything but emission and specular bounces, reflected at isect toward isect.wo.
  Spectrum directLight(const SurfaceInteraction& isect, const BSDF& bsdf, const Scene& scene,
                       IntegratorContext& ctx) const override;

 private:
  void deriveLookups();  // estimate_ and gather_ from settings_
  // A warning when maxdist finds far fewer photons than nused asks for, with a radius that would.
  void warnAboutSearchRadius(const Scene& scene, const PreprocessOptions& options) const;
  void computeRadiancePhotons(std::vector<RadiancePhotonSite> sites, const PhotonMap& direct,
                              int nThreads);

  PhotonMapSettings settings_;
  DensityEstimate estimate_;
  FinalGatherSettings gather_;
  PhotonMap caustic_, indirect_, direct_;
  RadiancePhotonMap radiance_;
  uint64_t photonPaths_ = 0, photonRays_ = 0;
};

}  // namespace candela
