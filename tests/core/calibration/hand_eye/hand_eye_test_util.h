#pragma once

// Helpers shared by the hand-eye tests: pose comparison and random rigid transforms.

#include <Eigen/Geometry>
#include <numbers>

#include "sim/cell/random.h"

namespace avc::calibration::hand_eye::testing {

inline constexpr double kDegree = std::numbers::pi / 180;

inline double RotationErrorDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(Eigen::Matrix3d(a.linear() * b.linear().transpose())).angle() * 180 /
         std::numbers::pi;
}

inline double TranslationErrorMm(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm() * 1e3;
}

// A rotation by `angle` about a uniformly random axis.
inline Eigen::Matrix3d RandomRotation(sim::DeterministicRandom& random, double angle) {
  return Eigen::AngleAxisd(angle, random.UnitVector()).toRotationMatrix();
}

// A rigid transform with a uniformly random axis, angle up to pi and translation up to
// `reach` metres per axis.
inline Eigen::Isometry3d RandomPose(sim::DeterministicRandom& random, double reach) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = RandomRotation(random, random.Uniform(0, std::numbers::pi));
  const double x = random.Symmetric(reach), y = random.Symmetric(reach),
               z = random.Symmetric(reach);
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

}  // namespace avc::calibration::hand_eye::testing
