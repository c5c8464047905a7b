#include "sim/render/tile_bins.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "sim/render/floor_div.h"

namespace avc::sim {
namespace {

constexpr size_t kTrianglesPerChunk = 8192;

}  // namespace

// A sample at supersample coordinate S belongs to pixel floor((S + 0.5) / n).
TileBins::TileSpan TileBins::SpanOf(const RasterTriangle& t, const SampleGrid& grid, int width,
                                    int height, int tile_size) {
  const int64_t pixel_fixed = int64_t{grid.n} * kSubpixelScale;
  const int64_t half = kSubpixelScale / 2;
  const int64_t x_min = std::min({t.x[0], t.x[1], t.x[2]}),
                x_max = std::max({t.x[0], t.x[1], t.x[2]});
  const int64_t y_min = std::min({t.y[0], t.y[1], t.y[2]}),
                y_max = std::max({t.y[0], t.y[1], t.y[2]});
  const int64_t u0 = std::max<int64_t>(0, FloorDiv(x_min + half, pixel_fixed));
  const int64_t u1 = std::min<int64_t>(width - 1, FloorDiv(x_max + half, pixel_fixed));
  const int64_t v0 = std::max<int64_t>(0, FloorDiv(y_min + half, pixel_fixed));
  const int64_t v1 = std::min<int64_t>(height - 1, FloorDiv(y_max + half, pixel_fixed));
  if (u0 > u1 || v0 > v1) return {1, 1, 0, 0};
  return {static_cast<int>(u0 / tile_size), static_cast<int>(v0 / tile_size),
          static_cast<int>(u1 / tile_size), static_cast<int>(v1 / tile_size)};
}

void TileBins::Build(int width, int height, int tile_size, const SampleGrid& grid,
                     const std::vector<RasterTriangle>& triangles) {
  width_ = width;
  height_ = height;
  tile_size_ = tile_size;
  tiles_x_ = (width + tile_size - 1) / tile_size;
  tiles_y_ = (height + tile_size - 1) / tile_size;
  // Count, then fill, each over fixed chunks of triangles in parallel; a chunk's entries in a bin
  // follow the earlier chunks', so every bin lists its triangles in ascending order whatever the
  // thread count.
  const size_t tiles = num_tiles();
  const size_t num_chunks = (triangles.size() + kTrianglesPerChunk - 1) / kTrianglesPerChunk;
  std::vector<TileSpan>& spans = spans_;
  spans.resize(triangles.size());
  std::vector<uint32_t>& counts = chunk_counts_;  // per chunk, per tile
  counts.assign(num_chunks * tiles, 0);
  tbb::parallel_for(size_t{0}, num_chunks, [&](size_t chunk) {
    uint32_t* count = counts.data() + chunk * tiles;
    const size_t end = std::min(triangles.size(), (chunk + 1) * kTrianglesPerChunk);
    for (size_t i = chunk * kTrianglesPerChunk; i < end; ++i) {
      const TileSpan s = spans[i] = SpanOf(triangles[i], grid, width, height, tile_size);
      for (int ty = s.y0; ty <= s.y1; ++ty) {
        for (int tx = s.x0; tx <= s.x1; ++tx) ++count[static_cast<size_t>(ty) * tiles_x_ + tx];
      }
    }
  });
  // Bin offsets, and each chunk's first slot in each bin (counts become cursors).
  offsets_.assign(tiles + 1, 0);
  for (size_t tile = 0; tile < tiles; ++tile) {
    uint32_t next = offsets_[tile];
    for (size_t chunk = 0; chunk < num_chunks; ++chunk) {
      const uint32_t n = counts[chunk * tiles + tile];
      counts[chunk * tiles + tile] = next;
      next += n;
    }
    offsets_[tile + 1] = next;
  }
  indices_.resize(offsets_.back());
  tbb::parallel_for(size_t{0}, num_chunks, [&](size_t chunk) {
    uint32_t* cursor = counts.data() + chunk * tiles;
    const size_t end = std::min(triangles.size(), (chunk + 1) * kTrianglesPerChunk);
    for (size_t i = chunk * kTrianglesPerChunk; i < end; ++i) {
      const TileSpan& s = spans[i];
      for (int ty = s.y0; ty <= s.y1; ++ty) {
        for (int tx = s.x0; tx <= s.x1; ++tx) {
          indices_[cursor[static_cast<size_t>(ty) * tiles_x_ + tx]++] = static_cast<uint32_t>(i);
        }
      }
    }
  });
}

TileRect TileBins::Rect(size_t tile) const {
  const int tx = static_cast<int>(tile % tiles_x_), ty = static_cast<int>(tile / tiles_x_);
  return {tx * tile_size_, ty * tile_size_, std::min(width_, (tx + 1) * tile_size_),
          std::min(height_, (ty + 1) * tile_size_)};
}

}  // namespace avc::sim
