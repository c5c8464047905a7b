#pragma once

// Screen tiles and the triangles that may touch each, in triangle order.

#include <cstdint>
#include <vector>

#include "sim/render/frame_geometry.h"

namespace avc::sim {

struct TileRect {
  int x0, y0, x1, y1;  // pixels [x0, x1) x [y0, y1)
};

class TileBins {
 public:
  // Bins triangles into tiles of tile_size pixels, replacing what was there (memory is reused).
  void Build(int width, int height, int tile_size, const SampleGrid& grid,
             const std::vector<RasterTriangle>& triangles);

  size_t num_tiles() const { return static_cast<size_t>(tiles_x_) * tiles_y_; }
  TileRect Rect(size_t tile) const;
  // Indices into the triangle list, ascending.
  const uint32_t* begin(size_t tile) const { return indices_.data() + offsets_[tile]; }
  const uint32_t* end(size_t tile) const { return indices_.data() + offsets_[tile + 1]; }

 private:
  struct TileSpan {
    int x0, y0, x1, y1;  // inclusive tile indices; x0 > x1 when empty
  };
  // Tiles whose pixels the triangle's box can reach.
  static TileSpan SpanOf(const RasterTriangle& t, const SampleGrid& grid, int width, int height,
                         int tile_size);

  int width_ = 0, height_ = 0, tile_size_ = 1, tiles_x_ = 0, tiles_y_ = 0;
  std::vector<uint32_t> offsets_;
  std::vector<uint32_t> indices_;
  std::vector<TileSpan> spans_;
  std::vector<uint32_t> chunk_counts_;
};

}  // namespace avc::sim
