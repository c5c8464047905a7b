#pragma once

// Ceres residuals of the hand-eye reprojection refinement (reprojection_refinement.h).

#include <ceres/rotation.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/calibration/hand_eye/core_projection_jet.h"
#include "core/camera/pinhole_camera.h"

namespace avc::calibration::hand_eye {

// Residual of one corner: projected minus detected pixel. Parameters: Z = T_cam_flange and
// Y = T_base_board (X^-1, so no inverse inside the cost), each as an Eigen quaternion (x y z w)
// and a translation, and the view's robot-pose correction (w, tau): the flange is at
// T_base_flange = [Exp(w) R | t + tau] for the reported [R | t].
class CornerResidual {
 public:
  CornerResidual(const camera::Intrinsics& intrinsics, const Eigen::Isometry3d& T_base_flange,
                 const Eigen::Vector3d& board_point, const Eigen::Vector2d& pixel)
      : intrinsics_(intrinsics),
        R_base_flange_(T_base_flange.linear()),
        t_base_flange_(T_base_flange.translation()),
        board_point_(board_point),
        pixel_(pixel) {}

  template <typename T>
  bool operator()(const T* q_cam_flange, const T* t_cam_flange, const T* q_base_board,
                  const T* t_base_board, const T* robot_correction, T* residual) const {
    using Vector3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Eigen::Quaternion<T>> R_cam_flange(q_cam_flange);
    const Eigen::Map<const Vector3> t_z(t_cam_flange);
    const Eigen::Map<const Eigen::Quaternion<T>> R_base_board(q_base_board);
    const Eigen::Map<const Vector3> t_y(t_base_board);
    const Vector3 p_base = R_base_board * board_point_.cast<T>() + t_y;
    // Into the corrected flange frame: R^T Exp(w)^T (p - t - tau).
    const Vector3 offset =
        p_base - t_base_flange_.cast<T>() - Eigen::Map<const Vector3>(robot_correction + 3);
    const T inverse_rotation[3] = {-robot_correction[0], -robot_correction[1],
                                   -robot_correction[2]};
    Vector3 unrotated;
    ceres::AngleAxisRotatePoint(inverse_rotation, offset.data(), unrotated.data());
    const Vector3 p_flange = R_base_flange_.transpose().cast<T>() * unrotated;
    const Vector3 p_cam = R_cam_flange * p_flange + t_z;
    if (!(p_cam.z() > T(0))) return false;
    const Eigen::Matrix<T, 2, 1> normalised(p_cam.x() / p_cam.z(), p_cam.y() / p_cam.z());
    const Eigen::Matrix<T, 2, 1> distorted = DistortForCeres(intrinsics_, normalised);
    residual[0] = intrinsics_.fx * distorted.x() + intrinsics_.cx - pixel_.x();
    residual[1] = intrinsics_.fy * distorted.y() + intrinsics_.cy - pixel_.y();
    return true;
  }

 private:
  camera::Intrinsics intrinsics_;
  Eigen::Matrix3d R_base_flange_;
  Eigen::Vector3d t_base_flange_;
  Eigen::Vector3d board_point_;
  Eigen::Vector2d pixel_;
};

// Gaussian prior of a robot-pose correction, in pixel units: sigma_px * (w / sigma_w,
// tau / sigma_tau), so pixels and robot poses add up to a likelihood.
class RobotPosePrior {
 public:
  RobotPosePrior(double rotation_weight, double translation_weight)
      : rotation_weight_(rotation_weight), translation_weight_(translation_weight) {}

  template <typename T>
  bool operator()(const T* robot_correction, T* residual) const {
    for (int i = 0; i < 3; ++i) {
      residual[i] = rotation_weight_ * robot_correction[i];
      residual[i + 3] = translation_weight_ * robot_correction[i + 3];
    }
    return true;
  }

 private:
  double rotation_weight_;
  double translation_weight_;
};

}  // namespace avc::calibration::hand_eye
