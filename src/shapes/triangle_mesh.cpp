#include "shapes/triangle_mesh.h"

#include <algorithm>
#include <filesystem>
#include <memory>

#include "core/sampling.h"
#include "shapes/ply_reader.h"
#include "textures/texture.h"

namespace candela {

namespace {

// Per-vertex (u, v), or the draft's default parameterisation (lrt draft §3.6.2).
void vertexUVs(const TriangleMesh& mesh, const int* v, Point2f uv[3]) {
  if (mesh.uv.empty()) {
    uv[0] = Point2f(0, 0);
    uv[1] = Point2f(1, 0);
    uv[2] = Point2f(1, 1);
  } else {
    for (int i = 0; i < 3; ++i) uv[i] = mesh.uv[v[i]];
  }
}

// The (u, v) differences of the 2x2 systems for dp/du, dp/dv and dn/du, dn/dv (lrt draft
// §3.6.2), and the inverse of their determinant; false (and *invDet 0) when (u, v) is degenerate.
bool uvSystem(const TriangleMesh& mesh, const int* v, Vector2f* duv02, Vector2f* duv12,
              Float* invDet) {
  Point2f uv[3];
  vertexUVs(mesh, v, uv);
  *duv02 = uv[0] - uv[2];
  *duv12 = uv[1] - uv[2];
  Float determinant = duv02->x * duv12->y - duv02->y * duv12->x;
  bool degenerate = std::abs(determinant) < 1e-8f;
  *invDet = degenerate ? 0 : 1 / determinant;
  return !degenerate;
}

// dp/du and dp/dv from the 2x2 system dp02 = duv02 (dpdu dpdv)^T, dp12 likewise (lrt draft
// §3.6.2); degenerate (u, v) gives an arbitrary frame around the normal. The default (u, v)
// (0, 0), (1, 0), (1, 1) solve to p1 - p0 and p2 - p1.
inline void positionDerivatives(const TriangleMesh& mesh, const int* v, Vector3f* dpdu,
                                Vector3f* dpdv) {
  const Point3f &p0 = mesh.p[v[0]], &p1 = mesh.p[v[1]], &p2 = mesh.p[v[2]];
  bool degenerateUV = false;
  if (mesh.uv.empty()) {
    *dpdu = p1 - p0;
    *dpdv = p2 - p1;
  } else {
    Vector2f duv02, duv12;
    Float invDet;
    degenerateUV = !uvSystem(mesh, v, &duv02, &duv12, &invDet);
    if (!degenerateUV) {
      Vector3f dp02 = p0 - p2, dp12 = p1 - p2;
      *dpdu = (dp02 * duv12.y - dp12 * duv02.y) * invDet;
      *dpdv = (dp12 * duv02.x - dp02 * duv12.x) * invDet;
    }
  }
  if (degenerateUV || cross(*dpdu, *dpdv).lengthSquared() == 0) {
    Vector3f ng = cross(p2 - p0, p1 - p0);
    Vector3f axis = ng.lengthSquared() > 0 ? normalize(ng) : Vector3f(0, 0, 1);
    coordinateSystem(axis, dpdu, dpdv);
  }
}

}  // namespace

TriangleMesh::TriangleMesh(const Transform& objectToWorld, bool reverseOrientation_,
                           std::vector<int> indices_, std::vector<Point3f> p_,
                           std::vector<Normal3f> n_, std::vector<Vector3f> s_,
                           std::vector<Point2f> uv_)
    : indices(std::move(indices_)),
      p(std::move(p_)),
      n(std::move(n_)),
      s(std::move(s_)),
      uv(std::move(uv_)),
      reverseOrientation(reverseOrientation_),
      transformSwapsHandedness(objectToWorld.swapsHandedness()) {
  // World space once, so that intersection needs no transform (lrt draft §3.6).
  for (Point3f& q : p) q = objectToWorld(q);
  for (Normal3f& nn : n) {
    nn = objectToWorld(nn);
    if (reverseOrientation) nn = -nn;
  }
  for (Vector3f& ss : s) ss = objectToWorld(ss);
  faces.resize(indices.size() / 3);
  for (size_t i = 0; i < faces.size(); ++i) {
    const int* v = &indices[3 * i];
    // Indices out of range are the scene readers' error to report, not a face.
    if (std::any_of(v, v + 3, [&](int k) { return k < 0 || size_t(k) >= p.size(); })) continue;
    Vector3f c = cross(p[v[0]] - p[v[2]], p[v[1]] - p[v[2]]);
    Float length = c.length();
    Face& face = faces[i];
    face.n = length > 0 ? Normal3f(c / length) : Normal3f(0, 0, 1);
    face.area = 0.5f * length;
  }
}

namespace {

struct TriangleHit {
  Float b0, b1, b2, t;
};

// The watertight ray-triangle test (pbrt 3e §3.6.2, after Woop et al. 2013): translate the
// vertices to the ray origin, permute so that the ray's largest direction component is z, and
// shear so the ray runs along +z; the edge functions of the 2D projections then decide the hit
// exactly when they are evaluated consistently, falling back to double when one is zero.
bool intersectTriangle(const Point3f& p0, const Point3f& p1, const Point3f& p2, const Ray& ray,
                       TriangleHit* hit) {
  if (ray.o.hasNaN() || ray.d.hasNaN() || std::isnan(ray.tMax)) return false;
  Vector3f p0t = p0 - ray.o, p1t = p1 - ray.o, p2t = p2 - ray.o;
  int kz = maxDimension(abs(ray.d));
  int kx = kz + 1 == 3 ? 0 : kz + 1;
  int ky = kx + 1 == 3 ? 0 : kx + 1;
  Vector3f d = permute(ray.d, kx, ky, kz);
  if (d.z == 0) return false;
  p0t = permute(p0t, kx, ky, kz);
  p1t = permute(p1t, kx, ky, kz);
  p2t = permute(p2t, kx, ky, kz);
  Float sx = -d.x / d.z, sy = -d.y / d.z, sz = 1 / d.z;
  p0t.x += sx * p0t.z;
  p0t.y += sy * p0t.z;
  p1t.x += sx * p1t.z;
  p1t.y += sy * p1t.z;
  p2t.x += sx * p2t.z;
  p2t.y += sy * p2t.z;

  Float e0 = p1t.x * p2t.y - p1t.y * p2t.x;
  Float e1 = p2t.x * p0t.y - p2t.y * p0t.x;
  Float e2 = p0t.x * p1t.y - p0t.y * p1t.x;
  if (e0 == 0 || e1 == 0 || e2 == 0) {
    // An edge through the ray in float: decide it in double (products of floats are exact).
    e0 = Float(double(p1t.x) * p2t.y - double(p1t.y) * p2t.x);
    e1 = Float(double(p2t.x) * p0t.y - double(p2t.y) * p0t.x);
    e2 = Float(double(p0t.x) * p1t.y - double(p0t.y) * p1t.x);
  }
  if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return false;
  Float det = e0 + e1 + e2;
  if (det == 0 || std::isnan(det)) return false;

  // Scaled distance, compared without dividing by det until the hit is known. The sheared x, y
  // were computed from the unscaled z, whose size their error bounds need below.
  Float maxZw = maxComponent(abs(Vector3f(p0t.z, p1t.z, p2t.z)));
  p0t.z *= sz;
  p1t.z *= sz;
  p2t.z *= sz;
  Float tScaled = e0 * p0t.z + e1 * p1t.z + e2 * p2t.z;
  if (det < 0 && (tScaled >= 0 || tScaled < ray.tMax * det)) return false;
  if (det > 0 && (tScaled <= 0 || tScaled > ray.tMax * det)) return false;
  Float invDet = 1 / det;
  Float t = tScaled * invDet;
  if (!(t < ray.tMax)) return false;

  // Reject t inside the test's own rounding error: such a "hit" is the triangle a spawned ray
  // leaves (pbrt 3e §3.9.6).
  Float maxZt = maxComponent(abs(Vector3f(p0t.z, p1t.z, p2t.z)));
  Float deltaZ = gamma(3) * maxZt;
  Float maxXt = maxComponent(abs(Vector3f(p0t.x, p1t.x, p2t.x)));
  Float maxYt = maxComponent(abs(Vector3f(p0t.y, p1t.y, p2t.y)));
  // The shear added sx z and sy z, so their size bounds its error: (pbrt 3e uses the scaled z
  // here, which mixes units: the bound then grows or shrinks with |d|, rejecting real hits of
  // unnormalised rays on small geometry and admitting self-hits on large geometry; and without
  // |sx|, |sy| a ray along an axis, which has no shear, got a bound that rejected every hit on a
  // sliver of aspect 1e6.)
  Float deltaX = gamma(5) * (maxXt + std::abs(sx) * maxZw);
  Float deltaY = gamma(5) * (maxYt + std::abs(sy) * maxZw);
  Float deltaE = 2 * (gamma(2) * maxXt * maxYt + deltaY * maxXt + deltaX * maxYt);
  Float maxE = maxComponent(abs(Vector3f(e0, e1, e2)));
  Float deltaT = 3 * (gamma(3) * maxE * maxZt + deltaE * maxZt + deltaZ * maxE) * std::abs(invDet);
  if (!(t > deltaT)) return false;

  hit->b0 = e0 * invDet;
  hit->b1 = e1 * invDet;
  hit->b2 = e2 * invDet;
  hit->t = t;
  return true;
}

Vector3f absWeighted(Float b, const Point3f& p) { return abs(Vector3f(p)) * std::abs(b); }

// The barycentrics of the ray's crossing of the triangle's plane, in double: the signed volumes
// d . ((pj - o) x (pk - o)) over their sum (pbrt 3e §3.6.2's edge functions, unsheared; products
// of floats are exact in double). Float barycentrics, Embree's or the watertight test's, are off
// by about 1e-7 of the triangle: on a sliver (aspect 1e6) that is a large part of its width, on a
// triangle far larger than its distance from the origin (a 1e9 ground plane) hundreds of units
// at the origin. Returns false, leaving b alone, when the crossing lies more than 64 float steps
// (at the largest coordinate of the vertices and the origin) outside the triangle: a ray in its
// plane, or a grazing hit that float arithmetic decided.
bool crossingBarycentrics(const double p[3][3], const Ray& ray, double b[3]) {
  double o[3] = {ray.o.x, ray.o.y, ray.o.z}, d[3] = {ray.d.x, ray.d.y, ray.d.z}, a[3][3];
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) a[k][i] = p[k][i] - o[i];
  auto cross = [](const double* u, const double* v, double* w) {
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
  };
  auto length = [](const double* w) { return std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]); };
  auto dot = [](const double* u, const double* v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  };
  // Two cross products for the three volumes: d . (a2 x a0) = a2 . (a0 x d) and
  // d . (a0 x a1) = a1 . (d x a0) share d x a0.
  double q[3], w[3];
  cross(d, a[0], q);
  cross(a[1], a[2], w);
  double e[3] = {dot(d, w), -dot(a[2], q), dot(a[1], q)};
  double sum = e[0] + e[1] + e[2];
  if (!(sum != 0) || !std::isfinite(sum)) return false;
  double invSum = 1 / sum;
  double r[3] = {e[0] * invSum, e[1] * invSum, e[2] * invSum};
  // One test for all three: an infinite or NaN ratio makes the sum so (finite ratios near 1e308
  // that overflow it only send a hit back to its float barycentrics).
  if (!std::isfinite(r[0] + r[1] + r[2])) return false;
  // The distances outside the edges only for a crossing outside some edge (an edge or corner
  // hit), not for the inside ones most hits are.
  if (r[0] < 0 || r[1] < 0 || r[2] < 0) {
    double magnitude = std::max({std::abs(o[0]), std::abs(o[1]), std::abs(o[2])});
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) magnitude = std::max(magnitude, std::abs(p[k][i]));
    double edge[3][3];
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) edge[k][i] = a[(k + 2) % 3][i] - a[(k + 1) % 3][i];
    double normal[3];
    cross(edge[2], edge[1], normal);  // (p1 - p0) x (p0 - p2): twice the area in length
    double twiceArea = length(normal), tolerance = 64 * 0x1p-24 * magnitude;
    // Below 0: outside edge k by -r[k] times the height over it.
    for (int k = 0; k < 3; ++k)
      if (r[k] < 0 && -r[k] * twiceArea > tolerance * length(edge[k])) return false;
  }
  for (int k = 0; k < 3; ++k) b[k] = r[k];
  return true;
}

}  // namespace

