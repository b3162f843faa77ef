// A transform that changes over the shutter interval (TransformTimes / ActiveTransform): the two
// key transforms are decomposed into translation, rotation (a quaternion) and scale, which are
// interpolated separately (lrt draft §2.7 scaffolding; pbrt 2e §2.9.3). Interpolating the
// matrices entry by entry instead would shrink a rotating object half way through a turn.
#pragma once

#include <memory>

#include "core/quaternion.h"
#include "core/transform.h"

namespace candela {

// The affine part of a matrix as M = T R S: a translation, a rotation and a symmetric "stretch"
// S (scale and shear), by polar decomposition of the upper 3x3 block. A mirroring matrix gets
// the rotation R = -Q of its orthogonal factor Q, so that S carries the reflection (S is then
// negative definite) and R is always a proper rotation a quaternion can hold. The projective
// row is ignored: shape and instance transforms are affine.
struct TransformComponents {
  double translation[3] = {0, 0, 0};
  Quaternion rotation;
  double stretch[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
};
TransformComponents decompose(const Matrix4x4& m);
Matrix4x4 compose(const TransformComponents& c);

class AnimatedTransform {
 public:
  AnimatedTransform() = default;
  explicit AnimatedTransform(const Transform& t) : start_(t) {}
  // Animated when start != end; startTime <= endTime.
  AnimatedTransform(const Transform& start, Float startTime, const Transform& end, Float endTime);
  bool isAnimated() const { return motion_ != nullptr; }
  const Transform& start() const { return start_; }
  const Transform& end() const { return motion_ ? motion_->end : start_; }
  Float startTime() const { return startTime_; }
  Float endTime() const { return endTime_; }
  // The transform at time t, clamped to [startTime, endTime]: exactly start() at or before
  // startTime and exactly end() at or after endTime. In between, T and S are interpolated
  // linearly and R by slerp along the shorter arc. If the keys have opposite handedness, S
  // passes through a singular matrix; at that instant the inverse is not finite (NaN).
  Transform interpolate(Float time) const;
  // use(the transform at time t): a still one's single transform passed in place, not copied as
  // interpolate() would copy it (cameras do this per ray).
  template <typename Use>
  decltype(auto) withTransformAt(Float time, Use&& use) const {
    return motion_ ? use(interpolate(time)) : use(start_);
  }
  // A box containing b under every transform of the interval (see the .cpp for the bound).
  Bounds3f motionBounds(const Bounds3f& b) const;

 private:
  // Only animated transforms carry the end key and the decomposition; it never changes once
  // made, so copies share it. A static transform (most instances) is just start_.
  struct Motion {
    Transform end;
    TransformComponents keys[2];  // the decomposed start and end
    double rotationAngle = 0;     // total angle the rotation turns through over the interval
  };
  Transform start_;
  Float startTime_ = 0, endTime_ = 1;
  std::shared_ptr<const Motion> motion_;
};

}  // namespace candela
