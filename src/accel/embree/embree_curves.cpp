#include "accel/embree/embree_curves.h"

namespace candela {

namespace {

RTCGeometryType embreeType(CurveType type) {
  switch (type) {
    case CurveType::Cylinder:
      return RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE;
    case CurveType::Ribbon:
      return RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_BEZIER_CURVE;
    case CurveType::Flat:
      break;
  }
  return RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE;
}

// Flat curves are tessellated into ray-facing quads; Embree's default of 4 per primitive shows
// facets on curves seen from close by.
constexpr float kFlatTessellationRate = 16;

}  // namespace

RTCGeometry newCurveGeometry(RTCDevice device, CurveType type, const Primitive* primitives,
                             const std::vector<uint32_t>& primIndex) {
  RTCGeometry g = rtcNewGeometry(device, embreeType(type));
  if (!g) return nullptr;
  size_t n = primIndex.size();
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 4 * n));
  auto* ib = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), n));
  float* nb = nullptr;
  if (type == CurveType::Ribbon)
    nb = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_NORMAL, 0,
                                                     RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4 * n));
  if (!vb || !ib || (type == CurveType::Ribbon && !nb)) {
    rtcReleaseGeometry(g);
    return nullptr;
  }
  for (size_t k = 0; k < n; ++k) {
    const auto* shape = static_cast<const CurveShape*>(primitives[primIndex[k]].shape);
    const CurvePiece& piece = shape->piece();
    ib[k] = unsigned(4 * k);
    for (int i = 0; i < 4; ++i) {
      float* v = vb + 4 * (4 * k + i);
      v[0] = piece.bezier.p[i].x;
      v[1] = piece.bezier.p[i].y;
      v[2] = piece.bezier.p[i].z;
      // The radius is linear in s; linear data has Bézier coefficients at thirds.
      v[3] = 0.5f * shape->widthAt(Float(i) / 3);
      if (nb) {
        // The normal curve: linear between the end normals in Bézier form. Embree only takes
        // its direction across the tangent, so it turns the band from one end normal to the
        // other in the same plane as the slerp of the software test, if not at the same rate.
        Float f = Float(i) / 3;
        Vector3f nn = Vector3f(piece.normal[0]) * (1 - f) + Vector3f(piece.normal[1]) * f;
        float* d = nb + 3 * (4 * k + i);
        d[0] = nn.x;
        d[1] = nn.y;
        d[2] = nn.z;
      }
    }
  }
  if (type == CurveType::Flat) rtcSetGeometryTessellationRate(g, kFlatTessellationRate);
  return g;
}

}  // namespace candela
