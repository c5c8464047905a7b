#include "tests/core/mvs/plane_sweep/sweep_test_scenes.h"

#include <Eigen/Geometry>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "core/eval/silhouette_agreement.h"
#include "core/segmentation/threshold_silhouette.h"

namespace avc::mvs::sweep_test {
namespace {

camera::Camera LookAt(const Eigen::Vector3d& centre, const Eigen::Vector3d& target,
                      const camera::Intrinsics& intrinsics) {
  const Eigen::Vector3d z = (target - centre).normalized();
  const Eigen::Vector3d x = Eigen::Vector3d::UnitY().cross(z).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d rotation;
  rotation.row(0) = x.transpose();
  rotation.row(1) = y.transpose();
  rotation.row(2) = z.transpose();
  camera::Camera camera;
  camera.intrinsics = intrinsics;
  camera.T_cam_world.linear() = rotation;
  camera.T_cam_world.translation() = -rotation * centre;
  return camera;
}

// Blurred seeded noise, contrast-stretched (own bit mapping: same bytes on every platform).
cv::Mat RandomTexture(int size, uint32_t seed) {
  std::mt19937 rng(seed);
  cv::Mat noise(size, size, CV_32F);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) noise.at<float>(y, x) = static_cast<float>(rng() >> 24);
  }
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), 2.0);
  cv::Mat texture;
  cv::normalize(noise, noise, 0, 255, cv::NORM_MINMAX);
  noise.convertTo(texture, CV_8U);
  return texture;
}

}  // namespace

TexturedPlane MakeTexturedPlane(double tilt, uint32_t seed) {
  TexturedPlane scene;
  scene.normal = Eigen::Vector3d(0, std::sin(tilt), std::cos(tilt));
  const Eigen::Vector3d e1 = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d e2 = scene.normal.cross(e1);
  constexpr int kTexels = 1024;
  constexpr double kSide = 0.4;  // metres
  const double texel = kSide / kTexels;
  const cv::Mat texture = RandomTexture(kTexels, seed);
  const cv::Mat texture_bgr = [&] {
    cv::Mat bgr;
    cv::cvtColor(texture, bgr, cv::COLOR_GRAY2BGR);
    return bgr;
  }();
  const cv::Mat ones(kTexels, kTexels, CV_8U, cv::Scalar(255));

  camera::Intrinsics intrinsics;
  intrinsics.width = 320;
  intrinsics.height = 240;
  intrinsics.fx = intrinsics.fy = 600;
  intrinsics.cx = 159.5;
  intrinsics.cy = 119.5;
  const double distance = 0.4;
  const double off = 20.0 * M_PI / 180.0;
  const std::vector<Eigen::Vector2d> directions = {
      {0, 0}, {off, 0}, {-off, 0}, {0, off}, {0, -off}};
  for (size_t i = 0; i < directions.size(); ++i) {
    const Eigen::Vector3d centre =
        distance *
        Eigen::Vector3d(std::sin(directions[i].x()), std::sin(directions[i].y()), 1).normalized();
    dataset::View view;
    view.name = "plane_" + std::to_string(i);
    view.camera = LookAt(centre, Eigen::Vector3d::Zero(), intrinsics);
    // Texel (i, j) is the plane point (i - N/2) texel e1 + (j - N/2) texel e2.
    const Eigen::Matrix3d rotation = view.camera.T_cam_world.linear();
    const Eigen::Vector3d origin = -0.5 * kSide * (e1 + e2);
    Eigen::Matrix3d plane_to_camera;
    plane_to_camera.col(0) = rotation * e1 * texel;
    plane_to_camera.col(1) = rotation * e2 * texel;
    plane_to_camera.col(2) = rotation * origin + view.camera.T_cam_world.translation();
    Eigen::Matrix3d k;
    k << intrinsics.fx, 0, intrinsics.cx, 0, intrinsics.fy, intrinsics.cy, 0, 0, 1;
    const Eigen::Matrix3d h = k * plane_to_camera;
    cv::Mat homography(3, 3, CV_64F);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) homography.at<double>(r, c) = h(r, c);
    }
    const cv::Size size(intrinsics.width, intrinsics.height);
    cv::warpPerspective(texture_bgr, view.image, homography, size, cv::INTER_AREA);
    cv::warpPerspective(ones, view.mask, homography, size, cv::INTER_NEAREST);
    scene.views.push_back(view);
  }

  const double voxel = 0.004;
  for (double x = -0.1; x <= 0.1; x += voxel) {
    for (double y = -0.1; y <= 0.1; y += voxel) {
      for (double z = -0.1; z <= 0.1; z += voxel) {
        if (std::abs(scene.normal.dot(Eigen::Vector3d(x, y, z))) <= voxel) {
          scene.bounds.occupied_centres.emplace_back(x, y, z);
        }
      }
    }
  }
  scene.bounds.voxel_size = voxel;
  return scene;
}

MvsBounds BoxBounds(const Eigen::Vector3d& min, const Eigen::Vector3d& max, double voxel) {
  MvsBounds bounds;
  bounds.voxel_size = voxel;
  const Eigen::Vector3i cells = ((max - min) / voxel).array().ceil().cast<int>();
  for (int i = 0; i < cells.x(); ++i) {
    for (int j = 0; j < cells.y(); ++j) {
      for (int k = 0; k < cells.z(); ++k) {
        bounds.occupied_centres.push_back(
            (min + voxel * Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5)).cast<float>());
      }
    }
  }
  return bounds;
}

MvsBounds VisualHull(const std::vector<dataset::View>& views, const Eigen::Vector3d& min,
                     const Eigen::Vector3d& max, double voxel, int misses) {
  const MvsBounds box = BoxBounds(min, max, voxel);
  MvsBounds hull;
  hull.voxel_size = voxel;
  for (const Eigen::Vector3f& centre : box.occupied_centres) {
    int outside = 0;
    for (const dataset::View& view : views) {
      const auto pixel = view.camera.Project(centre.cast<double>());
      if (!pixel) continue;
      const int x = static_cast<int>(std::lround(pixel->x()));
      const int y = static_cast<int>(std::lround(pixel->y()));
      if (x < 0 || y < 0 || x >= view.mask.cols || y >= view.mask.rows) continue;
      if (view.mask.at<uint8_t>(y, x) == 0) ++outside;
    }
    if (outside <= misses) hull.occupied_centres.push_back(centre);
  }
  return hull;
}

cv::Mat MiddleburySilhouette(const cv::Mat& bgr) {
  return segmentation::ThresholdSilhouette(bgr, 0.19, 10, 7);
}

double InsideSilhouetteFraction(const MvsPoints& points, const std::vector<dataset::View>& views,
                                const std::vector<cv::Mat>& silhouettes) {
  return eval::InsideAllSilhouettesFraction(points, views, silhouettes);
}

double InsideBoxFraction(const MvsPoints& points, const Eigen::Vector3d& min,
                         const Eigen::Vector3d& max) {
  if (points.size() == 0) return 0;
  size_t inside = 0;
  for (const Eigen::Vector3f& p : points.cloud.positions) {
    const Eigen::Vector3d q = p.cast<double>();
    inside += (q.array() >= min.array()).all() && (q.array() <= max.array()).all() ? 1 : 0;
  }
  return static_cast<double>(inside) / static_cast<double>(points.size());
}

}  // namespace avc::mvs::sweep_test
