// Parameters of pbrt-v3's "curve" shape (pbrt 3e §3.7; the pbrt-v3 file format): the segments
// the control points describe, their widths and normals, and the pieces each is split into.
#include <cmath>
#include <string>

#include "shapes/curve_shape.h"

namespace candela {

namespace {

[[noreturn]] void fail(const ParamSet& params, const std::string& name, const FileLoc& loc,
                       const std::string& message) {
  throw SceneError(params.locationOf(name, loc), message);
}

bool isFinite(const Point3f& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

CurveType curveType(const ParamSet& params, const FileLoc& loc) {
  std::string name = params.getOneString("type", "flat", {"flat", "cylinder", "ribbon"}, loc);
  if (name == "cylinder") return CurveType::Cylinder;
  if (name == "ribbon") return CurveType::Ribbon;
  return CurveType::Flat;
}

// Segment i of the control points, in Bézier form.
CubicBezier segment(const std::vector<Point3f>& cp, bool bspline, int degree, int i) {
  if (degree == 3) {
    if (bspline) return bezierFromCubicBSpline(cp[i], cp[i + 1], cp[i + 2], cp[i + 3]);
    return {{cp[3 * i], cp[3 * i + 1], cp[3 * i + 2], cp[3 * i + 3]}};
  }
  if (bspline) return bezierFromQuadraticBSpline(cp[i], cp[i + 1], cp[i + 2]);
  return bezierFromQuadratic(cp[2 * i], cp[2 * i + 1], cp[2 * i + 2]);
}

// The factor by which the transform scales widths: exact for similarities, the geometric mean
// of the axis scales otherwise (a width has no direction before it meets a ray).
Float widthScale(const Transform& t) {
  const auto& m = t.matrix().m;
  double det = double(m[0][0]) * (double(m[1][1]) * m[2][2] - double(m[1][2]) * m[2][1]) -
               double(m[0][1]) * (double(m[1][0]) * m[2][2] - double(m[1][2]) * m[2][0]) +
               double(m[0][2]) * (double(m[1][0]) * m[2][1] - double(m[1][1]) * m[2][0]);
  return Float(std::cbrt(std::abs(det)));
}

}  // namespace

std::vector<std::unique_ptr<Shape>> createCurveShapes(const Transform& objectToWorld,
                                                      bool reverseOrientation,
                                                      const ParamSet& params, const FileLoc& loc) {
  std::string basis = params.getOneString("basis", "bezier", {"bezier", "bspline"}, loc);
  bool bspline = basis == "bspline";
  // An integer within [2, 3]: quadratic or cubic.
  int degree = params.getOneInt("degree", 3, ValueRange::within(2, 3), loc);
  CurveType type = curveType(params, loc);

  // Bézier segments share their end points: 1 + k d points make k segments of degree d;
  // B-spline segments overlap in d points: n points make n - d.
  std::vector<Point3f> cp = params.getPoint3fArray("P");
  int n = int(cp.size());
  int nSegments = 0;
  if (bspline ? n >= degree + 1 : n >= degree + 1 && (n - 1) % degree == 0)
    nSegments = bspline ? n - degree : (n - 1) / degree;
  if (nSegments == 0) {
    std::string d = std::to_string(degree);
    fail(params, "P", loc,
         "curve \"P\" has " + std::to_string(n) + " points; a degree-" + d + " " + basis +
             (bspline ? " curve needs at least " + std::to_string(degree + 1)
                      : " curve needs " + std::to_string(degree + 1) + " + " + d +
                            "k (segments share their end points)"));
  }
  for (const Point3f& p : cp)
    if (!isFinite(p)) fail(params, "P", loc, "curve \"P\" has a NaN or infinite coordinate");

  Float width = params.getOneFloat("width", 1, ValueRange::nonNegative(), loc);
  Float width0 = params.getOneFloat("width0", width, ValueRange::nonNegative(), loc);
  Float width1 = params.getOneFloat("width1", width, ValueRange::nonNegative(), loc);

  std::vector<Normal3f> normals = params.getNormal3fArray("N");
  if (type == CurveType::Ribbon) {
    if (normals.empty())
      fail(params, "type", loc,
           "ribbon curves need \"normal N\": one normal per segment end (" +
               std::to_string(nSegments + 1) + " here)");
    if (int(normals.size()) != nSegments + 1)
      fail(params, "N", loc,
           "curve \"N\" has " + std::to_string(normals.size()) + " normals; " +
               std::to_string(nSegments) + " segments need " + std::to_string(nSegments + 1));
    for (Normal3f& nn : normals) {
      nn = objectToWorld(nn);
      if (!(nn.lengthSquared() > 0) || !std::isfinite(nn.lengthSquared()))
        fail(params, "N", loc, "curve \"N\" has a zero, NaN or infinite normal");
      nn = normalize(nn);
    }
  } else if (!normals.empty()) {
    fail(params, "N", loc, "curve \"N\" is only used by ribbons (\"string type\" \"ribbon\")");
  }

  int splitDepth = params.getOneInt("splitdepth", 3, ValueRange::within(0, 12), loc);
  int nPieces = 1 << splitDepth;

  Float scale = widthScale(objectToWorld);
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.reserve(size_t(nSegments) * size_t(nPieces));
  for (int i = 0; i < nSegments; ++i) {
    CubicBezier seg = segment(cp, bspline, degree, i);
    for (Point3f& p : seg.p) p = objectToWorld(p);
    // Widths vary linearly along the whole curve (pbrt 3e §3.7.1).
    Float segW0 = lerp(Float(i) / nSegments, width0, width1);
    Float segW1 = lerp(Float(i + 1) / nSegments, width0, width1);
    for (int j = 0; j < nPieces; ++j) {
      Float u0 = Float(j) / nPieces, u1 = Float(j + 1) / nPieces;
      CurvePiece piece;
      piece.bezier = subCurve(seg, u0, u1);
      piece.width[0] = lerp(u0, segW0, segW1) * scale;
      piece.width[1] = lerp(u1, segW0, segW1) * scale;
      if (type == CurveType::Ribbon) {
        piece.normal[0] = slerpUnit(u0, normals[i], normals[i + 1]);
        piece.normal[1] = slerpUnit(u1, normals[i], normals[i + 1]);
      }
      piece.uMin = u0;
      piece.uMax = u1;
      piece.type = type;
      piece.reverseOrientation = reverseOrientation;
      shapes.push_back(std::make_unique<CurveShape>(piece));
    }
  }
  return shapes;
}

}  // namespace candela
