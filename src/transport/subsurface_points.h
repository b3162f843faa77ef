// The sample points of the dipole integrator's preprocess (pbrt 2e §16.5; Jensen and Buhler
// 2002): points spread over every surface with a subsurface material, at least minDistance apart,
// each with the area it stands for and the irradiance arriving there.
//
// Placement: pbrt-v2 shot probe rays from the camera; candela has no camera at preprocess time,
// and instead traces isotropic random lines (a uniform direction and a uniform point on the disk
// across the bounding sphere perpendicular to it) through the translucent objects' bounding
// sphere, following each line through every surface it crosses. By Crofton's formula each
// crossing is a uniform sample of surface area, hidden surfaces included, and stands for
// 2 pi R^2 / (lines traced) of it. The crossings on translucent surfaces are thinned by dart
// throwing (Poisson-disk: a candidate is kept when no kept point lies within minDistance), and
// every crossing's area then goes to the kept point nearest to it, which estimates the point's
// Voronoi cell on the surface. Lines are traced in parallel with one random sequence per line
// and thinned in line order, so the points depend on the seed only. First, 16384 probe lines
// across the whole scene find the translucent surfaces' bounds (plus a quarter of their extent),
// and the placement lines cross only that sphere: a translucent object so small that no probe line
// meets it (about 1e-3 of the scene's cross-section) gets no points.
#pragma once

#include <vector>

#include "core/interaction.h"
#include "core/spectrum.h"
#include "transport/integrator_context.h"

namespace candela {

struct SubsurfacePoint {
  Point3f p;
  Normal3f n;  // geometric normal (either side)
  Vector3f pError;
  Float area = 0;
  Spectrum E;  // irradiance (before transmission through the boundary)
};

struct SubsurfacePointSet {
  std::vector<SubsurfacePoint> points;
  Float surfaceArea = 0;     // translucent surface area, by Crofton's formula
  uint64_t linesTraced = 0;  // probe lines of the placement phase
  uint64_t candidates = 0;   // crossings of translucent surfaces
  bool reachedPointLimit = false;
  Float time = 0;  // when the points are lit
  RayStats rays;
};

struct SubsurfacePlacementOptions {
  Float minDistance = 0.25f;
  uint64_t seed = 0;
  Float time = 0;
  int nThreads = 0;
  size_t maxPoints = size_t(1) << 20;
  // Crossings kept for the areas (12 bytes each): placement stops at this many.
  size_t maxCrossings = size_t(1) << 24;
};

// Places the points (irradiance left zero); empty when no line meets a translucent surface.
SubsurfacePointSet placeSubsurfacePoints(const Scene& scene,
                                         const SubsurfacePlacementOptions& options);

// Direct irradiance at every point from every light, nSamples(light) * sampleScale shadow rays
// each, from one random sequence per point (deterministic for any thread count).
void computeDirectIrradiance(const Scene& scene, uint64_t seed, int nThreads, Float sampleScale,
                             SubsurfacePointSet* set);

}  // namespace candela
