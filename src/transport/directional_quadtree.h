// The directional half of path guiding's SD-tree (Müller, Gross & Novák 2017, "Practical Path
// Guiding", §3.2): a distribution over all directions, kept as a quadtree over the square that the
// cylindrical map (cos θ = 2x - 1, φ = 2π y) takes to the sphere with constant Jacobian 4π. Each
// node holds the energy of its four quadrants; sampling descends by energy and ends uniform in a
// leaf, so the density is a product of 4 e_child / e_node along the descent, over 4π.
//
// It is used in passes: during a pass the distribution learned so far is sampled (read-only), and
// the radiance the pass finds is recorded, from any thread, into a second tree (order-independent
// sums, so the same bits for any thread schedule). Between passes finishPass() makes the recorded
// energies the distribution and refines the recording tree where the energy is: a quadrant holding
// more than subdivideShare of the total gets children, one holding less loses them (§3.3).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/order_independent_sum.h"
#include "core/vector.h"

namespace candela {

// The cylindrical map between directions and the unit square, and its inverse.
Vector3f squareToSphereCylindrical(const Point2f& p);
Point2f sphereToSquareCylindrical(const Vector3f& w);

class DirectionalQuadtree {
 public:
  static constexpr Float kDefaultSubdivideShare = 0.01f;  // Müller's ρ
  static constexpr int kMaxDepth = 20;                    // Müller's: finer than Float's u

  // Four leaves under the root, nothing learned.
  DirectionalQuadtree();

  // Whether the distribution has energy: until then it must not be sampled.
  bool trained() const { return total_ > 0; }
  // A direction from u in [0,1)^2 and its density over solid angle.
  Vector3f sample(Point2f u, Float* pdf) const;
  Float pdf(const Vector3f& w) const;

  // Adds an estimate of the radiance arriving from w, divided by the density w was chosen with
  // (so that a quadrant's sum estimates its integral of radiance). Thread-safe.
  void record(const Vector3f& w, double value);
  // Between passes (not concurrently with record or sampling).
  void finishPass(Float subdivideShare = kDefaultSubdivideShare);

  int samplingNodes() const { return int(sampling_.size()); }
  int recordingNodes() const { return int(recording_.size()); }

 private:
  // Children: 0 for a leaf quadrant (the root is node 0 and nobody's child). Quadrant q covers
  // x in [q&1, (q&1)+1)/2 and y in [q>>1, (q>>1)+1)/2 of its node's square.
  struct SamplingNode {
    std::array<uint32_t, 4> child{};
    std::array<Float, 4> energy{};
  };
  struct RecordingNode {
    std::array<uint32_t, 4> child{};
    std::array<OrderIndependentSum, 4> sum;
  };
  // The recording tree's energies, summed up from its leaves, per node and quadrant.
  std::vector<std::array<double, 4>> recordedEnergies() const;
  // Appends to next the refined copy of recording node `node` (or, for node < 0, a node whose
  // quadrants each hold `energy`/4 of an unrefined quadrant) and returns its index.
  uint32_t refine(std::vector<RecordingNode>& next, const std::vector<std::array<double, 4>>& e,
                  int node, double energy, double threshold, int depth) const;

  std::vector<SamplingNode> sampling_;
  Float total_ = 0;
  std::vector<RecordingNode> recording_;
};

}  // namespace candela
