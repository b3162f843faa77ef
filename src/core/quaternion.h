// Unit quaternions for interpolating rotations (pbrt 2e §2.9.2; Shoemake 1985), in double
// precision: they are only used to build matrices, never per hit point. Rotation matrices act on
// column vectors (p' = R p), as Matrix4x4 does.
#pragma once

#include <cmath>

namespace candela {

struct Quaternion {
  double x = 0, y = 0, z = 0, w = 1;  // w + xi + yj + zk

  Quaternion() = default;
  Quaternion(double x_, double y_, double z_, double w_) : x(x_), y(y_), z(z_), w(w_) {}
  Quaternion operator+(const Quaternion& q) const { return {x + q.x, y + q.y, z + q.z, w + q.w}; }
  Quaternion operator-(const Quaternion& q) const { return {x - q.x, y - q.y, z - q.z, w - q.w}; }
  Quaternion operator-() const { return {-x, -y, -z, -w}; }
  Quaternion operator*(double s) const { return {x * s, y * s, z * s, w * s}; }
  double length() const { return std::sqrt(x * x + y * y + z * z + w * w); }
};

inline double dot(const Quaternion& a, const Quaternion& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
}
inline Quaternion normalize(const Quaternion& q) { return q * (1 / q.length()); }

// The angle between two unit quaternions seen as 4D unit vectors. |a - b| = 2 sin(angle / 2) and
// |a + b| = 2 cos(angle / 2), so the ratio gives the angle accurately even when it is tiny, where
// acos(dot) loses all its digits.
inline double angleBetween(const Quaternion& a, const Quaternion& b) {
  return 2 * std::atan2((a - b).length(), (a + b).length());
}

// Spherical linear interpolation along the great arc from a (t = 0) to b (t = 1) at constant
// angular speed (pbrt 2e §2.9.2). The rotation the result stands for turns at twice that speed.
inline Quaternion slerp(double t, const Quaternion& a, const Quaternion& b) {
  double theta = angleBetween(a, b);
  if (theta < 1e-12) return a;
  double s = std::sin(theta);
  return normalize(a * (std::sin((1 - t) * theta) / s) + b * (std::sin(t * theta) / s));
}

// The rotation matrix of a unit quaternion.
inline void toMatrix(const Quaternion& q, double r[3][3]) {
  double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  r[0][0] = 1 - 2 * (yy + zz), r[0][1] = 2 * (xy - wz), r[0][2] = 2 * (xz + wy);
  r[1][0] = 2 * (xy + wz), r[1][1] = 1 - 2 * (xx + zz), r[1][2] = 2 * (yz - wx);
  r[2][0] = 2 * (xz - wy), r[2][1] = 2 * (yz + wx), r[2][2] = 1 - 2 * (xx + yy);
}

// The unit quaternion of a rotation matrix (determinant +1). The component of largest magnitude
// is found first from the diagonal, so the division below is never by a small number.
inline Quaternion fromMatrix(const double r[3][3]) {
  double trace = r[0][0] + r[1][1] + r[2][2];
  Quaternion q;
  if (trace > 0) {
    double s = 2 * std::sqrt(trace + 1);  // 4w
    q = {(r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s, s / 4};
  } else if (r[0][0] >= r[1][1] && r[0][0] >= r[2][2]) {
    double s = 2 * std::sqrt(1 + r[0][0] - r[1][1] - r[2][2]);  // 4x
    q = {s / 4, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s, (r[2][1] - r[1][2]) / s};
  } else if (r[1][1] >= r[2][2]) {
    double s = 2 * std::sqrt(1 + r[1][1] - r[0][0] - r[2][2]);  // 4y
    q = {(r[0][1] + r[1][0]) / s, s / 4, (r[1][2] + r[2][1]) / s, (r[0][2] - r[2][0]) / s};
  } else {
    double s = 2 * std::sqrt(1 + r[2][2] - r[0][0] - r[1][1]);  // 4z
    q = {(r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, s / 4, (r[1][0] - r[0][1]) / s};
  }
  return normalize(q);
}

}  // namespace candela
