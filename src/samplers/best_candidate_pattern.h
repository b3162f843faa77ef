// Best-candidate point patterns (lrt draft §7.6; Mitchell 1991): each new point is the one, of
// several uniform candidates, farthest from the points already placed, which approximates a
// Poisson-disk pattern (no two points close together) while being built one point at a time.
// The draft computes its table offline; here it is generated when a sampler is created, from a
// seed, in well under a second (tens of milliseconds for the 4096-point tables the sampler uses).
//
// The pattern lives on the unit torus, split into cellsPerSide^2 square cells that each receive
// exactly pointsPerCell points: points are placed in rounds, one per cell per round (cells in a
// random order), the candidates for a cell drawn inside it. Tiling the image with the pattern,
// one cell per pixel, then gives each pixel the sampler's fixed number of samples while distances
// are maximized across pixel borders and across the tile's wrap-around edges.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vector.h"

namespace candela {

class BestCandidatePattern {
 public:
  BestCandidatePattern(int cellsPerSide, int pointsPerCell, uint64_t seed);

  int cellsPerSide() const { return cellsPerSide_; }
  int pointsPerCell() const { return pointsPerCell_; }
  // Point k (in the order placed) of cell (cx, cy), relative to the cell: in [0, 1)^2.
  Point2f cellPoint(int cx, int cy, int k) const {
    return local_[(size_t(cy) * size_t(cellsPerSide_) + size_t(cx)) * size_t(pointsPerCell_) +
                  size_t(k)];
  }
  // The same point in the torus's coordinates, [0, 1)^2.
  Point2f torusPoint(int cx, int cy, int k) const;

  // The smallest toroidal distance between two points of the pattern (for tests: brute force).
  double minimumDistance() const;

 private:
  int cellsPerSide_, pointsPerCell_;
  std::vector<Point2f> local_;  // cell-major, pointsPerCell per cell
};

}  // namespace candela
