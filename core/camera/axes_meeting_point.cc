#include "core/camera/axes_meeting_point.h"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <stdexcept>

namespace avc::camera {

Eigen::Vector3d AxesMeetingPoint(const std::vector<Camera>& cameras) {
  if (cameras.size() < 2) {
    throw std::invalid_argument(
        fmt::format("need at least two cameras to locate the object, got {}", cameras.size()));
  }
  // Minimises the summed squared distances to the axes: sum (I - a a^T) (p - c) = 0.
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < cameras.size(); ++i) {
    const Camera& camera = cameras[i];
    if (const std::string problem = camera.intrinsics.Validate(); !problem.empty()) {
      throw std::invalid_argument(fmt::format("camera #{}: {}", i, problem));
    }
    if (!camera.T_cam_world.matrix().allFinite()) {
      throw std::invalid_argument(fmt::format("camera #{}: pose T_cam_world is not finite", i));
    }
    const Eigen::Vector3d axis = camera.Axis();
    const Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - axis * axis.transpose();
    normal += projector;
    rhs += projector * camera.Centre();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(normal);
  if (eigen.eigenvalues()(0) < 1e-6 * static_cast<double>(cameras.size())) {
    throw std::invalid_argument(
        "the optical axes are (nearly) parallel, so they do not meet near one point");
  }
  return normal.ldlt().solve(rhs);
}

}  // namespace avc::camera
