#include "core/mvs/plane_sweep/plane_homography.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>

namespace avc::mvs {
namespace {

Eigen::Matrix3d IntrinsicMatrix(const camera::Intrinsics& k) {
  Eigen::Matrix3d m;
  m << k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1;
  return m;
}

}  // namespace

HomographyBasis MakeHomographyBasis(const camera::Camera& reference, const camera::Camera& other) {
  const Eigen::Isometry3d relative = other.T_cam_world * reference.T_cam_world.inverse();
  const Eigen::Matrix3d k_other = IntrinsicMatrix(other.intrinsics);
  return {k_other * relative.linear() * IntrinsicMatrix(reference.intrinsics).inverse(),
          k_other * relative.translation()};
}

void WarpByPlane(const SweepView& other, const Eigen::Matrix3d& h, const cv::Rect& region,
                 float* warped, uint8_t* inside) {
  const int width = other.grey.cols;
  const int height = other.grey.rows;
  const float max_u = static_cast<float>(width - 1);
  const float max_v = static_cast<float>(height - 1);
  const Eigen::Matrix3f hf = h.cast<float>();
  for (int gy = 0; gy < region.height; ++gy) {
    const float y = static_cast<float>(region.y + gy);
    const float row_x = hf(0, 1) * y + hf(0, 2);
    const float row_y = hf(1, 1) * y + hf(1, 2);
    const float row_z = hf(2, 1) * y + hf(2, 2);
    for (int gx = 0; gx < region.width; ++gx) {
      const float x = static_cast<float>(region.x + gx);
      const int at = gy * region.width + gx;
      const float hz = hf(2, 0) * x + row_z;
      const float inverse = 1.0f / hz;
      const float u = (hf(0, 0) * x + row_x) * inverse;
      const float v = (hf(1, 0) * x + row_y) * inverse;
      if (!(hz > 0 && u >= 0 && v >= 0 && u <= max_u && v <= max_v)) {
        warped[at] = 0;
        inside[at] = 0;
        continue;
      }
      const int x0 = std::min(static_cast<int>(u), width - 2);
      const int y0 = std::min(static_cast<int>(v), height - 2);
      const float fu = u - static_cast<float>(x0);
      const float fv = v - static_cast<float>(y0);
      const float* r0 = other.grey.ptr<float>(y0) + x0;
      const float* r1 = other.grey.ptr<float>(y0 + 1) + x0;
      const float top = r0[0] + fu * (r0[1] - r0[0]);
      const float bottom = r1[0] + fu * (r1[1] - r1[0]);
      warped[at] = top + fv * (bottom - top);
      inside[at] = 1;
    }
  }
}

}  // namespace avc::mvs
