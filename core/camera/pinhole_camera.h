#pragma once

// The camera model of the whole system: OpenCV's pinhole with distortion k1 k2 p1 p2 k3, and a
// pose T_cam_world (world to camera), so a world point X images at K * distort([R|t] X).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>

namespace avc::camera {

struct Intrinsics {
  int width = 0;
  int height = 0;
  double fx = 0, fy = 0, cx = 0, cy = 0;
  std::array<double, 5> distortion{};  // k1 k2 p1 p2 k3, OpenCV order

  // Normalised image coordinates (x/z, y/z) with distortion applied, as cv::projectPoints.
  Eigen::Vector2d Distort(const Eigen::Vector2d& normalised) const;
  // Inverse of Distort by fixed-point iteration (as cv::undistortPoints); exact for no
  // distortion.
  Eigen::Vector2d Undistort(const Eigen::Vector2d& distorted) const;
  // Pixel of a point in camera coordinates; nullopt behind the camera (z <= 0).
  std::optional<Eigen::Vector2d> Project(const Eigen::Vector3d& p_cam) const;
  // Unit ray in camera coordinates through pixel (u, v) (pixel centres at integers).
  Eigen::Vector3d Ray(const Eigen::Vector2d& pixel) const;
  bool HasDistortion() const;
  // Empty when usable, else a sentence naming the bad field.
  std::string Validate() const;
};

struct Camera {
  Intrinsics intrinsics;
  Eigen::Isometry3d T_cam_world = Eigen::Isometry3d::Identity();

  std::optional<Eigen::Vector2d> Project(const Eigen::Vector3d& p_world) const {
    return intrinsics.Project(T_cam_world * p_world);
  }
  // Camera centre in world coordinates.
  Eigen::Vector3d Centre() const { return T_cam_world.inverse().translation(); }
  // Unit viewing direction (optical axis) in world coordinates.
  Eigen::Vector3d Axis() const { return T_cam_world.rotation().transpose().col(2); }
};

}  // namespace avc::camera
