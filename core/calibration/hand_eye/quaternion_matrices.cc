#include "core/calibration/hand_eye/quaternion_matrices.h"

#include <Eigen/Geometry>

namespace avc::calibration::hand_eye {

QuaternionVector QuaternionOfRotation(const Eigen::Matrix3d& rotation) {
  const Eigen::Quaterniond q(rotation);
  return QuaternionVector(q.w(), q.x(), q.y(), q.z()).normalized();
}

Eigen::Matrix3d RotationOfQuaternion(const QuaternionVector& q) {
  return Eigen::Quaterniond(q(0), q(1), q(2), q(3)).normalized().toRotationMatrix();
}

QuaternionVector Conjugate(const QuaternionVector& q) { return {q(0), -q(1), -q(2), -q(3)}; }

QuaternionVector Multiply(const QuaternionVector& q, const QuaternionVector& p) {
  return LeftProductMatrix(q) * p;
}

Eigen::Matrix4d LeftProductMatrix(const QuaternionVector& q) {
  const double w = q(0), x = q(1), y = q(2), z = q(3);
  Eigen::Matrix4d m;
  m << w, -x, -y, -z,  //
      x, w, -z, y,     //
      y, z, w, -x,     //
      z, -y, x, w;
  return m;
}

Eigen::Matrix4d RightProductMatrix(const QuaternionVector& q) {
  const double w = q(0), x = q(1), y = q(2), z = q(3);
  Eigen::Matrix4d m;
  m << w, -x, -y, -z,  //
      x, w, z, -y,     //
      y, -z, w, x,     //
      z, y, -x, w;
  return m;
}

}  // namespace avc::calibration::hand_eye
