// The quaternion product matrices against Eigen's quaternion product.

#include "core/calibration/hand_eye/quaternion_matrices.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "tests/core/calibration/hand_eye/hand_eye_test_util.h"

namespace avc::calibration::hand_eye {
namespace {

QuaternionVector AsVector(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }

TEST(HandEyeQuaternions, ProductMatricesMatchTheHamiltonProduct) {
  sim::DeterministicRandom random(17);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Quaterniond q(testing::RandomRotation(random, random.Uniform(0, 3.14)));
    const Eigen::Quaterniond p(testing::RandomRotation(random, random.Uniform(0, 3.14)));
    const QuaternionVector expected = AsVector(q * p);
    EXPECT_LT((LeftProductMatrix(AsVector(q)) * AsVector(p) - expected).norm(), 1e-15);
    EXPECT_LT((RightProductMatrix(AsVector(p)) * AsVector(q) - expected).norm(), 1e-15);
    EXPECT_LT((Multiply(AsVector(q), AsVector(p)) - expected).norm(), 1e-15);
    const Eigen::Matrix4d left = LeftProductMatrix(AsVector(q));
    EXPECT_LT((left.transpose() * left - Eigen::Matrix4d::Identity()).norm(), 1e-14);
  }
}

TEST(HandEyeQuaternions, ConversionsRoundTrip) {
  sim::DeterministicRandom random(18);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Matrix3d rotation = testing::RandomRotation(random, random.Uniform(0, 3.14159));
    const QuaternionVector q = QuaternionOfRotation(rotation);
    EXPECT_NEAR(q.norm(), 1.0, 1e-15);
    EXPECT_LT((RotationOfQuaternion(q) - rotation).norm(), 1e-14);
    EXPECT_LT((RotationOfQuaternion(-q) - rotation).norm(), 1e-14);
    EXPECT_LT((Multiply(q, Conjugate(q)) - QuaternionVector(1, 0, 0, 0)).norm(), 1e-15);
  }
}

}  // namespace
}  // namespace avc::calibration::hand_eye
