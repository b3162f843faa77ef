// pbrt-v3's "curve" shape (pbrt 3e §3.7): a thin strip of width w along a cubic Bézier. One
// CurveShape is one piece of one segment; a curve statement makes 2^splitdepth pieces per
// segment so that each has a tight bound. The Embree aggregate hands the pieces to Embree's
// native curve primitives; the book's aggregates call intersect(), which subdivides the piece
// recursively (curve_intersection.h).
//
// Types: "flat" faces every ray (a ray-facing strip, Embree's flat curves); "ribbon" is a band
// whose normal follows the given normals; "cylinder" is a round tube of radius w / 2. pbrt 3e
// only shades its cylinder as round (a flat strip with a rotated normal); here it is a true
// surface: Embree's round curves sweep a circle of radius w / 2 perpendicular to the curve, which
// for constant width is the swept sphere without its end caps.
//
// Everything is stored in world space: Bézier curves are affine invariant, so the transformed
// control points describe the transformed curve exactly.
#pragma once

#include <memory>
#include <vector>

#include "core/paramset.h"
#include "core/transform.h"
#include "shapes/cubic_bezier.h"
#include "shapes/shape.h"

namespace candela {

enum class CurveType { Flat, Cylinder, Ribbon };

// One piece, parametrised by s in [0, 1] over its own Bézier.
struct CurvePiece {
  CubicBezier bezier;        // world space
  Float width[2] = {1, 1};   // full width at s = 0 and s = 1, world units
  Normal3f normal[2];        // ribbon only: unit normals at s = 0 and s = 1
  Float uMin = 0, uMax = 1;  // the piece's range of its segment's u (the hit's uv.u)
  CurveType type = CurveType::Flat;
  bool reverseOrientation = false;
};

class CurveShape : public Shape {
 public:
  explicit CurveShape(const CurvePiece& piece) : piece_(piece) {}

  const CurvePiece& piece() const { return piece_; }
  Bounds3f worldBound() const override;
  bool intersect(const Ray& ray, Float* tHit, SurfaceInteraction* isect) const override;
  // pbrt 3e's estimate: control polygon length times mean width.
  Float area() const override;
  // Uniform in s and across the width on a strip through the curve (a fixed orientation for
  // flat and round curves): only an approximation, which is why curves refuse area lights.
  Interaction sample(const Point2f& u, Float* pdf) const override;
  const char* kind() const override { return "curve"; }

  // The interaction of a hit at piece parameter s and ray parameter t. surfaceNormal is the
  // normal the intersector found (Embree's Ng, or the software test's), used by round curves
  // and ribbons and ignored by flat curves, which face the ray. u along the curve (the segment's
  // u), v across it in [0, 1]; dpdu the tangent, dpdv across, |dpdv| the width there.
  SurfaceInteraction interactionAt(const Ray& ray, Float s, Float t,
                                   const Vector3f& surfaceNormal) const;
  // Ribbon normal at s: the two end normals interpolated along the great circle (pbrt 3e
  // §3.7.2 slerps them).
  Normal3f ribbonNormal(Float s) const;
  Float widthAt(Float s) const { return lerp(s, piece_.width[0], piece_.width[1]); }

 private:
  CurvePiece piece_;
};

// The unit vector a fraction t of the way from unit a to unit b along their great circle
// (linear and renormalised when they are nearly parallel or opposite).
Normal3f slerpUnit(Float t, const Normal3f& a, const Normal3f& b);

// The "curve" shape: "point P", "string basis" ("bezier", "bspline"), "integer degree" (3, 2),
// "string type" ("flat", "cylinder", "ribbon"), "normal N" (ribbons: one per segment end),
// "float width" (1) or "width0"/"width1" (across the whole curve), "integer splitdepth" (3).
// Bad parameters are SceneErrors at their location (loc when they have none).
std::vector<std::unique_ptr<Shape>> createCurveShapes(const Transform& objectToWorld,
                                                      bool reverseOrientation,
                                                      const ParamSet& params, const FileLoc& loc);

}  // namespace candela
