#pragma once

// Unit quaternions as plain 4-vectors (w, x, y, z) and the 4x4 matrices that turn a quaternion
// product into a matrix product, as Dornaika & Horaud's closed form needs them:
// q (x) p = LeftProductMatrix(q) * p and p (x) q = RightProductMatrix(q) * p.

#include <Eigen/Core>

namespace avc::calibration::hand_eye {

using QuaternionVector = Eigen::Vector4d;  // (w, x, y, z), Hamilton convention

// The unit quaternion of a rotation matrix, with whatever sign the conversion gives.
QuaternionVector QuaternionOfRotation(const Eigen::Matrix3d& rotation);
// The rotation matrix of a (not necessarily unit) quaternion; its sign does not matter.
Eigen::Matrix3d RotationOfQuaternion(const QuaternionVector& q);

QuaternionVector Conjugate(const QuaternionVector& q);
// Hamilton product q (x) p.
QuaternionVector Multiply(const QuaternionVector& q, const QuaternionVector& p);

// Q(q) with q (x) p = Q(q) p; orthonormal for a unit q.
Eigen::Matrix4d LeftProductMatrix(const QuaternionVector& q);
// W(q) with p (x) q = W(q) p; orthonormal for a unit q.
Eigen::Matrix4d RightProductMatrix(const QuaternionVector& q);

}  // namespace avc::calibration::hand_eye
