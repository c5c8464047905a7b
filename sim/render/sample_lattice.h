#pragma once

// Depth-tested samples on a regular lattice of supersample positions: sample (i, j) sits at the
// fixed-point position (origin_x + i * step, origin_y + j * step). The rasteriser's inner loop.

#include <cstdint>
#include <vector>

#include "sim/render/frame_geometry.h"

namespace avc::sim {

class SampleLattice {
 public:
  // Empties every sample.
  void Reset(int64_t origin_x, int64_t origin_y, int64_t step, int nx, int ny);
  // Depth-tests the samples the triangle covers and keeps the nearest surface. A sample exactly
  // on an edge belongs to the triangle for which that edge is a top or left edge, so neighbours
  // sharing an edge neither leave gaps nor both claim it. Ties in depth keep the earlier index.
  void Rasterize(const RasterTriangle& triangle, int32_t index);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  // Index of the nearest triangle at sample (i, j), -1 where none.
  int32_t triangle(int i, int j) const { return triangle_[static_cast<size_t>(j) * nx_ + i]; }
  float inv_z(int i, int j) const { return inv_z_[static_cast<size_t>(j) * nx_ + i]; }

 private:
  int64_t origin_x_ = 0, origin_y_ = 0, step_ = 1;
  int nx_ = 0, ny_ = 0;
  std::vector<float> inv_z_;  // 1/z of the nearest surface, 0 where none
  std::vector<int32_t> triangle_;
};

}  // namespace avc::sim
