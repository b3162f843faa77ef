// Points, vectors and normals in 2D and 3D (Pharr & Humphreys, lrt draft §2.1-2.3). Distinct
// types so that a transform applies the right rule to each.
#pragma once

#include <cassert>
#include <ostream>

#include "core/common.h"

namespace candela {

// Tag for the constructors that leave an object's coordinates unset, for hot locals that are
// written in full before anything reads them (zeroing a path vertex's hit point, ~220 bytes, was
// a tenth of the path integrator's own instructions). Every other construction zeroes them.
struct Uninitialized {
  explicit Uninitialized() = default;
};
inline constexpr Uninitialized kUninitialized{};

struct Vector2f {
  Float x = 0, y = 0;
  Vector2f() = default;
  constexpr Vector2f(Float x_, Float y_) : x(x_), y(y_) {}
  Vector2f operator+(Vector2f v) const { return {x + v.x, y + v.y}; }
  Vector2f operator-(Vector2f v) const { return {x - v.x, y - v.y}; }
  Vector2f operator*(Float s) const { return {x * s, y * s}; }
  Float operator[](int i) const { return i == 0 ? x : y; }
  Float& operator[](int i) { return i == 0 ? x : y; }
};

struct Point2f {
  Float x, y;
  constexpr Point2f() : x(0), y(0) {}
  explicit Point2f(Uninitialized) {}
  constexpr Point2f(Float x_, Float y_) : x(x_), y(y_) {}
  Point2f operator+(Vector2f v) const { return {x + v.x, y + v.y}; }
  Point2f operator+(Point2f p) const { return {x + p.x, y + p.y}; }
  Vector2f operator-(Point2f p) const { return {x - p.x, y - p.y}; }
  Point2f operator*(Float s) const { return {x * s, y * s}; }
  bool operator==(Point2f p) const { return x == p.x && y == p.y; }
  Float operator[](int i) const { return i == 0 ? x : y; }
  Float& operator[](int i) { return i == 0 ? x : y; }
};
inline Point2f operator*(Float s, Point2f p) { return p * s; }

struct Point2i {
  int x = 0, y = 0;
  Point2i() = default;
  constexpr Point2i(int x_, int y_) : x(x_), y(y_) {}
  bool operator==(Point2i p) const { return x == p.x && y == p.y; }
  bool operator!=(Point2i p) const { return !(*this == p); }
  int operator[](int i) const { return i == 0 ? x : y; }
  int& operator[](int i) { return i == 0 ? x : y; }
};

struct Vector3f {
  Float x, y, z;
  constexpr Vector3f() : x(0), y(0), z(0) {}
  explicit Vector3f(Uninitialized) {}
  constexpr Vector3f(Float x_, Float y_, Float z_) : x(x_), y(y_), z(z_) {}
  explicit Vector3f(const struct Normal3f& n);
  explicit Vector3f(const struct Point3f& p);
  Vector3f operator+(const Vector3f& v) const { return {x + v.x, y + v.y, z + v.z}; }
  Vector3f& operator+=(const Vector3f& v) {
    x += v.x, y += v.y, z += v.z;
    return *this;
  }
  Vector3f operator-(const Vector3f& v) const { return {x - v.x, y - v.y, z - v.z}; }
  Vector3f& operator-=(const Vector3f& v) {
    x -= v.x, y -= v.y, z -= v.z;
    return *this;
  }
  Vector3f operator*(Float s) const { return {x * s, y * s, z * s}; }
  Vector3f& operator*=(Float s) {
    x *= s, y *= s, z *= s;
    return *this;
  }
  Vector3f operator/(Float s) const {
    Float inv = Float(1) / s;
    return {x * inv, y * inv, z * inv};
  }
  Vector3f& operator/=(Float s) { return *this *= Float(1) / s; }
  Vector3f operator-() const { return {-x, -y, -z}; }
  bool operator==(const Vector3f& v) const { return x == v.x && y == v.y && z == v.z; }
  bool operator!=(const Vector3f& v) const { return !(*this == v); }
  Float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  Float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  Float lengthSquared() const { return x * x + y * y + z * z; }
  Float length() const { return std::sqrt(lengthSquared()); }
  bool hasNaN() const { return std::isnan(x) || std::isnan(y) || std::isnan(z); }
};
inline Vector3f operator*(Float s, const Vector3f& v) { return v * s; }

struct Point3f {
  Float x, y, z;
  constexpr Point3f() : x(0), y(0), z(0) {}
  explicit Point3f(Uninitialized) {}
  constexpr Point3f(Float x_, Float y_, Float z_) : x(x_), y(y_), z(z_) {}
  explicit Point3f(const Vector3f& v) : x(v.x), y(v.y), z(v.z) {}
  Point3f operator+(const Vector3f& v) const { return {x + v.x, y + v.y, z + v.z}; }
  Point3f& operator+=(const Vector3f& v) {
    x += v.x, y += v.y, z += v.z;
    return *this;
  }
  Point3f operator-(const Vector3f& v) const { return {x - v.x, y - v.y, z - v.z}; }
  Vector3f operator-(const Point3f& p) const { return {x - p.x, y - p.y, z - p.z}; }
  // Weighted sums of points (barycentric interpolation, filtering).
  Point3f operator+(const Point3f& p) const { return {x + p.x, y + p.y, z + p.z}; }
  Point3f& operator+=(const Point3f& p) {
    x += p.x, y += p.y, z += p.z;
    return *this;
  }
  Point3f operator*(Float s) const { return {x * s, y * s, z * s}; }
  Point3f operator/(Float s) const {
    Float inv = Float(1) / s;
    return {x * inv, y * inv, z * inv};
  }
  bool operator==(const Point3f& p) const { return x == p.x && y == p.y && z == p.z; }
  bool operator!=(const Point3f& p) const { return !(*this == p); }
  Float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  Float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  bool hasNaN() const { return std::isnan(x) || std::isnan(y) || std::isnan(z); }
};
inline Point3f operator*(Float s, const Point3f& p) { return p * s; }

struct Normal3f {
  Float x, y, z;
  constexpr Normal3f() : x(0), y(0), z(0) {}
  explicit Normal3f(Uninitialized) {}
  constexpr Normal3f(Float x_, Float y_, Float z_) : x(x_), y(y_), z(z_) {}
  explicit Normal3f(const Vector3f& v) : x(v.x), y(v.y), z(v.z) {}
  Normal3f operator+(const Normal3f& n) const { return {x + n.x, y + n.y, z + n.z}; }
  Normal3f& operator+=(const Normal3f& n) {
    x += n.x, y += n.y, z += n.z;
    return *this;
  }
  Normal3f operator-(const Normal3f& n) const { return {x - n.x, y - n.y, z - n.z}; }
  Normal3f operator*(Float s) const { return {x * s, y * s, z * s}; }
  Normal3f operator/(Float s) const {
    Float inv = Float(1) / s;
    return {x * inv, y * inv, z * inv};
  }
  Normal3f operator-() const { return {-x, -y, -z}; }
  bool operator==(const Normal3f& n) const { return x == n.x && y == n.y && z == n.z; }
  Float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  Float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  Float lengthSquared() const { return x * x + y * y + z * z; }
  Float length() const { return std::sqrt(lengthSquared()); }
  bool hasNaN() const { return std::isnan(x) || std::isnan(y) || std::isnan(z); }
};
inline Normal3f operator*(Float s, const Normal3f& n) { return n * s; }

inline Vector3f::Vector3f(const Normal3f& n) : x(n.x), y(n.y), z(n.z) {}
inline Vector3f::Vector3f(const Point3f& p) : x(p.x), y(p.y), z(p.z) {}

// Dot products between any pair of vector-like types.
template <typename A, typename B>
inline Float dot(const A& a, const B& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename A, typename B>
inline Float absDot(const A& a, const B& b) {
  return std::abs(dot(a, b));
}
// Cross products in double precision avoid catastrophic cancellation (pbrt 3e §2.2.1).
template <typename A, typename B>
inline Vector3f cross(const A& a, const B& b) {
  double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
  return Vector3f(Float(ay * bz - az * by), Float(az * bx - ax * bz), Float(ax * by - ay * bx));
}
inline Vector3f normalize(const Vector3f& v) { return v / v.length(); }
inline Normal3f normalize(const Normal3f& n) { return n / n.length(); }
inline Vector3f abs(const Vector3f& v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }
inline Point3f abs(const Point3f& p) { return {std::abs(p.x), std::abs(p.y), std::abs(p.z)}; }
inline Float maxComponent(const Vector3f& v) { return std::max(v.x, std::max(v.y, v.z)); }
inline int maxDimension(const Vector3f& v) {
  return (v.x > v.y) ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2);
}
inline Vector3f permute(const Vector3f& v, int x, int y, int z) { return {v[x], v[y], v[z]}; }
inline Point3f permute(const Point3f& p, int x, int y, int z) { return {p[x], p[y], p[z]}; }
inline Float distance(const Point3f& a, const Point3f& b) { return (a - b).length(); }
inline Float distanceSquared(const Point3f& a, const Point3f& b) { return (a - b).lengthSquared(); }
inline Point3f lerp(Float t, const Point3f& a, const Point3f& b) { return a * (1 - t) + b * t; }
inline Point3f min(const Point3f& a, const Point3f& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
inline Point3f max(const Point3f& a, const Point3f& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
// Flips n to lie in the hemisphere of v.
inline Normal3f faceForward(const Normal3f& n, const Vector3f& v) {
  return dot(n, v) < 0.f ? -n : n;
}
inline Vector3f faceForward(const Vector3f& n, const Vector3f& v) {
  return dot(n, v) < 0.f ? -n : n;
}

// An orthonormal basis around unit v1 (Duff et al. 2017, branchless and continuous).
inline void coordinateSystem(const Vector3f& v1, Vector3f* v2, Vector3f* v3) {
  Float sign = std::copysign(Float(1), v1.z);
  Float a = -1 / (sign + v1.z);
  Float b = v1.x * v1.y * a;
  *v2 = Vector3f(1 + sign * v1.x * v1.x * a, sign * b, -sign * v1.x);
  *v3 = Vector3f(b, sign + v1.y * v1.y * a, -v1.y);
}

inline Vector3f sphericalDirection(Float sinTheta, Float cosTheta, Float phi) {
  return {clamp(sinTheta, -1, 1) * std::cos(phi), clamp(sinTheta, -1, 1) * std::sin(phi),
          clamp(cosTheta, -1, 1)};
}

inline std::ostream& operator<<(std::ostream& os, const Vector3f& v) {
  return os << "[" << v.x << ", " << v.y << ", " << v.z << "]";
}
inline std::ostream& operator<<(std::ostream& os, const Point3f& p) {
  return os << "(" << p.x << ", " << p.y << ", " << p.z << ")";
}
inline std::ostream& operator<<(std::ostream& os, const Normal3f& n) {
  return os << "<" << n.x << ", " << n.y << ", " << n.z << ">";
}

}  // namespace candela