Bounds3f TriangleShape::worldBound() const {
  const int* vi = v();
  return unionOf(Bounds3f(mesh_->p[vi[0]], mesh_->p[vi[1]]), mesh_->p[vi[2]]);
}

bool TriangleShape::intersect(const Ray& ray, Float* tHit, SurfaceInteraction* isect) const {
  const int* vi = v();
  TriangleHit hit;
  if (!intersectTriangle(mesh_->p[vi[0]], mesh_->p[vi[1]], mesh_->p[vi[2]], ray, &hit))
    return false;
  if (mesh_->alpha && alphaCulls(ray, hit.b1, hit.b2, hit.t, false)) return false;
  *tHit = hit.t;
  if (isect) interactionAt(ray, hit.b1, hit.b2, hit.t, isect);
  return true;
}

bool TriangleShape::intersectP(const Ray& ray) const {
  const int* vi = v();
  TriangleHit hit;
  if (!intersectTriangle(mesh_->p[vi[0]], mesh_->p[vi[1]], mesh_->p[vi[2]], ray, &hit))
    return false;
  return !(mesh_->shadowAlpha && alphaCulls(ray, hit.b1, hit.b2, hit.t, true));
}

bool TriangleShape::degenerate() const {
  const int* vi = v();
  const Point3f &p0 = mesh_->p[vi[0]], &p1 = mesh_->p[vi[1]], &p2 = mesh_->p[vi[2]];
  for (const Point3f& q : {p0, p1, p2})
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) return true;
  return cross(p1 - p0, p2 - p0) == Vector3f();
}

