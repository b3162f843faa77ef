#include "core/direction_cone.h"

#include <algorithm>
#include <cmath>

namespace candela {

namespace {
// The union's half-angle is widened by this much (radians) so that it holds both cones after
// rounding: a cosine near 1 stored as a Float pins the angle down only to about 3.5e-4.
constexpr Float kWidening = 1e-3f;
}  // namespace

DirectionCone unionOf(const DirectionCone& a, const DirectionCone& b) {
  if (a.coversEveryDirection() || b.coversEveryDirection()) return DirectionCone::everyDirection();
  Float thetaA = safeAcos(a.cosTheta), thetaB = safeAcos(b.cosTheta);
  // The angle between the axes, by atan2 (acos of a dot product near 1 loses half the digits).
  Vector3f k = cross(a.w, b.w);
  Float kLength = k.length();
  Float thetaD = std::atan2(kLength, dot(a.w, b.w));
  // One cone inside the other.
  if (std::min(thetaD + thetaB, kPi) <= thetaA) return a;
  if (std::min(thetaD + thetaA, kPi) <= thetaB) return b;
  // The union's half-angle spans from a's far edge to b's far edge.
  Float thetaO = (thetaA + thetaD + thetaB) / 2;
  if (thetaO + kWidening >= kPi) return DirectionCone::everyDirection();
  // Its axis: a.w turned toward b.w by thetaO - thetaA, in the plane the two axes span.
  if (!(kLength > 0)) return DirectionCone::everyDirection();  // opposite axes
  k = k / kLength;
  Float turn = thetaO - thetaA;
  // Rodrigues' rotation of a.w about k, which is perpendicular to it.
  Vector3f w = a.w * std::cos(turn) + cross(k, a.w) * std::sin(turn);
  return {normalize(w), std::cos(thetaO + kWidening)};
}

}  // namespace candela
