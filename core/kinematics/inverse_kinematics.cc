#include "core/kinematics/inverse_kinematics.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/kinematics/forward_kinematics.h"
#include "core/kinematics/pose_difference.h"

namespace avc::kinematics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kStructureTolerance = 1e-12;
const JointVector kUrAlpha = (JointVector() << kPi / 2, 0, 0, kPi / 2, -kPi / 2, 0).finished();
// Cosines that leave [-1, 1] by no more than rounding are clamped, not rejected.
constexpr double kCosineSlack = 1e-10;
// Seeds for a perturbed arm come from its nearest UR-structured arm, which may miss the pose
// by millimetres.
constexpr double kSeedCosineSlack = 0.05;
constexpr double kSeedBranchSplit = 0.05;
// Below this |sin q5| joints 4 and 6 are treated as aligned.
constexpr double kWristSingularSine = 1e-12;
// A branch must reproduce the pose this well to be returned (a clamped boundary case can lose
// a few digits; a spurious branch is off by millimetres).
constexpr double kBranchAcceptance = 1e-7;
constexpr double kDuplicateJointGap = 1e-9;

void RequireRigidPose(const Eigen::Isometry3d& pose, const char* where) {
  if (!pose.matrix().allFinite()) {
    throw std::invalid_argument(fmt::format("{}: the flange pose is not finite", where));
  }
  const Eigen::Matrix3d rotation = pose.linear();
  const double orthogonality =
      (rotation * rotation.transpose() - Eigen::Matrix3d::Identity()).norm();
  if (orthogonality > 1e-6 || rotation.determinant() < 0) {
    throw std::invalid_argument(
        fmt::format("{}: the flange pose's rotation is not a rotation matrix (|R R^T - I| = {:g})",
                    where, orthogonality));
  }
}

bool SameJoints(const JointVector& a, const JointVector& b) {
  for (int i = 0; i < 6; ++i) {
    if (std::abs(WrapAngle(a[i] - b[i])) > kDuplicateJointGap) return false;
  }
  return true;
}

void AddUnlessDuplicate(const JointVector& q, std::vector<JointVector>& solutions) {
  const bool duplicate = std::any_of(solutions.begin(), solutions.end(),
                                     [&](const JointVector& s) { return SameJoints(s, q); });
  if (!duplicate) solutions.push_back(q);
}

// acos/asin arguments that rounding (or, for seeds, a small departure from the UR structure)
// pushed past +-1 by at most `slack` are clamped; nullopt when further out.
std::optional<double> ClampCosine(double value, double slack) {
  if (std::abs(value) > 1 + slack) return std::nullopt;
  return std::clamp(value, -1.0, 1.0);
}