bool TriangleShape::alphaCulls(const Ray& ray, Float b1, Float b2, Float t, bool forShadow) const {
  const Texture<Float>* a = forShadow ? mesh_->shadowAlpha : mesh_->alpha;
  // Exactly zero, as pbrt-v2 tests it: partial alpha is not stochastic transparency.
  return a && a->evaluate(interactionAt(ray, b1, b2, t)) == 0;
}

// Inline: every hit and light sample needs it.
inline Normal3f TriangleShape::orientedNormal(const TriangleMesh& mesh, int index, Float b0,
                                              Float b1, Float b2, Float* area) {
  const TriangleMesh::Face& face = mesh.faces[index];
  if (area) *area = face.area;
  const Normal3f& n = face.n;
  // Interpolated normals decide the side (pbrt 3e §3.6.3); otherwise the winding, corrected for
  // mirroring transforms and turned by ReverseOrientation (lrt draft §2.8).
  if (!mesh.n.empty()) {
    const int* vi = &mesh.indices[3 * index];
    Normal3f ns = mesh.n[vi[0]] * b0 + mesh.n[vi[1]] * b1 + mesh.n[vi[2]] * b2;
    if (ns.lengthSquared() > 0) return faceForward(n, Vector3f(ns));
    return n;
  }
  return mesh.reverseOrientation != mesh.transformSwapsHandedness ? -n : n;
}

