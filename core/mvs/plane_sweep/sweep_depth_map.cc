#include "core/mvs/plane_sweep/sweep_depth_map.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>

#include "core/mvs/plane_sweep/box_mean.h"
#include "core/mvs/plane_sweep/plane_homography.h"

namespace avc::mvs {
namespace {

constexpr float kInvalid = -2.0f;  // below any ZNCC
constexpr int kMaxNeighbours = 16;

// A tile of the reference image and its plane interval, swept on its own (tiles are
// independent, so they run in parallel without changing any result).
struct Tile {
  cv::Rect pixels;  // the tile
  cv::Rect region;  // the tile plus the ZNCC window's reach, within the image
  int first_plane = INT_MAX;
  int last_plane = -1;
  std::vector<uint8_t> plane_used;  // per plane of [first_plane, last_plane]: some pixel has it
};

// Per-tile scratch: warped neighbour, window sums of J, J^2 and I J, per-neighbour ZNCC, and
// the winner-take-all state with the scores either side of the winner (parabola fit).
struct TileScratch {
  std::vector<float> warped, row_j, row_jj, row_ij, scores;
  std::vector<uint8_t> inside;
  std::vector<float> best, before, after, previous;
  std::vector<int> best_index;
};

}  // namespace

double InverseDepthStep(const SweepView& reference, const std::vector<const SweepView*>& others,
                        const DepthRange& range, double max_step_px) {
  double max_rate = 0;  // pixels per unit inverse depth
  std::vector<HomographyBasis> bases;
  for (const SweepView* other : others)
    bases.push_back(MakeHomographyBasis(reference.camera, other->camera));
  constexpr int kStride = 8;
  for (int y = 0; y < range.far_depth.rows; y += kStride) {
    for (int x = 0; x < range.far_depth.cols; x += kStride) {
      const float far = range.far_depth.at<float>(y, x);
      if (!(far > 0)) continue;
      const std::array<double, 2> inverse_depths = {1.0 / far,
                                                    1.0 / range.near_depth.at<float>(y, x)};
      for (const HomographyBasis& basis : bases) {
        for (double w : inverse_depths) {
          const Eigen::Vector3d p = basis.a * Eigen::Vector3d(x, y, 1) + basis.b * w;
          if (!(p.z() > 0)) continue;
          const Eigen::Vector2d rate =
              (basis.b.head<2>() * p.z() - p.head<2>() * basis.b.z()) / (p.z() * p.z());
          max_rate = std::max(max_rate, rate.norm());
        }
      }
    }
  }
  return max_rate > 0 ? max_step_px / max_rate : 0;
}

namespace {

// Sweeps one tile: warps, ZNCC, best-k aggregation, winner-take-all, parabola refinement;
// writes the tile's pixels of `result`.
void SweepTile(const Tile& tile, const SweepView& reference,
               const std::vector<const SweepView*>& neighbours,
               const std::vector<HomographyBasis>& bases, const cv::Mat& first_plane,
               const cv::Mat& last_plane, const cv::Mat& ref_mean, const cv::Mat& ref_std,
               double w_min, double step, int best_k, const PlaneSweepOptions& options,
               TileScratch& s, SweepDepthMap& result) {
  const int used = static_cast<int>(bases.size());
  const int radius = options.window / 2;
  const cv::Rect& region = tile.region;
  const cv::Rect& px = tile.pixels;
  const size_t region_size = static_cast<size_t>(region.area());
  const size_t tile_size = static_cast<size_t>(px.area());
  s.warped.resize(region_size);
  s.inside.resize(region_size);
  s.row_j.resize(region_size);
  s.row_jj.resize(region_size);
  s.row_ij.resize(region_size);
  s.scores.assign(tile_size * static_cast<size_t>(used), kInvalid);
  s.best.assign(tile_size, kInvalid);
  s.before.assign(tile_size, kInvalid);
  s.after.assign(tile_size, kInvalid);
  s.previous.assign(tile_size, kInvalid);
  s.best_index.assign(tile_size, -1);
  const float min_std = static_cast<float>(options.min_texture_std);
  // Offsets of the tile inside its region.
  const int ox = px.x - region.x;
  const int oy = px.y - region.y;

  for (int plane = tile.first_plane; plane <= tile.last_plane; ++plane) {
    if (!tile.plane_used[static_cast<size_t>(plane - tile.first_plane)]) {
      // No pixel of the tile has this plane: only the winner bookkeeping moves on.
      std::fill(s.previous.begin(), s.previous.end(), kInvalid);
      continue;
    }
    const double w = w_min + plane * step;
    for (int n = 0; n < used; ++n) {
      const Eigen::Matrix3d h = bases[static_cast<size_t>(n)].AtInverseDepth(w);
      WarpByPlane(*neighbours[static_cast<size_t>(n)], h, region, s.warped.data(), s.inside.data());
      // Horizontal window sums of J, J^2 and I J over the region (clipped at its edges, which
      // are the image's edges wherever the tile is closer than the window's reach).
      for (int gy = 0; gy < region.height; ++gy) {
        const float* ref_row = reference.grey.ptr<float>(region.y + gy) + region.x;
        const float* j = s.warped.data() + gy * region.width;
        float* sj = s.row_j.data() + gy * region.width;
        float* sjj = s.row_jj.data() + gy * region.width;
        float* sij = s.row_ij.data() + gy * region.width;
        // Running sums: add the sample entering the window, drop the one leaving it.
        float a = 0, b = 0, c = 0;
        for (int k = 0; k < std::min(radius, region.width); ++k) {
          a += j[k];
          b += j[k] * j[k];
          c += j[k] * ref_row[k];
        }
        for (int gx = 0; gx < region.width; ++gx) {
          if (const int k = gx + radius; k < region.width) {
            a += j[k];
            b += j[k] * j[k];
            c += j[k] * ref_row[k];
          }
          if (const int k = gx - radius - 1; k >= 0) {
            a -= j[k];
            b -= j[k] * j[k];
            c -= j[k] * ref_row[k];
          }
          sj[gx] = a;
          sjj[gx] = b;
          sij[gx] = c;
        }
      }
      // Vertical sums at the tile's pixels, then ZNCC where the plane is in the pixel's range.
      float* score = s.scores.data() + static_cast<size_t>(n) * tile_size;
      for (int ty = 0; ty < px.height; ++ty) {
        const int y = px.y + ty;
        const int gy = oy + ty;
        const int lo_y = std::max(0, gy - radius);
        const int hi_y = std::min(region.height - 1, gy + radius);
        const int* lo = first_plane.ptr<int>(y) + px.x;
        const int* hi = last_plane.ptr<int>(y) + px.x;
        const float* mi = ref_mean.ptr<float>(y) + px.x;
        const float* si = ref_std.ptr<float>(y) + px.x;
        for (int tx = 0; tx < px.width; ++tx) {
          float& out = score[ty * px.width + tx];
          out = kInvalid;
          const int gx = ox + tx;
          if (plane < lo[tx] || plane > hi[tx] || si[tx] < min_std ||
              !s.inside[static_cast<size_t>(gy * region.width + gx)]) {
            continue;
          }
          const int lo_x = std::max(0, gx - radius);
          const int hi_x = std::min(region.width - 1, gx + radius);
          float a = 0, b = 0, c = 0;
          for (int k = lo_y; k <= hi_y; ++k) {
            const size_t at = static_cast<size_t>(k * region.width + gx);
            a += s.row_j[at];
            b += s.row_jj[at];
            c += s.row_ij[at];
          }
          const float count = static_cast<float>((hi_x - lo_x + 1) * (hi_y - lo_y + 1));
          const float mean_j = a / count;
          const float var_j = b / count - mean_j * mean_j;
          if (!(var_j >= min_std * min_std)) continue;
          out = (c / count - mi[tx] * mean_j) / (si[tx] * std::sqrt(var_j));
        }
      }
    }
    // Best-k mean per pixel, then the winner-take-all update.
    std::array<float, kMaxNeighbours> values{};
    for (int ty = 0; ty < px.height; ++ty) {
      const int* lo = first_plane.ptr<int>(px.y + ty) + px.x;
      const int* hi = last_plane.ptr<int>(px.y + ty) + px.x;
      for (int tx = 0; tx < px.width; ++tx) {
        const size_t at = static_cast<size_t>(ty * px.width + tx);
        float aggregated = kInvalid;
        if (plane >= lo[tx] && plane <= hi[tx]) {
          int valid = 0;
          for (int n = 0; n < used; ++n) {
            const float v = s.scores[static_cast<size_t>(n) * tile_size + at];
            if (v > kInvalid) values[static_cast<size_t>(valid++)] = v;
          }
          if (valid >= best_k) {
            std::partial_sort(values.begin(), values.begin() + best_k, values.begin() + valid,
                              std::greater<float>());
            float sum = 0;
            for (int k = 0; k < best_k; ++k) sum += values[static_cast<size_t>(k)];
            aggregated = sum / static_cast<float>(best_k);
          }
        }
        if (s.best_index[at] == plane - 1) s.after[at] = aggregated;
        if (aggregated > kInvalid && aggregated > s.best[at]) {
          s.best[at] = aggregated;
          s.best_index[at] = plane;
          s.before[at] = s.previous[at];
          s.after[at] = kInvalid;
        }
        s.previous[at] = aggregated;
      }
    }
  }

  // Sub-plane refinement: parabola through the winner and its neighbours in inverse depth.
  for (int ty = 0; ty < px.height; ++ty) {
    float* depth = result.depth.ptr<float>(px.y + ty) + px.x;
    float* score = result.score.ptr<float>(px.y + ty) + px.x;
    for (int tx = 0; tx < px.width; ++tx) {
      const size_t at = static_cast<size_t>(ty * px.width + tx);
      const int index = s.best_index[at];
      if (index < 0) continue;
      double offset = 0;
      if (s.before[at] > kInvalid && s.after[at] > kInvalid) {
        const double curvature = s.before[at] - 2.0 * s.best[at] + s.after[at];
        if (curvature < 0) {
          offset = std::clamp(0.5 * (s.before[at] - s.after[at]) / curvature, -0.5, 0.5);
        }
      }
      const double w = w_min + (index + offset) * step;
      if (!(w > 0)) continue;
      depth[tx] = static_cast<float>(1.0 / w);
      score[tx] = s.best[at];
    }
  }
}

}  // namespace

SweepDepthMap SweepReference(const SweepView& reference,
                             const std::vector<const SweepView*>& neighbours,
                             const DepthRange& range, const PlaneSweepOptions& options) {
  const cv::Size size = reference.grey.size();
  SweepDepthMap result;
  result.depth = cv::Mat(size, CV_32F, cv::Scalar(0));
  result.score = cv::Mat(size, CV_32F, cv::Scalar(-1));
  const int used = std::min<int>(static_cast<int>(neighbours.size()), kMaxNeighbours);
  const int best_k = std::min(options.best_k, used);
  if (used == 0 || best_k <= 0) return result;
  const std::vector<const SweepView*> swept(neighbours.begin(), neighbours.begin() + used);

  // Global inverse-depth span of the covered pixels and the plane spacing.
  double w_min = std::numeric_limits<double>::infinity();
  double w_max = 0;
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      const float far = range.far_depth.at<float>(y, x);
      if (!(far > 0)) continue;
      w_min = std::min(w_min, 1.0 / far);
      w_max = std::max(w_max, 1.0 / range.near_depth.at<float>(y, x));
    }
  }
  if (!(w_max > 0)) return result;
  double step = InverseDepthStep(reference, swept, range, options.max_plane_step_px);
  if (!(step > 0)) return result;
  int count = static_cast<int>(std::ceil((w_max - w_min) / step)) + 1;
  if (count > options.max_planes) {
    count = options.max_planes;
    step = (w_max - w_min) / std::max(1, count - 1);
  }
  result.planes = count;

  // Each pixel's planes: those inside its interval (at least the one nearest to it); each
  // tile's: the span of its pixels'.
  constexpr int kTileSize = 32;
  const int radius = options.window / 2;
  const int tiles_x = (size.width + kTileSize - 1) / kTileSize;
  const int tiles_y = (size.height + kTileSize - 1) / kTileSize;
  std::vector<Tile> tiles(static_cast<size_t>(tiles_x * tiles_y));
  for (int ty = 0; ty < tiles_y; ++ty) {
    for (int tx = 0; tx < tiles_x; ++tx) {
      Tile& tile = tiles[static_cast<size_t>(ty * tiles_x + tx)];
      tile.pixels = cv::Rect(tx * kTileSize, ty * kTileSize, kTileSize, kTileSize) &
                    cv::Rect(0, 0, size.width, size.height);
      tile.region = cv::Rect(tile.pixels.x - radius, tile.pixels.y - radius,
                             tile.pixels.width + 2 * radius, tile.pixels.height + 2 * radius) &
                    cv::Rect(0, 0, size.width, size.height);
    }
  }
  // Reference window statistics, once; textureless pixels (a
  // black background) are not swept at all.
  cv::Mat ref_mean, ref_sq_mean, ref_std;
  BoxMean(reference.grey, radius, ref_mean);
  BoxMean(reference.grey.mul(reference.grey), radius, ref_sq_mean);
  cv::Mat variance = ref_sq_mean - ref_mean.mul(ref_mean);
  cv::max(variance, 0, variance);
  cv::sqrt(variance, ref_std);
  cv::Mat first_plane(size, CV_32S, cv::Scalar(1));
  cv::Mat last_plane(size, CV_32S, cv::Scalar(0));
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      const float far = range.far_depth.at<float>(y, x);
      if (!(far > 0) || ref_std.at<float>(y, x) < options.min_texture_std) continue;
      const double w_far = 1.0 / far;
      const double w_near = 1.0 / range.near_depth.at<float>(y, x);
      int lo = std::clamp(static_cast<int>(std::ceil((w_far - w_min) / step - 1e-9)), 0, count - 1);
      int hi =
          std::clamp(static_cast<int>(std::floor((w_near - w_min) / step + 1e-9)), 0, count - 1);
      if (lo > hi) {
        lo = hi = std::clamp(static_cast<int>(std::lround((0.5 * (w_far + w_near) - w_min) / step)),
                             0, count - 1);
      }
      first_plane.at<int>(y, x) = lo;
      last_plane.at<int>(y, x) = hi;
      Tile& tile = tiles[static_cast<size_t>((y / kTileSize) * tiles_x + x / kTileSize)];
      tile.first_plane = std::min(tile.first_plane, lo);
      tile.last_plane = std::max(tile.last_plane, hi);
    }
  }
  std::vector<Tile> active;
  for (Tile& tile : tiles) {
    if (tile.last_plane < 0) continue;
    tile.plane_used.assign(static_cast<size_t>(tile.last_plane - tile.first_plane + 1), 0);
    for (int y = tile.pixels.y; y < tile.pixels.y + tile.pixels.height; ++y) {
      for (int x = tile.pixels.x; x < tile.pixels.x + tile.pixels.width; ++x) {
        for (int i = first_plane.at<int>(y, x); i <= last_plane.at<int>(y, x); ++i) {
          tile.plane_used[static_cast<size_t>(i - tile.first_plane)] = 1;
        }
      }
    }
    active.push_back(std::move(tile));
  }

  std::vector<HomographyBasis> bases;
  for (const SweepView* other : swept)
    bases.push_back(MakeHomographyBasis(reference.camera, other->camera));

  // Tiles write disjoint pixels, so the parallel loop gives the same bits for any schedule.
  tbb::enumerable_thread_specific<TileScratch> scratch;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, active.size(), 1),
                    [&](const tbb::blocked_range<size_t>& tiles_range) {
                      TileScratch& local = scratch.local();
                      for (size_t t = tiles_range.begin(); t != tiles_range.end(); ++t) {
                        SweepTile(active[t], reference, swept, bases, first_plane, last_plane,
                                  ref_mean, ref_std, w_min, step, best_k, options, local, result);
                      }
                    });
  return result;
}

}  // namespace avc::mvs
