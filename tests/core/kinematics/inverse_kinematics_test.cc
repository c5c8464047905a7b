#include "core/kinematics/inverse_kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <stdexcept>

#include "core/kinematics/forward_kinematics.h"
#include "core/kinematics/pose_difference.h"

namespace avc::kinematics {
namespace {

double Uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

JointVector RandomJoints(std::mt19937_64& rng) {
  JointVector q;
  for (int i = 0; i < 6; ++i) q[i] = Uniform(rng, -std::numbers::pi, std::numbers::pi);
  return q;
}

double LargestWrappedGap(const JointVector& a, const JointVector& b) {
  double gap = 0;
  for (int i = 0; i < 6; ++i) gap = std::max(gap, std::abs(WrapAngle(a[i] - b[i])));
  return gap;
}

void ExpectAllReproduce(const DhParameters& dh, const std::vector<JointVector>& solutions,
                        const Eigen::Isometry3d& pose, double tolerance) {
  for (const JointVector& solution : solutions) {
    ASSERT_TRUE(solution.allFinite());
    for (int i = 0; i < 6; ++i) {
      EXPECT_GT(solution[i], -std::numbers::pi);
      EXPECT_LE(solution[i], std::numbers::pi);
    }
    const PoseDifference error = ComparePoses(ForwardKinematics(dh, solution), pose);
    EXPECT_LT(error.translation_m, tolerance);
    EXPECT_LT(error.rotation_rad, tolerance);
  }
}

TEST(InverseKinematics, RoundTripsRandomJointVectors) {
  const DhParameters dh = NominalUr5();
  std::mt19937_64 rng(20240601);
  std::map<size_t, int> branch_counts;
  double worst_pose_error = 0, worst_joint_gap = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const JointVector q = RandomJoints(rng);
    const Eigen::Isometry3d pose = ForwardKinematics(dh, q);
    const std::vector<JointVector> solutions = InverseKinematics(dh, pose);
    ASSERT_FALSE(solutions.empty()) << "trial " << trial;
    ASSERT_LE(solutions.size(), 8u);
    ++branch_counts[solutions.size()];
    double nearest = 1e9;
    for (const JointVector& solution : solutions) {
      const PoseDifference error = ComparePoses(ForwardKinematics(dh, solution), pose);
      worst_pose_error = std::max({worst_pose_error, error.translation_m, error.rotation_rad});
      nearest = std::min(nearest, LargestWrappedGap(solution, q));
    }
    worst_joint_gap = std::max(worst_joint_gap, nearest);
    ASSERT_LT(nearest, 1e-8) << "trial " << trial << ": the original joints are not a solution";
  }
  EXPECT_LT(worst_pose_error, 1e-9);
  // Most random poses of a UR5 have all 8 branches.
  EXPECT_GT(branch_counts[8], 500);
  std::cout << "worst pose error " << worst_pose_error << ", worst joint gap " << worst_joint_gap
            << "\n";
  for (const auto& [count, poses] : branch_counts)
    std::cout << count << " branches: " << poses << " poses\n";
}

TEST(InverseKinematics, HandlesThetaOffsetsAndOtherLengths) {
  DhParameters dh = NominalUr5();  // a series-2 UR5 with calibrated zero offsets
  dh.a[2] = -0.39225;
  dh.d[3] = 0.11;
  dh.d[4] = 0.09475;
  dh.d[5] = 0.0825;
  dh.theta_offset << 0.01, -0.02, 0.005, 0.3, -0.1, 1.0;
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    const JointVector q = RandomJoints(rng);
    const Eigen::Isometry3d pose = ForwardKinematics(dh, q);
    const std::vector<JointVector> solutions = InverseKinematics(dh, pose);
    ExpectAllReproduce(dh, solutions, pose, 1e-9);
    double nearest = 1e9;
    for (const JointVector& s : solutions) nearest = std::min(nearest, LargestWrappedGap(s, q));
    ASSERT_LT(nearest, 1e-8) << "trial " << trial;
  }
}