SurfaceInteraction TriangleShape::interactionAt(const Ray& ray, Float b1, Float b2, Float t) const {
  SurfaceInteraction isect;
  interactionAt(ray, b1, b2, t, &isect);
  return isect;
}

void TriangleShape::interactionAt(const TriangleMesh& mesh, int index, const Ray& ray, Float b1In,
                                  Float b2In, SurfaceInteraction* out) {
  const int* vi = &mesh.indices[3 * index];
  const Point3f &p0 = mesh.p[vi[0]], &p1 = mesh.p[vi[1]], &p2 = mesh.p[vi[2]];
  const double pd[3][3] = {{p0.x, p0.y, p0.z}, {p1.x, p1.y, p1.z}, {p2.x, p2.y, p2.z}};
  double b[3] = {1 - double(b1In) - double(b2In), b1In, b2In};
  crossingBarycentrics(pd, ray, b);
  Float b0 = Float(b[0]), b1 = Float(b[1]), b2 = Float(b[2]);

  // The hit point from the barycentrics, interpolated in double (float weights would lose what
  // crossingBarycentrics gained), with the bound of pbrt 3e §3.9.4 for float barycentrics: the
  // offset that keeps spawned rays clear of the triangle must cover Embree's and the watertight
  // test's float view of it.
  Point3f pHit(Float(b[0] * pd[0][0] + b[1] * pd[1][0] + b[2] * pd[2][0]),
               Float(b[0] * pd[0][1] + b[1] * pd[1][1] + b[2] * pd[2][1]),
               Float(b[0] * pd[0][2] + b[1] * pd[1][2] + b[2] * pd[2][2]));
  Vector3f pError = (absWeighted(b0, p0) + absWeighted(b1, p1) + absWeighted(b2, p2)) * gamma(7);
  // The default (u, v) (0, 0), (1, 0), (1, 1) interpolate to (b1 + b2, b2).
  Point2f uvHit = mesh.uv.empty() ? Point2f(b1 + b2, b2)
                                  : mesh.uv[vi[0]] * b0 + mesh.uv[vi[1]] * b1 + mesh.uv[vi[2]] * b2;
  Vector3f wo = -ray.d;
  Float woLen = wo.length();
  if (woLen > 0) wo = wo / woLen;
  // Built in place: *out may be the caller's reused interaction; every member is written.
  Vector3f dpdu, dpdv;
  positionDerivatives(mesh, vi, &dpdu, &dpdv);
  SurfaceInteraction& isect =
      *std::construct_at(out, pHit, pError, uvHit, wo, dpdu, dpdv, Normal3f(), Normal3f(), ray.time,
                         orientedNormal(mesh, index, b0, b1, b2));

  if (mesh.n.empty() && mesh.s.empty()) return;
  // Shading frame from interpolated normal and tangent (lrt draft §3.6.3): ss is the tangent
  // (or dp/du) made perpendicular to ns, ts completes the frame, so cross(ss, ts) = ns.
  Normal3f ns = isect.n;
  if (!mesh.n.empty()) {
    Normal3f ni = mesh.n[vi[0]] * b0 + mesh.n[vi[1]] * b1 + mesh.n[vi[2]] * b2;
    if (ni.lengthSquared() > 0) ns = normalize(ni);
  }
  Vector3f ss = isect.dpdu;
  if (!mesh.s.empty()) {
    Vector3f si = mesh.s[vi[0]] * b0 + mesh.s[vi[1]] * b1 + mesh.s[vi[2]] * b2;
    if (si.lengthSquared() > 0) ss = si;
  }
  Vector3f ts = cross(ns, ss);
  if (ts.lengthSquared() > 0) {
    ts = normalize(ts);
    ss = cross(ts, ns);
  } else {
    coordinateSystem(Vector3f(ns), &ss, &ts);
  }
  // dn/du, dn/dv of the interpolated normal, by the same 2x2 solve as dp/du, dp/dv.
  Normal3f dndu, dndv;
  Vector2f duv02, duv12;
  Float invDet;
  if (!mesh.n.empty() && uvSystem(mesh, vi, &duv02, &duv12, &invDet)) {
    Normal3f dn1 = mesh.n[vi[0]] - mesh.n[vi[2]], dn2 = mesh.n[vi[1]] - mesh.n[vi[2]];
    dndu = (dn1 * duv12.y - dn2 * duv02.y) * invDet;
    dndv = (dn2 * duv02.x - dn1 * duv12.x) * invDet;
  }
  isect.setShadingGeometry(ss, ts, dndu, dndv, true);
}