// The 8 closed-form branches of a UR-structured `dh`, indexed shoulder * 4 + wrist * 2 + elbow,
// wrapped to (-pi, pi] but not checked against the pose; nullopt where a branch does not reach.
// `split` keeps the two shoulder and the two elbow branches at least that far from where they
// merge, so seeds for a perturbed arm near those singularities start on their own sides (0 for
// exact solutions).
using Branches = std::array<std::optional<JointVector>, 8>;
Branches AnalyticBranches(const DhParameters& dh, const Eigen::Isometry3d& T_base_flange,
                          double singular_q6, double slack, double split = 0) {
  const double d1 = dh.d[0], a2 = dh.a[1], a3 = dh.a[2], d4 = dh.d[3], d6 = dh.d[5];
  const Eigen::Matrix3d& R = T_base_flange.linear();
  const Eigen::Vector3d p = T_base_flange.translation();
  Branches branches;

  // Joint 1: the wrist centre (frame 5 origin) lies at height d4 along z1 = (s1, -c1, 0).
  const Eigen::Vector3d wrist = p - d6 * R.col(2);
  const double radius = std::hypot(wrist.x(), wrist.y());
  if (radius == 0) return branches;
  const std::optional<double> sine_shoulder = ClampCosine(d4 / radius, slack);
  if (!sine_shoulder) return branches;
  const double azimuth = std::atan2(wrist.y(), wrist.x());
  const double shoulder = std::clamp(std::asin(*sine_shoulder), -kPi / 2 + split, kPi / 2 - split);
  const std::array<double, 2> theta1_branches = {azimuth + shoulder, azimuth + kPi - shoulder};

  for (int shoulder_branch = 0; shoulder_branch < 2; ++shoulder_branch) {
    const double theta1 = theta1_branches[shoulder_branch];
    const Eigen::Vector3d z1(std::sin(theta1), -std::cos(theta1), 0);
    // Components of the flange axes along z1: x6 -> s5 c6, y6 -> -s5 s6, z6 -> c5.
    const double x_along = z1.dot(R.col(0)), y_along = z1.dot(R.col(1));
    const double c5 = z1.dot(R.col(2));
    const double s5_magnitude = std::hypot(x_along, y_along);
    for (int wrist_branch = 0; wrist_branch < 2; ++wrist_branch) {
      const double wrist_sign = wrist_branch == 0 ? 1.0 : -1.0;
      const double theta5 = std::atan2(wrist_sign * s5_magnitude, c5);
      const double theta6 = s5_magnitude < kWristSingularSine
                                ? singular_q6 + dh.theta_offset[5]
                                : std::atan2(-wrist_sign * y_along, wrist_sign * x_along);
      // Joints 2-4 form a planar 3R chain in frame 1: peel frames 1, 5 and 6 off the pose.
      const Eigen::Isometry3d T_1_4 =
          DhLinkTransform(dh.a[0], d1, dh.alpha[0], theta1).inverse() * T_base_flange *
          DhLinkTransform(dh.a[5], d6, dh.alpha[5], theta6).inverse() *
          DhLinkTransform(dh.a[4], dh.d[4], dh.alpha[4], theta5).inverse();
      const double px = T_1_4.translation().x(), py = T_1_4.translation().y();
      const std::optional<double> c3 =
          ClampCosine((px * px + py * py - a2 * a2 - a3 * a3) / (2 * a2 * a3), slack);
      if (!c3) continue;
      const double theta234 = std::atan2(T_1_4.linear()(1, 0), T_1_4.linear()(0, 0));
      for (int elbow_branch = 0; elbow_branch < 2; ++elbow_branch) {
        const double theta3 =
            (elbow_branch == 0 ? 1.0 : -1.0) * std::clamp(std::acos(*c3), split, kPi - split);
        const double theta2 =
            std::atan2(py, px) - std::atan2(a3 * std::sin(theta3), a2 + a3 * std::cos(theta3));
        const double theta4 = theta234 - theta2 - theta3;
        JointVector theta;
        theta << theta1, theta2, theta3, theta4, theta5, theta6;
        branches[shoulder_branch * 4 + wrist_branch * 2 + elbow_branch] =
            WrapJoints(theta - dh.theta_offset);
      }
    }
  }
  return branches;
}

// A seed for one branch of a perturbed arm: solve the structured arm for a corrected target
// until the perturbed arm reaches the real one (each pass removes the model error seen at the
// last joints). Near the wrist singularity this keeps the branch's identity, where the structured
// arm's joints for the uncorrected target can be far off in joints 4 and 6.
std::optional<JointVector> CorrectedBranchSeed(const DhParameters& dh,
                                               const DhParameters& structured,
                                               const Eigen::Isometry3d& T_base_flange,
                                               double singular_q6, int branch) {
  constexpr int kCorrectionPasses = 4;
  constexpr double kCorrectionTolerance = 1e-7;  // Newton finishes from here
  Eigen::Isometry3d corrected = T_base_flange;
  std::optional<JointVector> q;
  for (int pass = 0; pass < kCorrectionPasses; ++pass) {
    const std::optional<JointVector> candidate =
        AnalyticBranches(structured, corrected, singular_q6, kSeedCosineSlack)[branch];
    if (!candidate) break;
    q = candidate;
    const Eigen::Isometry3d reached = ForwardKinematics(dh, *q);
    const PoseDifference error = ComparePoses(reached, T_base_flange);
    if (error.translation_m < kCorrectionTolerance && error.rotation_rad < kCorrectionTolerance) {
      break;
    }
    corrected = T_base_flange * reached.inverse() * corrected;
  }
  return q;
}

}  // namespace

