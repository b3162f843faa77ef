#include "transport/directional_quadtree.h"

#include <algorithm>
#include <cmath>

namespace candela {

Vector3f squareToSphereCylindrical(const Point2f& p) {
  Float cosTheta = 2 * p.x - 1;
  Float sinTheta = std::sqrt(std::max(Float(0), 1 - cosTheta * cosTheta));
  Float phi = 2 * kPi * p.y;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

Point2f sphereToSquareCylindrical(const Vector3f& w) {
  Float cosTheta = std::clamp(w.z, Float(-1), Float(1));
  Float phi = std::atan2(w.y, w.x);
  if (phi < 0) phi += 2 * kPi;
  Float x = std::min((cosTheta + 1) / 2, kOneMinusEpsilon);
  Float y = std::min(phi * kInv2Pi, kOneMinusEpsilon);
  return {std::max(Float(0), x), std::max(Float(0), y)};
}

DirectionalQuadtree::DirectionalQuadtree() : sampling_(1), recording_(1) {}

namespace {
// The quadrant of a node's square holding p, with p taken to that quadrant's own unit square.
int quadrantOf(Point2f* p) {
  int qx = p->x >= Float(0.5), qy = p->y >= Float(0.5);
  p->x = std::min(2 * p->x - Float(qx), kOneMinusEpsilon);
  p->y = std::min(2 * p->y - Float(qy), kOneMinusEpsilon);
  return qx | (qy << 1);
}

// Chooses between two halves of weight a and b (a + b > 0) by u, and reuses u within the half.
int chooseHalf(Float a, Float b, Float* u) {
  Float pa = a / (a + b);
  if (*u < pa) {
    *u = std::min(*u / pa, kOneMinusEpsilon);
    return 0;
  }
  *u = std::min((*u - pa) / (1 - pa), kOneMinusEpsilon);
  return 1;
}
}  // namespace

Vector3f DirectionalQuadtree::sample(Point2f u, Float* pdf) const {
  Float density = 1, size = 1;
  Point2f origin(0, 0);
  for (uint32_t node = 0;;) {
    const std::array<Float, 4>& e = sampling_[node].energy;
    const Float sum = e[0] + e[1] + e[2] + e[3];
    if (sum == 0) break;  // its quadrants' energies rounded away: uniform over it (as pdf)
    // x first by the columns' energies, then y within the column (a quadrant of zero energy is
    // never chosen: its half or its column's share is 0).
    int qx = chooseHalf(e[0] + e[2], e[1] + e[3], &u.x);
    int qy = chooseHalf(e[qx], e[qx + 2], &u.y);
    int q = qx | (qy << 1);
    density *= 4 * e[q] / sum;
    size /= 2;
    origin.x += size * Float(qx);
    origin.y += size * Float(qy);
    node = sampling_[node].child[q];
    if (node == 0) break;
  }
  *pdf = density * kInv4Pi;
  Point2f p(std::min(origin.x + size * u.x, kOneMinusEpsilon),
            std::min(origin.y + size * u.y, kOneMinusEpsilon));
  return squareToSphereCylindrical(p);
}

Float DirectionalQuadtree::pdf(const Vector3f& w) const {
  if (!trained()) return 0;
  Point2f p = sphereToSquareCylindrical(w);
  Float density = 1;
  for (uint32_t node = 0;;) {
    const std::array<Float, 4>& e = sampling_[node].energy;
    const Float sum = e[0] + e[1] + e[2] + e[3];
    if (sum == 0) break;
    int q = quadrantOf(&p);
    if (e[q] == 0) return 0;
    density *= 4 * e[q] / sum;
    node = sampling_[node].child[q];
    if (node == 0) break;
  }
  return density * kInv4Pi;
}

void DirectionalQuadtree::record(const Vector3f& w, double value) {
  Point2f p = sphereToSquareCylindrical(w);
  for (uint32_t node = 0;;) {
    int q = quadrantOf(&p);
    uint32_t child = recording_[node].child[q];
    if (child == 0) {
      recording_[node].sum[q].add(value);
      return;
    }
    node = child;
  }
}

std::vector<std::array<double, 4>> DirectionalQuadtree::recordedEnergies() const {
  std::vector<std::array<double, 4>> e(recording_.size());
  // Children come after their parents (refine appends them so), so backwards is bottom-up.
  for (size_t i = recording_.size(); i-- > 0;)
    for (int q = 0; q < 4; ++q) {
      uint32_t c = recording_[i].child[q];
      e[i][q] = c ? e[c][0] + e[c][1] + e[c][2] + e[c][3] : recording_[i].sum[q].value();
    }
  return e;
}

uint32_t DirectionalQuadtree::refine(std::vector<RecordingNode>& next,
                                     const std::vector<std::array<double, 4>>& e, int node,
                                     double energy, double threshold, int depth) const {
  uint32_t index = uint32_t(next.size());
  next.emplace_back();
  for (int q = 0; q < 4; ++q) {
    // An unrefined quadrant's energy is taken as spread evenly over it.
    double eq = node >= 0 ? e[size_t(node)][q] : energy / 4;
    if (eq <= threshold || depth + 1 >= kMaxDepth) continue;
    int child = node >= 0 && recording_[size_t(node)].child[q]
                    ? int(recording_[size_t(node)].child[q])
                    : -1;
    uint32_t c = refine(next, e, child, eq, threshold, depth + 1);
    next[index].child[q] = c;
  }
  return index;
}

void DirectionalQuadtree::finishPass(Float subdivideShare) {
  std::vector<std::array<double, 4>> e = recordedEnergies();
  sampling_.assign(recording_.size(), SamplingNode());
  for (size_t i = 0; i < recording_.size(); ++i) {
    sampling_[i].child = recording_[i].child;
    for (int q = 0; q < 4; ++q) sampling_[i].energy[q] = Float(e[i][q]);
  }
  double total = e[0][0] + e[0][1] + e[0][2] + e[0][3];
  total_ = Float(total);
  // A quadrant's energy as a Float may round to 0 below a positive parent: then it is never
  // sampled and its density is 0, which the BSDF's share of the mixture covers.
  if (!(total > 0)) {
    for (RecordingNode& n : recording_)
      for (OrderIndependentSum& s : n.sum) s.reset();
    return;
  }
  std::vector<RecordingNode> next;
  next.reserve(recording_.size() * 2);
  refine(next, e, 0, total, total * subdivideShare, 0);
  recording_ = std::move(next);
}

}  // namespace candela