DirectionCone TriangleShape::normalBound() const {
  const TriangleMesh::Face& face = mesh_->faces[size_t(index_)];
  Vector3f n(face.n);
  if (mesh_->n.empty())
    return DirectionCone::of(mesh_->reverseOrientation != mesh_->transformSwapsHandedness ? -n : n);
  // With interpolated normals the side is the one they point to, and dot(n, ns) is linear in the
  // barycentrics: one sign at the three vertices is that sign everywhere.
  const int* vi = v();
  Float d0 = dot(n, mesh_->n[vi[0]]), d1 = dot(n, mesh_->n[vi[1]]), d2 = dot(n, mesh_->n[vi[2]]);
  if (d0 > 0 && d1 > 0 && d2 > 0) return DirectionCone::of(n);
  if (d0 < 0 && d1 < 0 && d2 < 0) return DirectionCone::of(-n);
  return DirectionCone::everyDirection();
}

Float TriangleShape::area() const {
  const int* vi = v();
  const Point3f &p0 = mesh_->p[vi[0]], &p1 = mesh_->p[vi[1]], &p2 = mesh_->p[vi[2]];
  return 0.5f * cross(p1 - p0, p2 - p0).length();
}

// Inline: both samples are this and little more.
inline Interaction TriangleShape::sampleArea(const Point2f& u, Float* area) const {
  const int* vi = v();
  const Point3f &p0 = mesh_->p[vi[0]], &p1 = mesh_->p[vi[1]], &p2 = mesh_->p[vi[2]];
  Point2f b = sampleUniformTriangle(u);
  Float b2 = 1 - b.x - b.y;
  Point3f p = p0 * b.x + p1 * b.y + p2 * b2;
  Vector3f pError = (absWeighted(b.x, p0) + absWeighted(b.y, p1) + absWeighted(b2, p2)) * gamma(6);
  Normal3f n = orientedNormal(b.x, b.y, b2, area);
  return Interaction(p, n, pError, Vector3f(), 0);
}

