#include "core/transform.h"

#include <stdexcept>

namespace candela {

Matrix4x4::Matrix4x4(const Float mat[4][4]) { std::memcpy(m, mat, 16 * sizeof(Float)); }

Matrix4x4::Matrix4x4(Float t00, Float t01, Float t02, Float t03, Float t10, Float t11, Float t12,
                     Float t13, Float t20, Float t21, Float t22, Float t23, Float t30, Float t31,
                     Float t32, Float t33) {
  m[0][0] = t00, m[0][1] = t01, m[0][2] = t02, m[0][3] = t03;
  m[1][0] = t10, m[1][1] = t11, m[1][2] = t12, m[1][3] = t13;
  m[2][0] = t20, m[2][1] = t21, m[2][2] = t22, m[2][3] = t23;
  m[3][0] = t30, m[3][1] = t31, m[3][2] = t32, m[3][3] = t33;
}

bool Matrix4x4::operator==(const Matrix4x4& o) const {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (m[i][j] != o.m[i][j]) return false;
  return true;
}

bool Matrix4x4::isIdentity() const { return *this == Matrix4x4(); }

Matrix4x4 transpose(const Matrix4x4& a) {
  Matrix4x4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
  return r;
}

Matrix4x4 mul(const Matrix4x4& a, const Matrix4x4& b) {
  Matrix4x4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += double(a.m[i][k]) * double(b.m[k][j]);
      r.m[i][j] = Float(s);
    }
  return r;
}

bool inverse(const Matrix4x4& mat, Matrix4x4* out) {
  double a[4][8];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      a[i][j] = mat.m[i][j];
      a[i][j + 4] = (i == j) ? 1 : 0;
    }
  for (int col = 0; col < 4; ++col) {
    // Partial pivoting on the largest remaining entry of this column.
    int pivot = col;
    for (int r = col + 1; r < 4; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    if (a[pivot][col] == 0 || !std::isfinite(a[pivot][col])) return false;
    if (pivot != col)
      for (int j = 0; j < 8; ++j) std::swap(a[pivot][j], a[col][j]);
    double inv = 1 / a[col][col];
    for (int j = 0; j < 8; ++j) a[col][j] *= inv;
    for (int r = 0; r < 4; ++r) {
      if (r == col || a[r][col] == 0) continue;
      double f = a[r][col];
      for (int j = 0; j < 8; ++j) a[r][j] -= f * a[col][j];
    }
  }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      out->m[i][j] = Float(a[i][j + 4]);
      if (!std::isfinite(out->m[i][j])) return false;
    }
  return true;
}

Transform::Transform(const Matrix4x4& m) : m_(m) {
  if (!inverse(m, &mInv_)) throw std::domain_error("singular transformation matrix");
}

bool Transform::swapsHandedness() const {
  const auto& m = m_.m;
  double det = double(m[0][0]) * (double(m[1][1]) * m[2][2] - double(m[1][2]) * m[2][1]) -
               double(m[0][1]) * (double(m[1][0]) * m[2][2] - double(m[1][2]) * m[2][0]) +
               double(m[0][2]) * (double(m[1][0]) * m[2][1] - double(m[1][1]) * m[2][0]);
  return det < 0;
}

Transform Transform::operator*(const Transform& t) const {
  return Transform(mul(m_, t.m_), mul(t.mInv_, mInv_));
}

Transform inverse(const Transform& t) { return Transform(t.inverseMatrix(), t.matrix()); }
Transform transpose(const Transform& t) {
  return Transform(transpose(t.matrix()), transpose(t.inverseMatrix()));
}

Normal3f Transform::operator()(const Normal3f& n) const {
  const auto& mi = mInv_.m;
  return Normal3f(mi[0][0] * n.x + mi[1][0] * n.y + mi[2][0] * n.z,
                  mi[0][1] * n.x + mi[1][1] * n.y + mi[2][1] * n.z,
                  mi[0][2] * n.x + mi[1][2] * n.y + mi[2][2] * n.z);
}

