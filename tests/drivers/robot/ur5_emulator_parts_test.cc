// The emulator's building blocks on their own: trapezoidal profile, script parser, arm motion
// model; and the driver's script generation, secondary messages and motion monitor.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/kinematics/forward_kinematics.h"
#include "drivers/robot/dashboard_client.h"
#include "drivers/robot/motion_monitor.h"
#include "drivers/robot/protocol/primary_protocol.h"
#include "drivers/robot/protocol/primary_robot_state.h"
#include "drivers/robot/urscript.h"
#include "sim/cell/perturbation.h"
#include "sim/emulators/ur5/trapezoid_profile.h"
#include "sim/emulators/ur5/ur5_arm.h"
#include "sim/emulators/ur5/ur5_script.h"

namespace avc {
namespace {

using kinematics::JointVector;
using sim::ur5::ScriptStatement;

std::vector<std::string> Lines(const std::string& text) {
  sim::ur5::ScriptAssembler assembler;
  assembler.Append(text);
  auto unit = assembler.Next();
  return unit ? *unit : std::vector<std::string>{};
}

TEST(TrapezoidProfile, CruisesWhenTheDistanceAllows) {
  const sim::ur5::TrapezoidProfile profile(2.0, 1.0, 2.0);  // 0.5 s ramps, 1.5 s cruise
  EXPECT_NEAR(profile.duration(), 2.5, 1e-12);
  EXPECT_NEAR(profile.Position(0.5), 0.25, 1e-12);
  EXPECT_NEAR(profile.Velocity(1.0), 1.0, 1e-12);
  EXPECT_NEAR(profile.Position(2.5), 2.0, 1e-12);
  EXPECT_NEAR(profile.Position(2.0), 2.0 - 0.25, 1e-12);
  EXPECT_EQ(profile.Velocity(3.0), 0.0);
}

TEST(TrapezoidProfile, TriangleWhenTooShortAndRejectsBadRates) {
  const sim::ur5::TrapezoidProfile profile(0.25, 10.0, 1.0);  // peak 0.5 at 0.5 s
  EXPECT_NEAR(profile.duration(), 1.0, 1e-12);
  EXPECT_NEAR(profile.Velocity(0.5), 0.5, 1e-12);
  EXPECT_NEAR(profile.Position(1.0), 0.25, 1e-12);
  EXPECT_THROW(sim::ur5::TrapezoidProfile(1.0, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(sim::ur5::TrapezoidProfile(-1.0, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(sim::ur5::TrapezoidProfile(NAN, 1.0, 1.0), std::invalid_argument);
}

TEST(Urscript, GeneratedProgramsParseBackToTheSameMotion) {
  const robot::Joints q = {0.1, -1.2, 1.3, -1.4, -1.5707963267948966, 0.25};
  const std::string movej = robot::MoveJProgram(q, 1.2, 0.8);
  EXPECT_EQ(movej.rfind("def avc_motion():\n  movej([", 0), 0u) << movej;
  EXPECT_NE(movej.find("\nend\n"), std::string::npos);
  const auto program = sim::ur5::ParseScriptUnit(Lines(movej));
  ASSERT_FALSE(program.error) << program.error->text;
  ASSERT_EQ(program.statements.size(), 1u);
  const ScriptStatement& s = program.statements[0];
  EXPECT_EQ(s.kind, ScriptStatement::Kind::kMoveJ);
  EXPECT_FALSE(s.target_is_pose);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(s.target[i], q[i], 1e-9);
  EXPECT_DOUBLE_EQ(s.acceleration, 1.2);
  EXPECT_DOUBLE_EQ(s.velocity, 0.8);

  const auto movel =
      sim::ur5::ParseScriptUnit(Lines(robot::MoveLProgram({0.4, -0.2, 0.3, 0, 3.1, 0}, 0.5, 0.1)));
  ASSERT_FALSE(movel.error);
  EXPECT_EQ(movel.statements[0].kind, ScriptStatement::Kind::kMoveL);
  EXPECT_TRUE(movel.statements[0].target_is_pose);
  const auto stop = sim::ur5::ParseScriptUnit(Lines(robot::StopJProgram(2.0)));
  ASSERT_FALSE(stop.error);
  EXPECT_EQ(stop.statements[0].kind, ScriptStatement::Kind::kStopJ);

  EXPECT_THROW(robot::MoveJProgram({0, NAN, 0, 0, 0, 0}, 1, 1), std::invalid_argument);
  EXPECT_THROW(robot::MoveJProgram(q, 0, 1), std::invalid_argument);
  EXPECT_THROW(robot::MoveLProgram({0, 0, 0, 0, 0, 0}, 1, -1), std::invalid_argument);
}

TEST(Ur5Script, UnsupportedAndMalformedStatementsAreErrorsWithLine) {
  const auto unsupported =
      sim::ur5::ParseScriptUnit(Lines("def p():\n  movej([0,0,0,0,0,0])\n  set_digital_out(1, "
                                      "True)\nend\n"));
  ASSERT_TRUE(unsupported.error);
  EXPECT_EQ(unsupported.error->line, 3);
  EXPECT_NE(unsupported.error->text.find("set_digital_out"), std::string::npos);
  EXPECT_TRUE(unsupported.statements.empty());
  EXPECT_TRUE(sim::ur5::ParseScriptUnit({"movej([0,0,0], a=1)"}).error);
  EXPECT_TRUE(sim::ur5::ParseScriptUnit({"movel([0,0,0,0,0,0])"}).error);  // needs p[...]
  EXPECT_TRUE(sim::ur5::ParseScriptUnit({"movej([0,0,0,0,0,0], t=2)"}).error);
  EXPECT_TRUE(sim::ur5::ParseScriptUnit({"movej([0,0,0,0,0,x])"}).error);
  // Positional a and v, one-liner outside a program.
  const auto one_liner = sim::ur5::ParseScriptUnit({"movej([1,2,3,4,5,6], 0.5, 0.25)"});
  ASSERT_FALSE(one_liner.error);
  EXPECT_DOUBLE_EQ(one_liner.statements[0].acceleration, 0.5);
  EXPECT_DOUBLE_EQ(one_liner.statements[0].velocity, 0.25);
}

TEST(Ur5Script, AssemblerWaitsForColumnZeroEnd) {
  sim::ur5::ScriptAssembler assembler;
  assembler.Append("def a():\n  movej([0,0,0,0,0,0])\n");
  EXPECT_FALSE(assembler.Next());
  assembler.Append("end\nstopj(1.0)\n");
  const auto block = assembler.Next();
  ASSERT_TRUE(block);
  EXPECT_EQ(block->size(), 3u);
  const auto line = assembler.Next();
  ASSERT_TRUE(line);
  EXPECT_EQ(line->front(), "stopj(1.0)");
  EXPECT_FALSE(assembler.Next());
}

TEST(Ur5Arm, MoveJArrivesTogetherWithinTheTrapezoidTime) {
  const auto dh = kinematics::NominalUr5();
  JointVector start;
  start << 0, -1.5, 1.5, -1.5, -1.5, 0;
  JointVector target = start;
  target[0] += 1.0;
  target[2] -= 0.5;
  sim::ur5::Ur5Arm arm(dh, start);
  ASSERT_EQ(arm.StartMoveJ(target, 2.0, 1.0), "");
  double t = 0;
  double halfway_ratio = 0;
  while (arm.moving() && t < 10) {
    arm.Step(0.008);
    t += 0.008;
    if (std::abs(t - 0.75) < 0.004) {
      halfway_ratio = (arm.q()[2] - start[2]) / (arm.q()[0] - start[0]);
    }
  }
  EXPECT_NEAR(t, 1.5, 0.01);  // 1 rad at v 1, a 2: 0.5 s ramps + 0.5 s cruise
  EXPECT_NEAR((arm.q() - target).norm(), 0, 1e-12);
  EXPECT_NEAR(halfway_ratio, -0.5, 1e-9);  // straight line in joint space
  EXPECT_NE(arm.StartMoveJ(JointVector::Constant(7.0), 1, 1), "");
}

TEST(Ur5Arm, MoveLFollowsAStraightToolLineOnTheTrueArm) {
  const auto cell = sim::PerturbedCell(3);
  JointVector start;
  start << 0.2, -1.4, 1.6, -1.8, -1.5, 0.3;
  sim::ur5::Ur5Arm arm(cell.dh, start);
  const Eigen::Isometry3d from = kinematics::ForwardKinematics(cell.dh, start);
  Eigen::Isometry3d to = from;
  to.translation() += Eigen::Vector3d(0.05, -0.08, 0.04);
  ASSERT_EQ(arm.StartMoveL(to, 1.0, 0.1), "");
  double worst_off_line = 0;
  const Eigen::Vector3d direction = (to.translation() - from.translation()).normalized();
  for (int i = 0; i < 2000 && arm.moving(); ++i) {
    ASSERT_EQ(arm.Step(0.008), "");
    const Eigen::Vector3d p = kinematics::ForwardKinematics(cell.dh, arm.q()).translation();
    const Eigen::Vector3d offset = p - from.translation();
    worst_off_line = std::max(worst_off_line, (offset - offset.dot(direction) * direction).norm());
  }
  EXPECT_FALSE(arm.moving());
  const Eigen::Isometry3d reached = kinematics::ForwardKinematics(cell.dh, arm.q());
  EXPECT_LT((reached.translation() - to.translation()).norm(), 1e-8);
  EXPECT_LT(worst_off_line, 1e-8);
  Eigen::Isometry3d far = from;
  far.translation() = Eigen::Vector3d(3, 0, 0);
  EXPECT_NE(arm.StartMoveL(far, 1, 0.1), "");
}

TEST(Ur5Arm, BrakeStopsShortOfTheTarget) {
  const auto dh = kinematics::NominalUr5();
  sim::ur5::Ur5Arm arm(dh, JointVector::Zero());
  JointVector target = JointVector::Zero();
  target[0] = 2.0;
  ASSERT_EQ(arm.StartMoveJ(target, 1.0, 1.0), "");
  for (int i = 0; i < 100; ++i) arm.Step(0.008);  // 0.8 s: still accelerating
  const double speed = arm.qd()[0];
  arm.Brake(4.0);
  for (int i = 0; i < 200 && arm.moving(); ++i) arm.Step(0.008);
  EXPECT_FALSE(arm.moving());
  EXPECT_LT(arm.q()[0], 1.0);
  EXPECT_GT(speed, 0.7);
}

TEST(PrimaryProtocol, RuntimeExceptionRoundTripsThroughTheFramer) {
  robot::primary::RobotMessage message;
  message.timestamp = 42;
  message.message_type = robot::primary::kRuntimeException;
  message.line = 3;
  message.column = 5;
  message.text = "unsupported function";
  const auto bytes = robot::primary::EncodeRobotMessage(message);
  EXPECT_EQ(bytes[3], bytes.size());  // int32 size, big-endian, includes the header
  EXPECT_EQ(bytes[4], robot::primary::kRobotMessageType);
  robot::primary::PackageFramer framer;
  framer.Append(bytes.data(), 7);
  EXPECT_FALSE(framer.Next());
  framer.Append(bytes.data() + 7, bytes.size() - 7);
  const auto package = framer.Next();
  ASSERT_TRUE(package);
  EXPECT_EQ(robot::primary::DecodeRobotMessage(package->body), message);
}

TEST(PrimaryProtocol, VersionAndKinematicsInfoRoundTrip) {
  const robot::primary::VersionMessage version{"URControl", 3, 15, 7, 106331, "23-11-2026"};
  const auto version_bytes = robot::primary::EncodeVersionMessage(version, 9);
  robot::primary::PackageFramer framer;
  framer.Append(version_bytes.data(), version_bytes.size());
  const auto message = framer.Next();
  ASSERT_TRUE(message);
  EXPECT_FALSE(robot::primary::DecodeRobotMessage(message->body));  // not text or exception
  EXPECT_EQ(robot::primary::DecodeVersionMessage(message->body), version);

  robot::primary::KinematicsInfo info;
  info.a = {0, -0.425, -0.39225, 0, 0, 0};
  info.d = {0.089159, 0, 0, 0.10915, 0.09465, 0.0823};
  info.checksum[2] = 77;
  info.calibration_status = 1;
  const auto state = robot::primary::EncodeKinematicsState(info);
  // 5 header + 5 sub-header + 6*4 checksums + 24*8 doubles + 4 status.
  EXPECT_EQ(state.size(), 5u + 5 + 24 + 192 + 4);
  // An unknown sub-package first must be skipped by its size.
  std::vector<uint8_t> body(7 + state.size() - 5);
  const std::array<uint8_t, 7> unknown = {0, 0, 0, 7, 99, 0xAA, 0xBB};
  std::copy(unknown.begin(), unknown.end(), body.begin());
  std::copy(state.begin() + 5, state.end(), body.begin() + 7);
  EXPECT_EQ(robot::primary::FindKinematicsInfo(body), info);
  body[3] = 200;  // a size running past the package
  EXPECT_THROW(robot::primary::FindKinematicsInfo(body), std::runtime_error);
}

TEST(Dashboard, ReplyValueParsesAndRejects) {
  EXPECT_EQ(robot::ReplyValue("Robotmode: RUNNING", "Robotmode"), "RUNNING");
  EXPECT_THROW(robot::ReplyValue("could not understand: 'x'", "Robotmode"), std::runtime_error);
  EXPECT_EQ(robot::ParseRobotMode("POWER_OFF"), robot::RobotMode::kPowerOff);
  EXPECT_EQ(robot::ParseSafetyMode("PROTECTIVE_STOP"), robot::SafetyMode::kProtectiveStop);
  EXPECT_FALSE(robot::ParseRobotMode("SLEEPING"));
}

TEST(MotionMonitor, ReachedOnlyWhenCloseAndStillAndStopsReported) {
  robot::RobotState state;
  state.robot_mode = robot::RobotMode::kRunning;
  state.actual_q = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  auto monitor = robot::MotionMonitor::ForJoints({0.1, 0.2, 0.3, 0.4, 0.5, 0.6005});
  EXPECT_EQ(monitor.Update(state), robot::MotionStatus::kReached);
  state.actual_qd[2] = 0.01;
  EXPECT_EQ(monitor.Update(state), robot::MotionStatus::kMoving);
  state.actual_qd[2] = 0;
  state.actual_q[1] = 0.21;
  EXPECT_EQ(monitor.Update(state), robot::MotionStatus::kMoving);
  state.safety_mode = robot::SafetyMode::kProtectiveStop;
  EXPECT_EQ(monitor.Update(state), robot::MotionStatus::kSafetyStop);
  EXPECT_NE(monitor.detail().find("PROTECTIVE_STOP"), std::string::npos);

  robot::RobotState at_pose;
  at_pose.robot_mode = robot::RobotMode::kRunning;
  at_pose.actual_tcp_pose = {0.3, -0.1, 0.4, 0, std::numbers::pi - 1e-4, 0};
  // The same orientation written with the flipped rotation vector near pi.
  auto pose_monitor =
      robot::MotionMonitor::ForPose({0.3, -0.1, 0.4, 0, -(std::numbers::pi - 1e-4), 0});
  EXPECT_EQ(pose_monitor.Update(at_pose), robot::MotionStatus::kReached);
  at_pose.actual_tcp_pose[0] += 0.01;
  EXPECT_EQ(pose_monitor.Update(at_pose), robot::MotionStatus::kMoving);
}

}  // namespace
}  // namespace avc
