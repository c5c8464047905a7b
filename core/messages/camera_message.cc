#include "core/messages/camera_message.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace avc::messages {
namespace {

// Rigid transforms from calibration are orthonormal to double precision; this tolerance only
// catches matrices that are not rotations at all (scaled, sheared, garbage).
constexpr double kRotationTolerance = 1e-6;

}  // namespace

avc::camera_t CameraToMessage(const camera::Camera& camera, const std::string& image_id,
                              const std::string& camera_id) {
  avc::camera_t message{};
  message.image_id = image_id;
  message.camera_id = camera_id;
  const camera::Intrinsics& k = camera.intrinsics;
  message.width = k.width;
  message.height = k.height;
  message.fx = k.fx;
  message.fy = k.fy;
  message.cx = k.cx;
  message.cy = k.cy;
  for (int i = 0; i < 5; ++i) message.distortion[i] = k.distortion[static_cast<size_t>(i)];
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) message.T_cam_world[4 * r + c] = camera.T_cam_world.matrix()(r, c);
  }
  return message;
}

camera::Camera CameraFromMessage(const avc::camera_t& message) {
  camera::Camera camera;
  camera::Intrinsics& k = camera.intrinsics;
  k.width = message.width;
  k.height = message.height;
  k.fx = message.fx;
  k.fy = message.fy;
  k.cx = message.cx;
  k.cy = message.cy;
  for (int i = 0; i < 5; ++i) k.distortion[static_cast<size_t>(i)] = message.distortion[i];
  std::string problem = k.Validate();
  if (problem.empty() && !(std::isfinite(k.fx) && std::isfinite(k.fy))) {
    problem = "focal lengths are not finite";
  }
  if (!problem.empty()) {
    throw std::invalid_argument(fmt::format("camera of image '{}': {}", message.image_id, problem));
  }
  Eigen::Matrix4d pose;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) pose(r, c) = message.T_cam_world[4 * r + c];
  }
  if (!pose.allFinite()) {
    throw std::invalid_argument(
        fmt::format("camera of image '{}': T_cam_world is not finite", message.image_id));
  }
  const Eigen::Matrix3d rotation = pose.topLeftCorner<3, 3>();
  const double orthogonality =
      (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orthogonality > kRotationTolerance || rotation.determinant() < 0 ||
      pose.row(3) != Eigen::RowVector4d(0, 0, 0, 1)) {
    throw std::invalid_argument(fmt::format(
        "camera of image '{}': T_cam_world is not a rigid transform", message.image_id));
  }
  camera.T_cam_world.matrix() = pose;
  return camera;
}

}  // namespace avc::messages
