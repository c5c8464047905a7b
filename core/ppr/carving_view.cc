#include "core/ppr/carving_view.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace avc::ppr {
namespace {

void CheckPose(const Eigen::Isometry3d& pose, const std::string& name) {
  if (!pose.matrix().allFinite()) {
    throw std::invalid_argument(
        fmt::format("view '{}': camera pose T_cam_world is not finite", name));
  }
  const Eigen::Matrix3d r = pose.rotation();
  if (!(r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), 1e-6)) {
    throw std::invalid_argument(
        fmt::format("view '{}': rotation of camera pose T_cam_world is not orthonormal", name));
  }
}

}  // namespace

CarvingView PrepareCarvingView(const camera::Camera& camera, const cv::Mat& mask,
                               const std::string& name) {
  const auto& k = camera.intrinsics;
  if (const std::string problem = k.Validate(); !problem.empty()) {
    throw std::invalid_argument(fmt::format("view '{}': camera intrinsics: {}", name, problem));
  }
  CheckPose(camera.T_cam_world, name);
  if (mask.empty()) throw std::invalid_argument(fmt::format("view '{}': mask is empty", name));
  if (mask.type() != CV_8UC1) {
    throw std::invalid_argument(
        fmt::format("view '{}': mask must be CV_8UC1 (one 8-bit channel)", name));
  }
  if (mask.cols != k.width || mask.rows != k.height) {
    throw std::invalid_argument(fmt::format("view '{}': mask is {}x{} but its camera is {}x{}",
                                            name, mask.cols, mask.rows, k.width, k.height));
  }
  CarvingView view;
  view.name = name;
  view.camera = camera;
  cv::Mat labels;
  cv::compare(mask, 0, labels, cv::CMP_NE);  // 255 plant, 0 background
  labels.convertTo(labels, CV_8U, 1.0 / 255);
  if (k.HasDistortion()) {
    // Carve in the undistorted image so footprints are exact bounding rectangles; pixels that
    // map outside the real image are not seen by this view.
    const cv::Matx33d matrix(k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1);
    const cv::Mat coefficients(1, 5, CV_64F, const_cast<double*>(k.distortion.data()));
    cv::Mat map_x, map_y, undistorted;
    cv::initUndistortRectifyMap(matrix, coefficients, cv::Mat(), matrix, labels.size(), CV_32FC1,
                                map_x, map_y);
    cv::remap(labels, undistorted, map_x, map_y, cv::INTER_NEAREST, cv::BORDER_CONSTANT,
              cv::Scalar(kUnseenPixel));
    labels = undistorted;
    view.camera.intrinsics.distortion = {};
    view.has_unseen = cv::countNonZero(labels == kUnseenPixel) > 0;
  }
  view.labels = labels;
  return view;
}

FootprintTest::FootprintTest(const CarvingView& view, double voxel_size)
    : rotation_(view.camera.T_cam_world.rotation()),
      translation_(view.camera.T_cam_world.translation()),
      fx_(view.camera.intrinsics.fx),
      fy_(view.camera.intrinsics.fy),
      cx_(view.camera.intrinsics.cx),
      cy_(view.camera.intrinsics.cy),
      width_(view.labels.cols),
      height_(view.labels.rows),
      voxel_size_(voxel_size) {
  // Integrate 0/1 images: 0/255 ones would overflow 32 bits on an 18 MP image.
  const cv::Mat plant = (view.labels == kPlantPixel) / 255;
  cv::integral(plant, plant_integral_, CV_32S);
  if (view.has_unseen) {
    const cv::Mat seen = (view.labels != kUnseenPixel) / 255;
    cv::integral(seen, seen_integral_, CV_32S);
  }
}

int64_t FootprintTest::RectSum(const cv::Mat& integral, int i0, int j0, int i1, int j1) const {
  return int64_t{integral.at<int32_t>(j1 + 1, i1 + 1)} - integral.at<int32_t>(j0, i1 + 1) -
         integral.at<int32_t>(j1 + 1, i0) + integral.at<int32_t>(j0, i0);
}

Footprint FootprintTest::Classify(const ProxyCell& cell) const {
  const double edge = voxel_size_ * static_cast<double>(int64_t{1} << cell.level);
  const Eigen::Vector3d corner =
      rotation_ * (Eigen::Vector3d(cell.x, cell.y, cell.z) * edge) + translation_;
  const Eigen::Vector3d ex = rotation_.col(0) * edge;
  const Eigen::Vector3d ey = rotation_.col(1) * edge;
  const Eigen::Vector3d ez = rotation_.col(2) * edge;
  double umin = std::numeric_limits<double>::infinity(), umax = -umin, vmin = umin, vmax = -umin;
  int in_front = 0;
  for (int c = 0; c < 8; ++c) {
    Eigen::Vector3d p = corner;
    if (c & 1) p += ex;
    if (c & 2) p += ey;
    if (c & 4) p += ez;
    if (!(p.z() > 1e-9)) continue;
    ++in_front;
    const double u = fx_ * p.x() / p.z() + cx_;
    const double v = fy_ * p.y() / p.z() + cy_;
    umin = std::min(umin, u);
    umax = std::max(umax, u);
    vmin = std::min(vmin, v);
    vmax = std::max(vmax, v);
  }
  const bool is_voxel = cell.level == 0;
  if (in_front == 0) return Footprint::kNoVote;  // the whole cube is behind the camera
  if (in_front < 8) return is_voxel ? Footprint::kNoVote : Footprint::kMixed;
  // Pixel i covers [i - 0.5, i + 0.5); clamp before converting so huge values cannot overflow.
  const auto to_pixel = [](double value, int size) {
    return static_cast<int>(std::floor(std::clamp(value + 0.5, -1.0, size + 1.0)));
  };
  const int i0 = to_pixel(umin, width_), i1 = to_pixel(umax, width_);
  const int j0 = to_pixel(vmin, height_), j1 = to_pixel(vmax, height_);
  if (i1 < 0 || j1 < 0 || i0 >= width_ || j0 >= height_) return Footprint::kNoVote;
  const int ci0 = std::max(i0, 0), ci1 = std::min(i1, width_ - 1);
  const int cj0 = std::max(j0, 0), cj1 = std::min(j1, height_ - 1);
  const bool inside = ci0 == i0 && ci1 == i1 && cj0 == j0 && cj1 == j1;
  const int64_t area = int64_t{ci1 - ci0 + 1} * (cj1 - cj0 + 1);
  const int64_t plant = RectSum(plant_integral_, ci0, cj0, ci1, cj1);
  const int64_t seen = seen_integral_.empty() ? area : RectSum(seen_integral_, ci0, cj0, ci1, cj1);
  if (seen == 0) return Footprint::kNoVote;
  if (inside && seen == area && plant == 0) return Footprint::kBackground;
  if (inside && plant == area) return Footprint::kPlant;
  if (!is_voxel) return Footprint::kMixed;
  // A voxel touching any plant pixel is plant (conservative: thin structures survive); one
  // partly outside the image or unseen with no plant pixel gets no vote.
  return plant > 0 ? Footprint::kPlant : Footprint::kNoVote;
}

}  // namespace avc::ppr
