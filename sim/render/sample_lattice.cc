#include "sim/render/sample_lattice.h"

#include <algorithm>

#include "sim/render/floor_div.h"

namespace avc::sim {

void SampleLattice::Reset(int64_t origin_x, int64_t origin_y, int64_t step, int nx, int ny) {
  origin_x_ = origin_x;
  origin_y_ = origin_y;
  step_ = step;
  nx_ = nx;
  ny_ = ny;
  inv_z_.assign(static_cast<size_t>(nx) * ny, 0.0f);
  triangle_.assign(static_cast<size_t>(nx) * ny, -1);
}

void SampleLattice::Rasterize(const RasterTriangle& t, int32_t index) {
  const int64_t x_min = std::min({t.x[0], t.x[1], t.x[2]}),
                x_max = std::max({t.x[0], t.x[1], t.x[2]});
  const int64_t y_min = std::min({t.y[0], t.y[1], t.y[2]}),
                y_max = std::max({t.y[0], t.y[1], t.y[2]});
  const int64_t i0 = std::max<int64_t>(0, CeilDiv(x_min - origin_x_, step_));
  const int64_t i1 = std::min<int64_t>(nx_ - 1, FloorDiv(x_max - origin_x_, step_));
  const int64_t j0 = std::max<int64_t>(0, CeilDiv(y_min - origin_y_, step_));
  const int64_t j1 = std::min<int64_t>(ny_ - 1, FloorDiv(y_max - origin_y_, step_));
  if (i0 > i1 || j0 > j1) return;

  // Edge k runs from vertex k to vertex k+1; inside is E >= 0 (positive orientation, y down).
  const int64_t x_start = origin_x_ + i0 * step_, y_start = origin_y_ + j0 * step_;
  int64_t row[3], step_x[3], step_y[3];
  for (int k = 0; k < 3; ++k) {
    const int b = (k + 1) % 3;
    const int64_t dx = int64_t{t.x[b]} - t.x[k], dy = int64_t{t.y[b]} - t.y[k];
    const bool top_left = dy < 0 || (dy == 0 && dx > 0);
    row[k] = dx * (y_start - t.y[k]) - dy * (x_start - t.x[k]) - (top_left ? 0 : 1);
    step_x[k] = -dy * step_;
    step_y[k] = dx * step_;
  }
  const float scale = 1.0f / kSubpixelScale;
  const float fx0 = static_cast<float>(x_start - t.x[0]) * scale;
  const float fstep = static_cast<float>(step_) * scale;
  const float inv_z_step = t.inv_z_dx * fstep;
  for (int64_t j = j0; j <= j1; ++j) {
    const float fy = static_cast<float>(origin_y_ + j * step_ - t.y[0]) * scale;
    float inv_z = t.inv_z0 + t.inv_z_dx * fx0 + t.inv_z_dy * fy;
    int64_t e0 = row[0], e1 = row[1], e2 = row[2];
    float* depth = inv_z_.data() + j * nx_;
    int32_t* owner = triangle_.data() + j * nx_;
    for (int64_t i = i0; i <= i1; ++i) {
      if ((e0 | e1 | e2) >= 0 && inv_z > depth[i]) {
        depth[i] = inv_z;
        owner[i] = index;
      }
      e0 += step_x[0];
      e1 += step_x[1];
      e2 += step_x[2];
      inv_z += inv_z_step;
    }
    row[0] += step_y[0];
    row[1] += step_y[1];
    row[2] += step_y[2];
  }
}

}  // namespace avc::sim
