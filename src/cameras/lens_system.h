// A lens system of spherical interfaces and an aperture stop centred on the optical axis (pbrt 3e
// §6.4.1, after Kolb et al. 1995). Lens space: the film is the plane z = 0, the interfaces lie
// along -z, the scene is beyond them; lengths are in metres. Rays are traced in double precision:
// the thick-lens approximation below follows rays a millionth of an aperture from the axis.
#pragma once

#include <cmath>
#include <vector>

namespace candela {

struct LensVector {
  double x = 0, y = 0, z = 0;
  LensVector operator+(const LensVector& v) const { return {x + v.x, y + v.y, z + v.z}; }
  LensVector operator-(const LensVector& v) const { return {x - v.x, y - v.y, z - v.z}; }
  LensVector operator*(double s) const { return {x * s, y * s, z * s}; }
  double dot(const LensVector& v) const { return x * v.x + y * v.y + z * v.z; }
  double length() const { return std::sqrt(dot(*this)); }
};

struct LensRay {
  LensVector o, d;  // d need not be unit length
  LensVector at(double t) const { return o + d * t; }
};

// One line of a lens file, front (scene side) first.
struct LensInterface {
  double curvatureRadius = 0;  // signed, centre at vertex z + radius; 0: the planar aperture stop
  double thickness = 0;        // along the axis to the next interface (the last: to the film)
  double eta = 1;              // index of the medium behind it, toward the film (stop: air)
  double apertureRadius = 0;   // rays farther from the axis are blocked
  bool isStop() const { return curvatureRadius == 0; }
};

// Cardinal points of the thick-lens approximation (pbrt 3e §6.4.3), lens-space z.
struct ThickLens {
  double focalLength = 0;      // effective focal length (> 0 converges)
  double principalScene = 0;   // principal plane H, met by rays from the film side
  double principalFilm = 0;    // principal plane H', met by rays from the scene side
  double focalPointScene = 0;  // F: where rays parallel from the film side cross the axis
  double focalPointFilm = 0;   // F': where rays parallel from the scene cross the axis
};

class LensSystem {
 public:
  explicit LensSystem(std::vector<LensInterface> interfaces);

  const std::vector<LensInterface>& interfaces() const { return interfaces_; }
  // The distance from the rear vertex to the film (the last interface's thickness).
  double filmDistance() const { return interfaces_.back().thickness; }
  void setFilmDistance(double d) { interfaces_.back().thickness = d; }
  double rearZ() const { return -interfaces_.back().thickness; }
  double frontZ() const;
  double rearApertureRadius() const { return interfaces_.back().apertureRadius; }

  // A ray from the film side (moving toward -z) through every interface, refracted by Snell's
  // law; false when an interface is missed, an aperture blocks it (when clipped) or it is
  // totally internally reflected. *out is the ray leaving the front interface.
  bool traceFromFilm(const LensRay& in, LensRay* out, bool clipped = true) const;
  // The same from the scene side (moving toward +z); *out leaves the rear interface.
  bool traceFromScene(const LensRay& in, LensRay* out, bool clipped = true) const;

  // From two rays parallel to the axis at a paraxial height, one from each side, traced without
  // apertures (focus is the glass's property, not the stop's). Throws std::runtime_error when a
  // paraxial ray does not get through or leaves parallel to the axis (no focus).
  ThickLens thickLens() const;
  // The film distance at which a point on the axis focusDistance in front of the film is
  // sharp, by the thick-lens equation (pbrt 3e §6.4.4). Throws std::runtime_error when no film
  // position focuses it (closer than four focal lengths' worth of conjugates, or a diverging
  // lens).
  double filmDistanceFocusing(double focusDistance) const;

 private:
  bool refractAt(size_t i, double zVertex, double etaI, double etaT, LensRay* r,
                 bool clipped) const;

  std::vector<LensInterface> interfaces_;
};

}  // namespace candela