Ray Transform::operator()(const Ray& r) const {
  Vector3f oError, dError;
  return apply(r, &oError, &dError);
}

RayDifferential Transform::operator()(const RayDifferential& r) const {
  RayDifferential ret((*this)(Ray(r)));
  ret.hasDifferentials = r.hasDifferentials;
  ret.rxOrigin = (*this)(r.rxOrigin);
  ret.ryOrigin = (*this)(r.ryOrigin);
  ret.rxDirection = (*this)(r.rxDirection);
  ret.ryDirection = (*this)(r.ryDirection);
  return ret;
}

Bounds3f Transform::operator()(const Bounds3f& b) const {
  Bounds3f r;
  if (b.empty()) return r;
  for (int c = 0; c < 8; ++c) r = unionOf(r, (*this)(b.corner(c)));
  return r;
}

Point3f Transform::apply(const Point3f& p, Vector3f* absError) const {
  const auto& m = m_.m;
  Float x = p.x, y = p.y, z = p.z;
  Float xp = m[0][0] * x + m[0][1] * y + m[0][2] * z + m[0][3];
  Float yp = m[1][0] * x + m[1][1] * y + m[1][2] * z + m[1][3];
  Float zp = m[2][0] * x + m[2][1] * y + m[2][2] * z + m[2][3];
  Float wp = m[3][0] * x + m[3][1] * y + m[3][2] * z + m[3][3];
  Float xe =
      std::abs(m[0][0] * x) + std::abs(m[0][1] * y) + std::abs(m[0][2] * z) + std::abs(m[0][3]);
  Float ye =
      std::abs(m[1][0] * x) + std::abs(m[1][1] * y) + std::abs(m[1][2] * z) + std::abs(m[1][3]);
  Float ze =
      std::abs(m[2][0] * x) + std::abs(m[2][1] * y) + std::abs(m[2][2] * z) + std::abs(m[2][3]);
  *absError = Vector3f(xe, ye, ze) * gamma(3);
  if (wp == 1) return Point3f(xp, yp, zp);
  return Point3f(xp, yp, zp) / wp;
}

Point3f Transform::apply(const Point3f& p, const Vector3f& pe, Vector3f* absError) const {
  const auto& m = m_.m;
  Vector3f base;
  Point3f r = apply(p, &base);
  for (int i = 0; i < 3; ++i) {
    Float propagated =
        std::abs(m[i][0]) * pe.x + std::abs(m[i][1]) * pe.y + std::abs(m[i][2]) * pe.z;
    (*absError)[i] = base[i] + (gamma(3) + 1) * propagated;
  }
  return r;
}

Vector3f Transform::apply(const Vector3f& v, Vector3f* absError) const {
  const auto& m = m_.m;
  for (int i = 0; i < 3; ++i)
    (*absError)[i] =
        gamma(3) * (std::abs(m[i][0] * v.x) + std::abs(m[i][1] * v.y) + std::abs(m[i][2] * v.z));
  return (*this)(v);
}

Ray Transform::apply(const Ray& r, Vector3f* oError, Vector3f* dError) const {
  Point3f o = apply(r.o, oError);
  Vector3f d = apply(r.d, dError);
  Float tMax = r.tMax;
  Float lengthSquared = d.lengthSquared();
  if (lengthSquared > 0) {
    Float dt = dot(abs(d), *oError) / lengthSquared;
    o += d * dt;
    tMax -= dt;
  }
  return Ray(o, d, tMax, r.time);
}

Transform translate(const Vector3f& d) {
  Matrix4x4 m(1, 0, 0, d.x, 0, 1, 0, d.y, 0, 0, 1, d.z, 0, 0, 0, 1);
  Matrix4x4 mi(1, 0, 0, -d.x, 0, 1, 0, -d.y, 0, 0, 1, -d.z, 0, 0, 0, 1);
  return Transform(m, mi);
}