TEST(InverseKinematics, WristSingularityGivesFiniteSolutions) {
  const DhParameters dh = NominalUr5();
  JointVector q;
  q << 0.4, -1.2, 1.5, -0.7, 0.0, 0.9;  // q5 = 0: joints 4 and 6 aligned
  const Eigen::Isometry3d pose = ForwardKinematics(dh, q);
  const std::vector<JointVector> solutions = InverseKinematics(dh, pose, 0.9);
  ASSERT_FALSE(solutions.empty());
  ExpectAllReproduce(dh, solutions, pose, 1e-9);
  // With the joint-6 hint equal to the true q6 the original joints come back exactly.
  double nearest = 1e9;
  for (const JointVector& s : solutions) nearest = std::min(nearest, LargestWrappedGap(s, q));
  EXPECT_LT(nearest, 1e-9);
  // Any other hint still reproduces the pose; the branches that are singular (the other shoulder
  // branch is not) take the hint as joint 6.
  const std::vector<JointVector> other = InverseKinematics(dh, pose, -2.0);
  ASSERT_FALSE(other.empty());
  ExpectAllReproduce(dh, other, pose, 1e-9);
  int singular_branches = 0;
  for (const JointVector& s : other) {
    if (std::abs(std::sin(s[4])) < 1e-9) {
      ++singular_branches;
      EXPECT_NEAR(s[5], -2.0, 1e-12);
    }
  }
  EXPECT_GT(singular_branches, 0);
}

TEST(InverseKinematics, ShoulderAndElbowSingularitiesGiveFiniteSolutions) {
  const DhParameters dh = NominalUr5();
  // Upper arm vertical and straight (q3 = 0), wrist 1 making theta234 = 0: the wrist centre sits
  // at exactly d4 from the base axis (the two shoulder branches merge) and the elbow branches
  // merge.
  JointVector q;
  q << 0.3, -std::numbers::pi / 2, 0.0, std::numbers::pi / 2, 0.7, 0.2;
  const Eigen::Isometry3d pose = ForwardKinematics(dh, q);
  const std::vector<JointVector> solutions = InverseKinematics(dh, pose);
  ASSERT_FALSE(solutions.empty());
  ExpectAllReproduce(dh, solutions, pose, 1e-7);
  double nearest = 1e9;
  for (const JointVector& s : solutions) nearest = std::min(nearest, LargestWrappedGap(s, q));
  EXPECT_LT(nearest, 1e-6);
  // Upright with every singularity at once: shoulder, elbow and wrist.
  JointVector upright;
  upright << 0, -std::numbers::pi / 2, 0, -std::numbers::pi / 2, 0, 0;
  const Eigen::Isometry3d upright_pose = ForwardKinematics(dh, upright);
  const std::vector<JointVector> upright_solutions = InverseKinematics(dh, upright_pose);
  ASSERT_FALSE(upright_solutions.empty());
  ExpectAllReproduce(dh, upright_solutions, upright_pose, 1e-7);
}

TEST(InverseKinematics, OutOfReachGivesNoSolution) {
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() << 1.2, 0.4, 0.3;  // beyond |a2| + |a3| + wrist offsets
  EXPECT_TRUE(InverseKinematics(NominalUr5(), far).empty());
  // Inside the base cylinder of radius d4 the wrist centre cannot go.
  Eigen::Isometry3d inside = Eigen::Isometry3d::Identity();
  inside.translation() << 0.01, 0.0, 0.3 + 0.0823;  // flange z up: wrist centre 1 cm from the axis
  EXPECT_TRUE(InverseKinematics(NominalUr5(), inside).empty());
}

