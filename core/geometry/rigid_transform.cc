#include "core/geometry/rigid_transform.h"

#include <fmt/format.h>

namespace avc::geometry {

std::string RigidTransformProblem(const Eigen::Isometry3d& transform, const std::string& name,
                                  double tolerance) {
  const auto problem = [&name](const std::string& why) {
    return name + " is not a rigid transform: " + why;
  };
  if (!transform.matrix().allFinite()) return problem("not finite (NaN or infinity)");
  const Eigen::Matrix3d rotation = transform.linear();
  const double orthogonality =
      (rotation * rotation.transpose() - Eigen::Matrix3d::Identity()).norm();
  if (!(orthogonality <= tolerance)) {
    return problem(fmt::format("its rotation block has |R R^T - I| = {:.3g}", orthogonality));
  }
  if (rotation.determinant() < 0) return problem("a reflection (determinant -1)");
  if (transform.matrix().row(3) != Eigen::RowVector4d(0, 0, 0, 1)) {
    return problem("its bottom row is not 0 0 0 1");
  }
  return {};
}

}  // namespace avc::geometry
