#include "core/animated_transform.h"

#include <algorithm>

namespace candela {

namespace {

using Mat3 = double[3][3];

double determinant(const Mat3 a) {
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
         a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// The transposed inverse of a (by cofactors: the cofactor matrix divided by the determinant is
// exactly the inverse transpose). a must be invertible.
void inverseTranspose(const Mat3 a, Mat3 out) {
  double inv = 1 / determinant(a);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      out[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) * inv;
    }
}

void multiply(const Mat3 a, const Mat3 b, Mat3 out) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      out[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
}

// |a v| in the Euclidean norm.
double applyLength(const Mat3 a, const Point3f& v) {
  double s = 0;
  for (int i = 0; i < 3; ++i) {
    double c = a[i][0] * v.x + a[i][1] * v.y + a[i][2] * v.z;
    s += c * c;
  }
  return std::sqrt(s);
}

}  // namespace

TransformComponents decompose(const Matrix4x4& m) {
  TransformComponents c;
  for (int i = 0; i < 3; ++i) c.translation[i] = m.m[i][3];
  double a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = m.m[i][j];

  // Polar decomposition A = Q S by averaging Q with its inverse transpose until it stops
  // changing (pbrt 2e §2.9.3; Higham's Newton iteration). It converges quadratically to the
  // orthogonal factor Q of any invertible A; Q has the sign of A's determinant.
  double q[3][3], next[3][3], it[3][3];
  std::copy(&a[0][0], &a[0][0] + 9, &q[0][0]);
  for (int iteration = 0; iteration < 100; ++iteration) {
    if (determinant(q) == 0) break;  // singular input: leave Q = A, S = Q^T A
    inverseTranspose(q, it);
    double change = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        next[i][j] = 0.5 * (q[i][j] + it[i][j]);
        change = std::max(change, std::abs(next[i][j] - q[i][j]));
      }
    std::copy(&next[0][0], &next[0][0] + 9, &q[0][0]);
    if (change <= 1e-15) break;
  }
  // A mirror: take the proper rotation -Q; the reflection moves into S = (-Q)^T A.
  if (determinant(q) < 0)
    for (auto& row : q)
      for (double& v : row) v = -v;
  c.rotation = fromMatrix(q);
  // S = R^T A with R the rotation of the quaternion (orthogonal to double precision).
  double r[3][3], rt[3][3];
  toMatrix(c.rotation, r);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rt[i][j] = r[j][i];
  multiply(rt, a, c.stretch);
  return c;
}

Matrix4x4 compose(const TransformComponents& c) {
  double r[3][3], rs[3][3];
  toMatrix(c.rotation, r);
  multiply(r, c.stretch, rs);
  Matrix4x4 m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m.m[i][j] = Float(rs[i][j]);
    m.m[i][3] = Float(c.translation[i]);
  }
  return m;
}

AnimatedTransform::AnimatedTransform(const Transform& start, Float startTime, const Transform& end,
                                     Float endTime)
    : start_(start), startTime_(startTime), endTime_(endTime) {
  if (start == end) return;
  auto m = std::make_shared<Motion>();
  m->end = end;
  m->keys[0] = decompose(start.matrix());
  m->keys[1] = decompose(end.matrix());
  // q and -q are the same rotation; of the two arcs between the keys take the shorter one.
  if (dot(m->keys[0].rotation, m->keys[1].rotation) < 0) m->keys[1].rotation = -m->keys[1].rotation;
  m->rotationAngle = 2 * angleBetween(m->keys[0].rotation, m->keys[1].rotation);
  motion_ = std::move(m);
}

Transform AnimatedTransform::interpolate(Float time) const {
  if (!motion_ || time <= startTime_) return start_;
  if (time >= endTime_) return motion_->end;
  const TransformComponents* keys = motion_->keys;
  double s = (double(time) - startTime_) / (double(endTime_) - startTime_);
  TransformComponents c;
  for (int i = 0; i < 3; ++i)
    c.translation[i] = (1 - s) * keys[0].translation[i] + s * keys[1].translation[i];
  c.rotation = slerp(s, keys[0].rotation, keys[1].rotation);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      c.stretch[i][j] = (1 - s) * keys[0].stretch[i][j] + s * keys[1].stretch[i][j];
  Matrix4x4 m = compose(c);
  Matrix4x4 mInv;
  if (!inverse(m, &mInv))
    for (auto& row : mInv.m)
      for (Float& v : row) v = std::numeric_limits<Float>::quiet_NaN();
  return Transform(m, mInv);
}

// Samples the motion at K + 1 evenly spaced instants and bounds what happens between them.
// Write x(s) = T(s) + R(s) S(s) p for a point p of b and s in [0, 1] over the interval. The
// union of the boxes at the samples contains every chord x(s_k) x(s_k+1) (each box contains the
// image of all of b, and the union is convex). Along an interval of length h a curve strays from
// its chord by at most h^2 / 8 max |x''| (the error of linear interpolation). T and S are linear
// in s, and slerp turns R at a constant rate w about a fixed axis, so |R'v| = w|v|, |R''v| <=
// w^2 |v|, and x'' = R'' S p + 2 R' (S1 - S0) p, so |x''| <= w^2 max|S p| + 2 w |(S1 - S0) p|,
// where max|S(s) p| <= max(|S0 p|, |S1 p|) (S(s) p is linear in s and the norm convex) and
// both norms are largest at a corner of b. Pure translation and scaling need no padding at all.
Bounds3f AnimatedTransform::motionBounds(const Bounds3f& b) const {
  if (b.empty()) return b;
  if (!motion_) return start_(b);
  const TransformComponents* keys = motion_->keys;
  constexpr int kSteps = 64;
  Bounds3f result = unionOf(start_(b), motion_->end(b));
  Float t0 = startTime_, t1 = endTime_;
  for (int k = 1; k < kSteps; ++k)
    result = unionOf(result, interpolate(lerp(Float(k) / kSteps, t0, t1))(b));

  double dS[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) dS[i][j] = keys[1].stretch[i][j] - keys[0].stretch[i][j];
  double maxS = 0, maxDS = 0;
  for (int c = 0; c < 8; ++c) {
    Point3f p = b.corner(c);
    maxS = std::max({maxS, applyLength(keys[0].stretch, p), applyLength(keys[1].stretch, p)});
    maxDS = std::max(maxDS, applyLength(dS, p));
  }
  double w = motion_->rotationAngle;
  double h = 1.0 / kSteps;
  double curvePad = h * h / 8 * (w * w * maxS + 2 * w * maxDS);
  // Rounding: matrices rounded to float and corners transformed in float, a few ulps of the
  // largest coordinate involved; 2e-6 relative is some thirty of them.
  Float magnitude = std::max(
      {maxComponent(abs(Vector3f(result.pMin))), maxComponent(abs(Vector3f(result.pMax)))});
  Float pad = Float(curvePad) + 2e-6f * magnitude;
  Vector3f v(pad, pad, pad);
  return Bounds3f(result.pMin - v, result.pMax + v);
}

}  // namespace candela
