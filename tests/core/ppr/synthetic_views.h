#pragma once

// Cameras on rings around the origin and masks of analytic shapes, for the proxy's tests.

#include <Eigen/Geometry>
#include <cmath>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/camera/pinhole_camera.h"

namespace avc::ppr::testing {

// A camera at `centre` looking at `target`, image y pointing down the world z axis.
inline camera::Camera LookAt(const Eigen::Vector3d& centre, const Eigen::Vector3d& target,
                             int width = 640, int height = 480, double focal = 700) {
  camera::Camera camera;
  camera.intrinsics = {width, height, focal, focal, (width - 1) / 2.0, (height - 1) / 2.0, {}};
  const Eigen::Vector3d z = (target - centre).normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d r;
  r.row(0) = x;
  r.row(1) = y;
  r.row(2) = z;
  camera.T_cam_world.linear() = r;
  camera.T_cam_world.translation() = -r * centre;
  return camera;
}

// `count` cameras on two rings (elevations +35 and -25 degrees) at `distance` from the origin.
inline std::vector<camera::Camera> RingCameras(int count, double distance) {
  std::vector<camera::Camera> cameras;
  for (int i = 0; i < count; ++i) {
    const double azimuth = 2 * M_PI * i / count;
    const double elevation = (i % 2 == 0 ? 35.0 : -25.0) * M_PI / 180;
    const Eigen::Vector3d centre(distance * std::cos(elevation) * std::cos(azimuth),
                                 distance * std::cos(elevation) * std::sin(azimuth),
                                 distance * std::sin(elevation));
    cameras.push_back(LookAt(centre, Eigen::Vector3d::Zero()));
  }
  return cameras;
}

// 255 where the ray through the pixel centre meets the shape (hit(origin, direction)).
template <class Hit>
cv::Mat RayMask(const camera::Camera& camera, Hit&& hit) {
  const auto& k = camera.intrinsics;
  cv::Mat mask(k.height, k.width, CV_8UC1, cv::Scalar(0));
  const Eigen::Matrix3d r_world_cam = camera.T_cam_world.rotation().transpose();
  const Eigen::Vector3d origin = camera.Centre();
  for (int v = 0; v < k.height; ++v) {
    for (int u = 0; u < k.width; ++u) {
      const Eigen::Vector3d direction = r_world_cam * k.Ray(Eigen::Vector2d(u, v));
      if (hit(origin, direction)) mask.at<uint8_t>(v, u) = 255;
    }
  }
  return mask;
}

inline cv::Mat SphereMask(const camera::Camera& camera, const Eigen::Vector3d& centre,
                          double radius) {
  return RayMask(camera, [&](const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
    const Eigen::Vector3d to_centre = centre - o;
    return (to_centre - to_centre.dot(d) * d).norm() <= radius && to_centre.dot(d) > 0;
  });
}

inline cv::Mat BoxMask(const camera::Camera& camera, const Eigen::AlignedBox3d& box) {
  return RayMask(camera, [&](const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
    double t0 = 0, t1 = 1e9;  // slab test
    for (int a = 0; a < 3; ++a) {
      const double inv = 1 / d[a];
      double near = (box.min()[a] - o[a]) * inv, far = (box.max()[a] - o[a]) * inv;
      if (near > far) std::swap(near, far);
      t0 = std::max(t0, near);
      t1 = std::min(t1, far);
    }
    return t0 <= t1;
  });
}

}  // namespace avc::ppr::testing