std::string UrStructureError(const DhParameters& dh) {
  if (std::string error = dh.Validate(); !error.empty()) return error;
  for (int i : {0, 3, 4, 5}) {
    if (std::abs(dh.a[i]) > kStructureTolerance)
      return fmt::format("a[{}] = {} is not 0", i + 1, dh.a[i]);
  }
  for (int i : {1, 2}) {
    if (std::abs(dh.d[i]) > kStructureTolerance)
      return fmt::format("d[{}] = {} is not 0", i + 1, dh.d[i]);
  }
  for (int i = 0; i < 6; ++i) {
    if (std::abs(dh.alpha[i] - kUrAlpha[i]) > kStructureTolerance) {
      return fmt::format("alpha[{}] = {} is not {}", i + 1, dh.alpha[i], kUrAlpha[i]);
    }
  }
  if (dh.a[1] == 0 || dh.a[2] == 0 || dh.d[3] == 0 || dh.d[5] == 0) {
    return "a2, a3, d4 and d6 must be non-zero";
  }
  return {};
}

DhParameters NearestUrStructure(const DhParameters& dh) {
  DhParameters structured = dh;
  for (int i : {0, 3, 4, 5}) structured.a[i] = 0;
  for (int i : {1, 2}) structured.d[i] = 0;
  structured.alpha = kUrAlpha;
  return structured;
}

std::vector<JointVector> InverseKinematics(const DhParameters& dh,
                                           const Eigen::Isometry3d& T_base_flange,
                                           double singular_q6) {
  if (std::string error = UrStructureError(dh); !error.empty()) {
    throw std::invalid_argument("InverseKinematics: the DH set lacks the UR structure: " + error);
  }
  RequireRigidPose(T_base_flange, "InverseKinematics");
  if (!std::isfinite(singular_q6)) {
    throw std::invalid_argument("InverseKinematics: singular_q6 is not finite");
  }
  std::vector<JointVector> solutions;
  for (const std::optional<JointVector>& branch :
       AnalyticBranches(dh, T_base_flange, singular_q6, kCosineSlack)) {
    if (!branch) continue;
    const JointVector& q = *branch;
    const PoseDifference error = ComparePoses(ForwardKinematics(dh, q), T_base_flange);
    if (error.translation_m < kBranchAcceptance && error.rotation_rad < kBranchAcceptance) {
      AddUnlessDuplicate(q, solutions);
    }
  }
  return solutions;
}

std::vector<JointVector> InverseKinematicsRefined(const DhParameters& dh,
                                                  const Eigen::Isometry3d& T_base_flange,
                                                  double singular_q6) {
  if (std::string error = dh.Validate(); !error.empty()) {
    throw std::invalid_argument("InverseKinematicsRefined: " + error);
  }
  RequireRigidPose(T_base_flange, "InverseKinematicsRefined");
  if (!std::isfinite(singular_q6)) {
    throw std::invalid_argument("InverseKinematicsRefined: singular_q6 is not finite");
  }
  const DhParameters structured = NearestUrStructure(dh);
  if (std::string error = UrStructureError(structured); !error.empty()) {
    throw std::invalid_argument(
        "InverseKinematicsRefined: the DH set is far from the UR structure: " + error);
  }
  // Two seeds per branch, each robust where the other is not: the corrected-target seed near the
  // wrist singularity, the split seed near the shoulder and elbow singularities (where the
  // structured arm may not reach the corrected target at all).
  const Branches split_seeds =
      AnalyticBranches(structured, T_base_flange, singular_q6, kSeedCosineSlack, kSeedBranchSplit);
  std::vector<JointVector> solutions;
  for (int branch = 0; branch < 8; ++branch) {
    for (const std::optional<JointVector>& seed :
         {CorrectedBranchSeed(dh, structured, T_base_flange, singular_q6, branch),
          split_seeds[branch]}) {
      if (!seed) continue;
      if (const std::optional<JointVector> q = RefineInverseKinematics(dh, T_base_flange, *seed)) {
        AddUnlessDuplicate(WrapJoints(*q), solutions);
      }
    }
  }
  // Near the wrist singularity the structured arm can miss a wrist branch entirely (joint 6 is
  // ill-determined there and swings the elbow target out of reach); the wrist-flipped twin of a
  // found solution is then a close seed for it.
  const size_t found = solutions.size();
  constexpr double kNearWristSingularSine = 0.2;
  for (size_t i = 0; i < found; ++i) {
    if (std::abs(std::sin(solutions[i][4])) > kNearWristSingularSine) continue;
    JointVector flipped = solutions[i];
    flipped[3] += kPi;
    flipped[4] = -flipped[4];
    flipped[5] += kPi;
    if (std::optional<JointVector> q = RefineInverseKinematics(dh, T_base_flange, flipped)) {
      AddUnlessDuplicate(WrapJoints(*q), solutions);
    }
  }
  return solutions;
}