Transform scale(Float x, Float y, Float z) {
  Matrix4x4 m(x, 0, 0, 0, 0, y, 0, 0, 0, 0, z, 0, 0, 0, 0, 1);
  if (x == 0 || y == 0 || z == 0) throw std::domain_error("scale by zero is not invertible");
  Matrix4x4 mi(1 / x, 0, 0, 0, 0, 1 / y, 0, 0, 0, 0, 1 / z, 0, 0, 0, 0, 1);
  return Transform(m, mi);
}

Transform rotateX(Float theta) {
  Float s = std::sin(radians(theta)), c = std::cos(radians(theta));
  Matrix4x4 m(1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0, 0, 0, 0, 1);
  return Transform(m, transpose(m));
}
Transform rotateY(Float theta) {
  Float s = std::sin(radians(theta)), c = std::cos(radians(theta));
  Matrix4x4 m(c, 0, s, 0, 0, 1, 0, 0, -s, 0, c, 0, 0, 0, 0, 1);
  return Transform(m, transpose(m));
}
Transform rotateZ(Float theta) {
  Float s = std::sin(radians(theta)), c = std::cos(radians(theta));
  Matrix4x4 m(c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
  return Transform(m, transpose(m));
}

// Rotation by theta degrees about an arbitrary axis (Rodrigues' formula).
Transform rotate(Float theta, const Vector3f& axis) {
  if (axis.lengthSquared() == 0) throw std::domain_error("rotation about a zero-length axis");
  Vector3f a = normalize(axis);
  Float s = std::sin(radians(theta)), c = std::cos(radians(theta));
  Matrix4x4 m;
  m.m[0][0] = a.x * a.x + (1 - a.x * a.x) * c;
  m.m[0][1] = a.x * a.y * (1 - c) - a.z * s;
  m.m[0][2] = a.x * a.z * (1 - c) + a.y * s;
  m.m[0][3] = 0;
  m.m[1][0] = a.x * a.y * (1 - c) + a.z * s;
  m.m[1][1] = a.y * a.y + (1 - a.y * a.y) * c;
  m.m[1][2] = a.y * a.z * (1 - c) - a.x * s;
  m.m[1][3] = 0;
  m.m[2][0] = a.x * a.z * (1 - c) - a.y * s;
  m.m[2][1] = a.y * a.z * (1 - c) + a.x * s;
  m.m[2][2] = a.z * a.z + (1 - a.z * a.z) * c;
  m.m[2][3] = 0;
  return Transform(m, transpose(m));
}

Transform lookAt(const Point3f& pos, const Point3f& look, const Vector3f& up) {
  Vector3f dirRaw = look - pos;
  if (dirRaw.lengthSquared() == 0) throw std::domain_error("LookAt: eye and look point coincide");
  if (up.lengthSquared() == 0) throw std::domain_error("LookAt: zero-length up vector");
  Vector3f dir = normalize(dirRaw);
  Vector3f rightRaw = cross(normalize(up), dir);
  if (rightRaw.length() == 0)
    throw std::domain_error("LookAt: up vector and viewing direction are parallel");
  Vector3f right = normalize(rightRaw);
  Vector3f newUp = cross(dir, right);
  // Columns of camera-to-world are the camera's axes in world space.
  Matrix4x4 cameraToWorld(right.x, newUp.x, dir.x, pos.x, right.y, newUp.y, dir.y, pos.y, right.z,
                          newUp.z, dir.z, pos.z, 0, 0, 0, 1);
  Matrix4x4 worldToCamera;
  if (!inverse(cameraToWorld, &worldToCamera)) throw std::domain_error("LookAt: singular matrix");
  return Transform(worldToCamera, cameraToWorld);
}

Transform orthographic(Float zNear, Float zFar) {
  return scale(1, 1, 1 / (zFar - zNear)) * translate(Vector3f(0, 0, -zNear));
}

Transform perspective(Float fov, Float n, Float f) {
  Matrix4x4 persp(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, f / (f - n), -f * n / (f - n), 0, 0, 1, 0);
  Float invTanAng = 1 / std::tan(radians(fov) / 2);
  return scale(invTanAng, invTanAng, 1) * Transform(persp);
}

}  // namespace candela
