// 4x4 matrices and rigid/projective transforms with their inverses (lrt draft §2.7). Applying a
// transform can also carry a conservative bound on the rounding error (pbrt 3e §3.9.4).
#pragma once

#include "core/bounds.h"
#include "core/ray.h"

namespace candela {

struct Matrix4x4 {
  Float m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  Matrix4x4() = default;
  explicit Matrix4x4(const Float mat[4][4]);
  Matrix4x4(Float t00, Float t01, Float t02, Float t03, Float t10, Float t11, Float t12, Float t13,
            Float t20, Float t21, Float t22, Float t23, Float t30, Float t31, Float t32, Float t33);
  bool operator==(const Matrix4x4& o) const;
  bool operator!=(const Matrix4x4& o) const { return !(*this == o); }
  bool isIdentity() const;
};
Matrix4x4 transpose(const Matrix4x4& m);
Matrix4x4 mul(const Matrix4x4& a, const Matrix4x4& b);
// Gauss-Jordan elimination with full pivoting, in double; returns false for a singular matrix.
bool inverse(const Matrix4x4& m, Matrix4x4* inv);

class Transform {
 public:
  Transform() = default;
  explicit Transform(const Matrix4x4& m);  // throws std::domain_error when m is singular
  Transform(const Matrix4x4& m, const Matrix4x4& mInv) : m_(m), mInv_(mInv) {}
  const Matrix4x4& matrix() const { return m_; }
  const Matrix4x4& inverseMatrix() const { return mInv_; }
  bool operator==(const Transform& t) const { return m_ == t.m_; }
  bool operator!=(const Transform& t) const { return !(*this == t); }
  bool isIdentity() const { return m_.isIdentity(); }
  bool swapsHandedness() const;
  Transform operator*(const Transform& t) const;

  // Inline: cameras and shapes apply these once or more per ray, where a call costs as much as
  // the arithmetic.
  Point3f operator()(const Point3f& p) const {
    const auto& m = m_.m;
    Float xp = m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3];
    Float yp = m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3];
    Float zp = m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3];
    Float wp = m[3][0] * p.x + m[3][1] * p.y + m[3][2] * p.z + m[3][3];
    if (wp == 1) return Point3f(xp, yp, zp);
    return Point3f(xp, yp, zp) / wp;
  }
  Vector3f operator()(const Vector3f& v) const {
    const auto& m = m_.m;
    return Vector3f(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
                    m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                    m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z);
  }
  Normal3f operator()(const Normal3f& n) const;  // by the inverse transpose
  Ray operator()(const Ray& r) const;
  RayDifferential operator()(const RayDifferential& r) const;
  Bounds3f operator()(const Bounds3f& b) const;

  // With error bounds: *absError bounds |result - exact result|.
  Point3f apply(const Point3f& p, Vector3f* absError) const;
  Point3f apply(const Point3f& p, const Vector3f& pError, Vector3f* absError) const;
  Vector3f apply(const Vector3f& v, Vector3f* absError) const;
  // Transforms a ray and moves its origin to the edge of its error box along d, so that the
  // transformed ray does not start behind a surface it was spawned from.
  Ray apply(const Ray& r, Vector3f* oError, Vector3f* dError) const;

 private:
  Matrix4x4 m_, mInv_;
};

Transform inverse(const Transform& t);
Transform transpose(const Transform& t);
Transform translate(const Vector3f& delta);
Transform scale(Float x, Float y, Float z);
Transform rotateX(Float thetaDeg);
Transform rotateY(Float thetaDeg);
Transform rotateZ(Float thetaDeg);
Transform rotate(Float thetaDeg, const Vector3f& axis);
// World-to-camera for an eye at pos looking at look (lrt draft §2.7.6); throws
// std::domain_error when up is parallel to the view direction or pos == look.
Transform lookAt(const Point3f& pos, const Point3f& look, const Vector3f& up);
Transform orthographic(Float zNear, Float zFar);
Transform perspective(Float fovDeg, Float zNear, Float zFar);

}  // namespace candela