TEST(InverseKinematics, RejectsBadInput) {
  Eigen::Isometry3d pose = ForwardKinematics(NominalUr5(), JointVector::Constant(0.3));
  Eigen::Isometry3d nan_pose = pose;
  nan_pose.translation().x() = std::nan("");
  EXPECT_THROW(InverseKinematics(NominalUr5(), nan_pose), std::invalid_argument);
  Eigen::Isometry3d sheared = pose;
  sheared.linear()(0, 1) += 0.1;
  EXPECT_THROW(InverseKinematics(NominalUr5(), sheared), std::invalid_argument);
  DhParameters bent = NominalUr5();
  bent.alpha[1] = 1e-4;
  try {
    InverseKinematics(bent, pose);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("alpha[2]"), std::string::npos) << error.what();
  }
}

TEST(ClosestSolution, PicksTheNearestBranchAndTurn) {
  const DhParameters dh = NominalUr5();
  JointVector q;
  q << 2.9, -1.0, 1.3, -2.8, -1.1, 3.0;
  const std::vector<JointVector> solutions = InverseKinematics(dh, ForwardKinematics(dh, q));
  ASSERT_GE(solutions.size(), 4u);
  // The arm sits one turn around on joints 1 and 6 and slightly off the solution.
  JointVector current = q;
  current[0] -= 2 * std::numbers::pi;
  current[5] -= 2 * std::numbers::pi;
  current += JointVector::Constant(0.01);
  const std::optional<JointVector> closest = ClosestSolution(solutions, current);
  ASSERT_TRUE(closest.has_value());
  JointVector expected = q;
  expected[0] -= 2 * std::numbers::pi;
  expected[5] -= 2 * std::numbers::pi;
  EXPECT_LT((*closest - expected).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_TRUE(WithinJointLimits(*closest));
  EXPECT_FALSE(ClosestSolution({}, current).has_value());
  EXPECT_THROW(ClosestSolution(solutions, JointVector::Constant(std::nan(""))),
               std::invalid_argument);
}

TEST(ClosestSolution, StaysInsideTheJointLimits) {
  JointVector solution = JointVector::Zero();
  solution[0] = 3.0;
  const JointVector current = JointVector::Constant(6.2);  // nearest turn of 3.0 would be 3 + 2 pi
  const std::optional<JointVector> closest = ClosestSolution({solution}, current);
  ASSERT_TRUE(closest.has_value());
  EXPECT_TRUE(WithinJointLimits(*closest));
  EXPECT_NEAR((*closest)[0], 3.0, 1e-15);
  EXPECT_NEAR((*closest)[1], 2 * std::numbers::pi, 1e-15);
}

DhParameters PerturbedUr5() {
  DhParameters perturbed = NominalUr5();
  perturbed.a << 0.0008, -0.4243, -0.3931, -0.0006, 0.0009, -0.0004;
  perturbed.d << 0.0899, 0.0007, -0.0005, 0.1085, 0.0951, 0.0818;
  perturbed.alpha += (JointVector() << 4e-4, -6e-4, 3e-4, -5e-4, 8e-4, 2e-4).finished();
  perturbed.theta_offset << 3e-4, -4e-4, 2e-4, 6e-4, -1e-4, 5e-4;
  return perturbed;
}

TEST(RefineInverseKinematics, ConvergesOnAPerturbedArm) {
  const DhParameters perturbed = PerturbedUr5();
  EXPECT_NE(UrStructureError(perturbed), "");
  EXPECT_THROW(InverseKinematics(perturbed, Eigen::Isometry3d::Identity()), std::invalid_argument);
  const DhParameters structured = NearestUrStructure(perturbed);
  EXPECT_EQ(UrStructureError(structured), "");
  std::mt19937_64 rng(9);
  for (int trial = 0; trial < 100; ++trial) {
    const JointVector q = RandomJoints(rng);
    // Start a few milliradians away, as a nominal-model solution would be.
    JointVector seed = q;
    for (int i = 0; i < 6; ++i) seed[i] += Uniform(rng, -0.005, 0.005);
    const Eigen::Isometry3d pose = ForwardKinematics(perturbed, q);
    const std::optional<JointVector> refined = RefineInverseKinematics(perturbed, pose, seed);
    ASSERT_TRUE(refined.has_value()) << "trial " << trial;
    const PoseDifference error = ComparePoses(ForwardKinematics(perturbed, *refined), pose);
    EXPECT_LT(error.translation_m, 1e-11);
    EXPECT_LT(error.rotation_rad, 1e-11);
    EXPECT_LT(LargestWrappedGap(*refined, q), 1e-8);
  }
}

TEST(InverseKinematicsRefined, FindsEveryBranchOfAPerturbedArm) {
  const DhParameters perturbed = PerturbedUr5();
  const DhParameters nominal = NominalUr5();
  std::mt19937_64 rng(10);
  int matching_counts = 0;
  int trials = 0;
  while (trials < 200) {
    const JointVector q = RandomJoints(rng);
    const Eigen::Isometry3d pose = ForwardKinematics(perturbed, q);
    // Completeness is promised away from the wrist, elbow and shoulder singularities (within a few
    // centimetres or degrees of them two branches of the perturbed arm can merge into one seed).
    const Eigen::Vector3d wrist_centre = pose.translation() - perturbed.d[5] * pose.linear().col(2);
    if (std::abs(std::sin(q[4])) < 0.05 || std::abs(std::sin(q[2])) < 0.05 ||
        wrist_centre.head<2>().norm() < perturbed.d[3] + 0.02) {
      continue;
    }
    const int trial = trials++;
    const std::vector<JointVector> solutions = InverseKinematicsRefined(perturbed, pose);
    ASSERT_FALSE(solutions.empty()) << "trial " << trial;
    ExpectAllReproduce(perturbed, solutions, pose, 1e-9);
    double nearest = 1e9;
    for (const JointVector& s : solutions) nearest = std::min(nearest, LargestWrappedGap(s, q));
    ASSERT_LT(nearest, 1e-8) << "trial " << trial;
    if (solutions.size() == InverseKinematics(nominal, ForwardKinematics(nominal, q)).size()) {
      ++matching_counts;
    }
  }
  // Millimetre perturbations rarely change how many branches reach a pose.
  EXPECT_GT(matching_counts, 190);
  // On a UR-structured arm it is the analytic solver.
  JointVector q;
  q << 0.2, -0.9, 1.1, 0.4, -0.6, 1.7;
  const Eigen::Isometry3d pose = ForwardKinematics(nominal, q);
  const std::vector<JointVector> analytic = InverseKinematics(nominal, pose);
  const std::vector<JointVector> refined = InverseKinematicsRefined(nominal, pose);
  ASSERT_EQ(analytic.size(), refined.size());
  for (size_t i = 0; i < analytic.size(); ++i)
    EXPECT_LT(LargestWrappedGap(analytic[i], refined[i]), 1e-12);
}

TEST(InverseKinematicsRefined, SingularPosesGiveFiniteSolutions) {
  const DhParameters perturbed = PerturbedUr5();
  for (const JointVector& q :
       {(JointVector() << 0.4, -1.2, 1.5, -0.7, 0.0, 0.9).finished(),
        (JointVector() << 0.3, -std::numbers::pi / 2, 0.0, std::numbers::pi / 2, 0.7, 0.2)
            .finished(),
        (JointVector() << 0, -std::numbers::pi / 2, 0, -std::numbers::pi / 2, 0, 0).finished()}) {
    const Eigen::Isometry3d pose = ForwardKinematics(perturbed, q);
    const std::vector<JointVector> solutions = InverseKinematicsRefined(perturbed, pose);
    ASSERT_FALSE(solutions.empty()) << q.transpose();
    ExpectAllReproduce(perturbed, solutions, pose, 1e-9);
  }
}

TEST(RefineInverseKinematics, UnreachablePoseFails) {
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() << 1.5, 0, 0.2;
  EXPECT_FALSE(RefineInverseKinematics(NominalUr5(), far, JointVector::Constant(0.2)).has_value());
}

}  // namespace
}  // namespace avc::kinematics
