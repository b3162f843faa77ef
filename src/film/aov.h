// Arbitrary output variables: extra EXR layers beside the beauty image, for compositing. Named
// as Nuke and OpenImageIO read them: albedo.R/G/B, N.X/Y/Z, Z, P.X/Y/Z, variance.R/G/B, samples.
#pragma once

#include <string>
#include <vector>

#include "core/error.h"
#include "core/spectrum.h"
#include "core/vector.h"

namespace candela {

enum AovFlag : unsigned {
  kAovAlbedo = 1u << 0,    // reflectance of the first surface (its BSDF's directional albedo)
  kAovNormal = 1u << 1,    // world-space shading normal of the first surface, unit length
  kAovDepth = 1u << 2,     // distance along the camera ray (from its start on the near plane)
                           // to the first surface, the nearest in the pixel; +inf where none
  kAovPosition = 1u << 3,  // world-space position of the first surface
  kAovVariance = 1u << 4,  // estimated variance of the pixel's mean radiance
  kAovSamples = 1u << 5,   // samples taken in the pixel
};
// AOVs that need the first surface hit of each camera ray.
inline constexpr unsigned kAovGeometric = kAovAlbedo | kAovNormal | kAovDepth | kAovPosition;

// "albedo,normal,depth" -> flags; unknown names are a SceneError at loc listing the known ones.
unsigned parseAovList(const std::string& list, const FileLoc& loc);
// Channel names of the flags, in the order the film writes them.
std::vector<std::string> aovChannelNames(unsigned flags);

// What one camera ray saw first.
struct AovSample {
  bool hit = false;
  Spectrum albedo;
  Normal3f normal;
  Float depth = kInfinity;
  Point3f position;
};

}  // namespace candela