Interaction TriangleShape::sample(const Point2f& u, Float* pdf) const {
  Float area;
  Interaction it = sampleArea(u, &area);
  *pdf = area > 0 ? 1 / area : 0;
  return it;
}

Interaction TriangleShape::sample(const Interaction& ref, const Point2f& u, Float* pdf) const {
  Vector3f wi;
  return sampleFrom(ref, u, pdf, &wi);
}

Interaction TriangleShape::sampleFrom(const Interaction& ref, const Point2f& u, Float* pdf,
                                      Vector3f* wi) const {
  Float area;
  Interaction it = sampleArea(u, &area);
  // Area density to solid angle, as Shape::sample; the distance that converts it also makes the
  // unit direction (Shape::sampleFrom's, bit for bit).
  Vector3f d = it.p - ref.p;
  Float dist2 = d.lengthSquared(), dist = std::sqrt(dist2);
  Float cosTheta = dist2 > 0 ? absDot(it.n, d) / dist : 0;
  *pdf = cosTheta > 0 && area > 0 ? dist2 / (cosTheta * area) : 0;
  if (std::isinf(*pdf)) *pdf = 0;
  if (*pdf != 0) *wi = d / dist;
  return it;
}

Float TriangleShape::pdf(const Interaction& ref, const Vector3f& wi) const {
  const int* vi = v();
  const Point3f &p0 = mesh_->p[vi[0]], &p1 = mesh_->p[vi[1]], &p2 = mesh_->p[vi[2]];
  Ray ray = ref.spawnRay(wi);
  TriangleHit hit;
  if (!intersectTriangle(p0, p1, p2, ray, &hit)) return 0;
  if (mesh_->alpha && alphaCulls(ray, hit.b1, hit.b2, hit.t, false)) return 0;
  // The hit point as interactionAt finds it.
  Float b0 = 1 - hit.b1 - hit.b2;
  Point3f pHit = p0 * b0 + p1 * hit.b1 + p2 * hit.b2;
  Float a;
  Float cosTheta = absDot(orientedNormal(b0, hit.b1, hit.b2, &a), -wi);
  if (cosTheta == 0) return 0;
  Float pdf = distanceSquared(ref.p, pHit) / (cosTheta * a);
  return std::isinf(pdf) ? 0 : pdf;
}

std::vector<std::unique_ptr<Shape>> createTriangleShapes(const TriangleMesh* mesh) {
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.reserve(mesh->triangleCount());
  for (int i = 0; i < mesh->triangleCount(); ++i)
    shapes.push_back(std::make_unique<TriangleShape>(mesh, i));
  return shapes;
}