std::optional<JointVector> ClosestSolution(const std::vector<JointVector>& solutions,
                                           const JointVector& current) {
  if (!current.allFinite()) {
    throw std::invalid_argument("ClosestSolution: the current joint vector is not finite");
  }
  std::optional<JointVector> best;
  double best_distance = 0;
  for (const JointVector& solution : solutions) {
    JointVector shifted;
    for (int i = 0; i < 6; ++i) {
      // The 2 pi equivalent nearest to the current joint, pulled back inside the limits.
      double value = solution[i] + kTwoPi * std::round((current[i] - solution[i]) / kTwoPi);
      if (value > kJointLimitRad) value -= kTwoPi;
      if (value < -kJointLimitRad) value += kTwoPi;
      shifted[i] = value;
    }
    const double distance = (shifted - current).squaredNorm();
    if (!best || distance < best_distance) {
      best = shifted;
      best_distance = distance;
    }
  }
  return best;
}

std::optional<JointVector> RefineInverseKinematics(const DhParameters& dh,
                                                   const Eigen::Isometry3d& T_base_flange,
                                                   const JointVector& seed, double tolerance) {
  if (std::string error = dh.Validate(); !error.empty()) {
    throw std::invalid_argument("RefineInverseKinematics: " + error);
  }
  RequireRigidPose(T_base_flange, "RefineInverseKinematics");
  if (!seed.allFinite())
    throw std::invalid_argument("RefineInverseKinematics: the seed is not finite");
  constexpr int kMaxIterations = 50;
  constexpr double kMaxStepRad = 0.5;  // keeps a poor seed from jumping across branches
  JointVector q = seed;
  for (int iteration = 0; iteration <= kMaxIterations; ++iteration) {
    const Eigen::Isometry3d current = ForwardKinematics(dh, q);
    const Eigen::AngleAxisd rotation_error(
        Eigen::Matrix3d(T_base_flange.linear() * current.linear().transpose()));
    Eigen::Matrix<double, 6, 1> error;
    error << T_base_flange.translation() - current.translation(),
        rotation_error.angle() * rotation_error.axis();
    if (error.head<3>().norm() < tolerance && rotation_error.angle() < tolerance) {
      if (!WithinJointLimits(q)) return std::nullopt;
      return q;
    }
    if (iteration == kMaxIterations) break;
    const Eigen::Matrix<double, 6, 6> jacobian = GeometricJacobian(dh, q);
    // Lightly damped normal equations: exact Newton away from singularities, bounded near them.
    const Eigen::Matrix<double, 6, 6> normal =
        jacobian.transpose() * jacobian + 1e-12 * Eigen::Matrix<double, 6, 6>::Identity();
    JointVector step = normal.ldlt().solve(jacobian.transpose() * error);
    if (!step.allFinite()) return std::nullopt;
    const double largest = step.cwiseAbs().maxCoeff();
    if (largest > kMaxStepRad) step *= kMaxStepRad / largest;
    q += step;
  }
  return std::nullopt;
}

}  // namespace avc::kinematics