namespace {

// Checks sizes and index ranges; err(name, message) throws at the parameter named.
template <typename ErrorFn>
void validateMesh(const std::vector<int>& indices, size_t nP, size_t nN, size_t nS, size_t nUV,
                  const char* uvName, ErrorFn err) {
  if (indices.empty()) err("indices", "mesh has no triangles");
  if (indices.size() % 3 != 0)
    err("indices",
        "\"indices\" has " + std::to_string(indices.size()) + " entries, not a multiple of 3");
  for (size_t i = 0; i < indices.size(); ++i)
    if (indices[i] < 0 || size_t(indices[i]) >= nP)
      err("indices", "\"indices\"[" + std::to_string(i) + "] = " + std::to_string(indices[i]) +
                         " is out of range: there are " + std::to_string(nP) + " vertices in P");
  auto checkSize = [&](const char* name, size_t n) {
    if (n == 0 || n == nP) return;
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
    std::string message = "\"";
    message += name;
    message += "\" has " + std::to_string(n) + " values but P has " + std::to_string(nP);
    err(name, message + " vertices");
  };
  checkSize("N", nN);
  checkSize("S", nS);
  checkSize(uvName, nUV);
}

std::vector<std::unique_ptr<Shape>> finishMesh(std::unique_ptr<TriangleMesh> mesh,
                                               std::unique_ptr<TriangleMesh>* meshOut) {
  std::vector<std::unique_ptr<Shape>> shapes = createTriangleShapes(mesh.get());
  *meshOut = std::move(mesh);
  return shapes;
}

}  // namespace

std::vector<std::unique_ptr<Shape>> createTriangleMeshShapes(const Transform& objectToWorld,
                                                             bool reverseOrientation,
                                                             const ParamSet& params,
                                                             std::unique_ptr<TriangleMesh>* meshOut,
                                                             const FileLoc& loc) {
  std::vector<int> indices = params.getIntArray("indices");
  std::vector<Point3f> P = params.getPoint3fArray("P");
  std::vector<Normal3f> N = params.getNormal3fArray("N");
  std::vector<Vector3f> S = params.getVector3fArray("S");
  const char* uvName = params.find("uv") ? "uv" : "st";
  std::vector<Point2f> uv = params.getPoint2fArray(uvName);

  auto err = [&](const std::string& name, const std::string& message) {
    throw SceneError(params.locationOf(name, loc), "trianglemesh: " + message);
  };
  if (P.empty()) err("P", "missing vertex positions \"P\" (point3)");
  // A single triangle may omit its indices (pbrt 3e's trianglemesh does the same).
  if (indices.empty() && !params.find("indices") && P.size() == 3) indices = {0, 1, 2};
  if (indices.empty()) err("indices", "missing \"indices\" (integer, 3 per triangle)");
  validateMesh(indices, P.size(), N.size(), S.size(), uv.size(), uvName, err);
  return finishMesh(
      std::make_unique<TriangleMesh>(objectToWorld, reverseOrientation, std::move(indices),
                                     std::move(P), std::move(N), std::move(S), std::move(uv)),
      meshOut);
}

std::vector<std::unique_ptr<Shape>> createPlyMeshShapes(
    const Transform& objectToWorld, bool reverseOrientation, const ParamSet& params,
    std::unique_ptr<TriangleMesh>* meshOut, const FileLoc& loc, const std::string& baseDir) {
  std::string filename = params.getOneString("filename", "");
  FileLoc fileLoc = params.locationOf("filename", loc);
  if (filename.empty()) throw SceneError(fileLoc, "plymesh: missing \"string filename\"");
  std::filesystem::path path(filename);
  if (path.is_relative() && !baseDir.empty()) path = std::filesystem::path(baseDir) / path;

  PlyMesh ply;
  try {
    ply = readPly(path.string());
  } catch (const FileError& e) {
    throw SceneError(fileLoc, std::string("plymesh: ") + e.what());
  }
  auto err = [&](const std::string& /*name*/, const std::string& message) {
    throw SceneError(fileLoc, "plymesh \"" + path.string() + "\": " + message);
  };
  if (ply.positions.empty()) err("P", "no vertices");
  validateMesh(ply.indices, ply.positions.size(), ply.normals.size(), 0, ply.uvs.size(), "uv", err);
  return finishMesh(
      std::make_unique<TriangleMesh>(objectToWorld, reverseOrientation, std::move(ply.indices),
                                     std::move(ply.positions), std::move(ply.normals),
                                     std::vector<Vector3f>(), std::move(ply.uvs)),
      meshOut);
}

}  // namespace candela
