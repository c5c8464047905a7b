// The driver's RTDE, dashboard and script clients against the UR5 emulator on ephemeral ports,
// with simulated time running 10x faster than real time.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/kinematics/forward_kinematics.h"
#include "core/kinematics/pose_difference.h"
#include "drivers/robot/dashboard_client.h"
#include "drivers/robot/motion_wait.h"
#include "drivers/robot/rtde_client.h"
#include "drivers/robot/script_client.h"
#include "drivers/robot/urscript.h"
#include "sim/cell/perturbation.h"
#include "sim/emulators/ur5/ur5_emulator.h"
#include "tests/drivers/robot/emulator_test_settings.h"

namespace avc {
namespace {

using kinematics::JointVector;
using net::Milliseconds;
using robot::MotionStatus;
using robot::RobotMode;
using robot::SafetyMode;

sim::ur5::Ur5EmulatorOptions TestOptions() {
  sim::ur5::Ur5EmulatorOptions options;
  options.cell = sim::PerturbedCell(11);
  options.rtde_port = 0;
  options.primary_port = 0;
  options.secondary_port = 0;
  options.dashboard_port = 0;
  options.encoder_noise_rad = testing::kEncoderNoise;
  options.seed = 5;
  return options;
}

// Simulated time runs 10x faster than real time.
std::unique_ptr<sim::ur5::Ur5Emulator> StartEmulator(const sim::ur5::Ur5EmulatorOptions& options) {
  return std::make_unique<sim::ur5::Ur5Emulator>(options,
                                                 std::make_shared<sim::ScaledEmulatorClock>(10));
}

JointVector ToJoints(const std::array<double, 6>& q) {
  return Eigen::Map<const JointVector>(q.data());
}

std::string ErrorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::exception& error) {
    return error.what();
  }
  return {};
}

class RobotClientEmulatorTest : public ::testing::Test {
 protected:
  void SetUp() override { emulator_ = StartEmulator(TestOptions()); }

  robot::RtdeClient StreamingClient() {
    robot::RtdeClient client(testing::kEmulatorHost, emulator_->rtde_port());
    client.Handshake();
    return client;
  }

  // Dashboard sequence that makes the robot ready: POWER_OFF -> IDLE -> RUNNING.
  void PowerUp() {
    robot::DashboardClient dashboard(testing::kEmulatorHost, emulator_->dashboard_port());
    dashboard.PowerOn();
    dashboard.BrakeRelease();
  }

  std::unique_ptr<sim::ur5::Ur5Emulator> emulator_;
};

TEST_F(RobotClientEmulatorTest, NegotiatesVersion2AndReadsTheCb3Version) {
  robot::RtdeClient client(testing::kEmulatorHost, emulator_->rtde_port());
  EXPECT_EQ(client.NegotiateProtocol(), 2);
  const auto version = client.GetControllerVersion();
  EXPECT_EQ(version.major, 3u);
  EXPECT_EQ(version.minor, 15u);
  EXPECT_EQ(client.MaxFrequency(), 125.0);
}

TEST(RobotClientEmulator, FallsBackToVersion1OnAnOldController) {
  auto options = TestOptions();
  options.max_protocol_version = 1;
  auto emulator = StartEmulator(options);
  robot::RtdeClient client(testing::kEmulatorHost, emulator->rtde_port());
  client.Handshake();
  EXPECT_EQ(client.protocol_version(), 1);
  const auto sample = client.Receive(net::Milliseconds(2000));
  ASSERT_TRUE(sample);
  EXPECT_EQ(sample->state.robot_mode, RobotMode::kPowerOff);
}

TEST(RobotClientEmulator, SteppedClockGivesExactControllerTimestamps) {
  // Every clock read advances 1 ms, so the arm runs as fast as the loop turns and the data
  // package timestamps sit exactly on the 8 ms control grid.
  auto clock = std::make_shared<sim::SteppedEmulatorClock>(0.001);
  sim::ur5::Ur5Emulator emulator(TestOptions(), clock);
  robot::RtdeClient client(testing::kEmulatorHost, emulator.rtde_port());
  client.Handshake();
  auto previous = client.Receive(net::Milliseconds(2000));
  ASSERT_TRUE(previous);
  for (int i = 0; i < 20; ++i) {
    const auto sample = client.Receive(net::Milliseconds(2000));
    ASSERT_TRUE(sample);
    EXPECT_NEAR(sample->state.timestamp - previous->state.timestamp, 0.008, 1e-9);
    previous = sample;
  }
  EXPECT_LE(previous->state.timestamp, clock->NowSeconds());
}

TEST_F(RobotClientEmulatorTest, UnknownOutputVariableIsReportedByName) {
  robot::RtdeClient client(testing::kEmulatorHost, emulator_->rtde_port());
  client.NegotiateProtocol();
  client.GetControllerVersion();
  const std::string error = ErrorOf([&] {
    client.SetupOutputs(125, {"actual_q", "actual_warp_factor"});
  });
  EXPECT_NE(error.find("actual_warp_factor"), std::string::npos) << error;
  EXPECT_EQ(error.find("actual_q,"), std::string::npos) << error;  // only the unknown one
  EXPECT_NE(error.find(fmt::format("127.0.0.1:{}", emulator_->rtde_port())), std::string::npos)
      << error;
  EXPECT_NE(error.find("setup outputs"), std::string::npos) << error;
  // Frequencies above the CB3 rate are refused before anything is sent.
  EXPECT_NE(ErrorOf([&] { client.SetupOutputs(500, {"actual_q"}); }).find("125"),
            std::string::npos);
}

TEST_F(RobotClientEmulatorTest, InputRegisterOwnedByAnotherClientIsInUse) {
  robot::RtdeClient first(testing::kEmulatorHost, emulator_->rtde_port());
  first.NegotiateProtocol();
  const uint8_t recipe = first.SetupInputs({"input_int_register_24", "input_double_register_24"});
  EXPECT_EQ(recipe, 1);
  first.SendInputs(recipe, {int32_t{7}, 2.5});
  robot::RtdeClient second(testing::kEmulatorHost, emulator_->rtde_port());
  second.NegotiateProtocol();
  const std::string error = ErrorOf([&] { second.SetupInputs({"input_int_register_24"}); });
  EXPECT_NE(error.find("in use by another client: input_int_register_24"), std::string::npos)
      << error;
  EXPECT_NE(ErrorOf([&] { second.SetupInputs({"input_int_register_99"}); }).find("unknown"),
            std::string::npos);
  // The written registers read back through an output recipe.
  second.SetupOutputs(125, {"input_int_register_24", "input_double_register_24"});
  second.Start();
  const auto sample = second.Receive(net::Milliseconds(2000));
  ASSERT_TRUE(sample);
  EXPECT_EQ(std::get<int32_t>(sample->package.values[0]), 7);
  EXPECT_EQ(std::get<double>(sample->package.values[1]), 2.5);
}

TEST_F(RobotClientEmulatorTest, StreamsStateAtTheControllerRate) {
  auto client = StreamingClient();
  std::vector<robot::RobotState> states;
  while (states.size() < 50) {
    const auto sample = client.Receive(net::Milliseconds(2000));
    ASSERT_TRUE(sample);
    states.push_back(sample->state);
  }
  for (size_t i = 1; i < states.size(); ++i) {
    EXPECT_NEAR(states[i].timestamp - states[i - 1].timestamp, 1.0 / 125, 1e-9);
  }
  const auto& last = states.back();
  EXPECT_EQ(last.robot_mode, RobotMode::kPowerOff);
  EXPECT_EQ(last.safety_mode, SafetyMode::kNormal);
  EXPECT_EQ(last.safety_status_bits & robot::kSafetyNormal, robot::kSafetyNormal);
  EXPECT_EQ(last.runtime_state, robot::RuntimeState::kStopped);
  const JointVector truth = TestOptions().initial_q;
  EXPECT_LT((ToJoints(last.actual_q) - truth).cwiseAbs().maxCoeff(),
            testing::kEncoderNoise * 1.0001);
  EXPECT_GT((ToJoints(last.actual_q) - truth).cwiseAbs().maxCoeff(), 0);  // noise is on
}

TEST_F(RobotClientEmulatorTest, DashboardPowerOnAndBrakeReleaseSequence) {
  robot::DashboardClient dashboard(testing::kEmulatorHost, emulator_->dashboard_port());
  EXPECT_EQ(dashboard.banner(), robot::kDashboardBanner);
  EXPECT_EQ(dashboard.GetRobotMode(), RobotMode::kPowerOff);
  dashboard.PowerOn();
  EXPECT_EQ(dashboard.GetRobotMode(), RobotMode::kIdle);
  dashboard.BrakeRelease();
  EXPECT_EQ(dashboard.GetRobotMode(), RobotMode::kRunning);
  EXPECT_EQ(dashboard.GetSafetyMode(), SafetyMode::kNormal);
  EXPECT_EQ(dashboard.SafetyStatus(), "NORMAL");
  dashboard.CloseSafetyPopup();
  EXPECT_NE(dashboard.PolyscopeVersion().find("3.15"), std::string::npos);
  EXPECT_NE(ErrorOf([&] { dashboard.UnlockProtectiveStop(); }).find("not protective stopped"),
            std::string::npos);
  EXPECT_EQ(dashboard.Command("fly away"), "could not understand: 'fly away'");
  // RTDE sees the same state.
  auto client = StreamingClient();
  const auto sample = client.ReceiveLatest(net::Milliseconds(2000));
  ASSERT_TRUE(sample);
  EXPECT_EQ(sample->state.robot_mode, RobotMode::kRunning);
  EXPECT_EQ(sample->state.robot_status_bits & robot::kStatusPowerOn, robot::kStatusPowerOn);
}

TEST_F(RobotClientEmulatorTest, MoveJArrivesAndTcpPoseIsTheTrueArmsForwardKinematics) {
  PowerUp();
  auto client = StreamingClient();
  robot::ScriptClient script(testing::kEmulatorHost, emulator_->secondary_port());
  const robot::Joints target = {0.3, -1.2, 1.4, -1.9, -1.4, 0.5};
  script.Send(robot::MoveJProgram(target, 3.0, 1.5));
  auto monitor = robot::MotionMonitor::ForJoints(target);
  const auto outcome = robot::WaitForMotion(client, monitor, net::Milliseconds(5000));
  ASSERT_EQ(outcome.status, MotionStatus::kReached) << outcome.detail;
  const robot::RobotState& state = outcome.last_state;
  const JointVector q = ToJoints(state.actual_q);
  EXPECT_LT((q - ToJoints(target)).cwiseAbs().maxCoeff(), 1.0001 * testing::kEncoderNoise);
  const JointVector truth = emulator_->Snapshot().true_q;
  EXPECT_LT((truth - ToJoints(target)).cwiseAbs().maxCoeff(), 1e-12);

  const auto cell = TestOptions().cell;
  const Eigen::Isometry3d reported = robot::PoseFromVector(state.actual_tcp_pose);
  const auto vs_true =
      kinematics::ComparePoses(reported, kinematics::ForwardKinematics(cell.dh, q));
  EXPECT_LT(vs_true.translation_m, 1e-9);
  EXPECT_LT(vs_true.rotation_rad, 1e-9);
  // Nominal FK is off by millimetres: a driver using it instead of actual_TCP_pose would be wrong.
  const auto vs_nominal = kinematics::ComparePoses(
      reported, kinematics::ForwardKinematics(kinematics::NominalUr5(), q));
  EXPECT_GT(vs_nominal.translation_m, 5e-4);
  EXPECT_TRUE(script.Poll(net::Milliseconds(50)).empty());  // no runtime error
}

TEST_F(RobotClientEmulatorTest, MoveLReachesThePose) {
  PowerUp();
  auto client = StreamingClient();
  const auto start = client.ReceiveLatest(net::Milliseconds(2000));
  ASSERT_TRUE(start);
  Eigen::Isometry3d goal = robot::PoseFromVector(start->state.actual_tcp_pose);
  goal.translation() += Eigen::Vector3d(0.05, 0.03, -0.04);
  const auto goal_vector = robot::VectorFromPose(goal);
  robot::ScriptClient script(testing::kEmulatorHost, emulator_->secondary_port());
  script.Send(robot::MoveLProgram(goal_vector, 1.0, 0.2));
  auto monitor = robot::MotionMonitor::ForPose(goal_vector, {.position_m = 1e-4});
  const auto outcome = robot::WaitForMotion(client, monitor, net::Milliseconds(5000));
  ASSERT_EQ(outcome.status, MotionStatus::kReached) << outcome.detail;
}

TEST_F(RobotClientEmulatorTest, ProtectiveStopMidMoveIsReportedAndRecoverable) {
  robot::DashboardClient dashboard(testing::kEmulatorHost, emulator_->dashboard_port());
  dashboard.PowerOn();
  dashboard.BrakeRelease();
  auto client = StreamingClient();
  robot::ScriptClient script(testing::kEmulatorHost, emulator_->secondary_port());
  const robot::Joints target = {
      1.0, -1.5707963267948966, 1.5707963267948966, -1.5707963267948966, -1.5707963267948966, 0};
  emulator_->ArmProtectiveStopAt(0.4);
  script.Send(robot::MoveJProgram(target, 2.0, 1.0));
  auto monitor = robot::MotionMonitor::ForJoints(target);
  const auto stopped = robot::WaitForMotion(client, monitor, net::Milliseconds(5000));
  ASSERT_EQ(stopped.status, MotionStatus::kSafetyStop) << stopped.detail;
  EXPECT_NE(stopped.detail.find("PROTECTIVE_STOP"), std::string::npos);
  const double stopped_at = stopped.last_state.actual_q[0];
  EXPECT_GT(stopped_at, 0.35);
  EXPECT_LT(stopped_at, 0.5);
  EXPECT_EQ(dashboard.GetSafetyMode(), SafetyMode::kProtectiveStop);
  // Not retried behind our back: the arm stays where it stopped.
  const auto later = client.ReceiveLatest(net::Milliseconds(2000));
  ASSERT_TRUE(later);
  EXPECT_NEAR(later->state.actual_q[0], stopped_at, 3 * testing::kEncoderNoise);
  EXPECT_EQ(later->state.runtime_state, robot::RuntimeState::kStopped);
  // A program sent while stopped is refused with a runtime error.
  script.Send(robot::MoveJProgram(target, 2.0, 1.0));
  const auto refused = script.Poll(net::Milliseconds(2000));
  ASSERT_EQ(refused.size(), 1u);
  EXPECT_NE(refused[0].text.find("PROTECTIVE_STOP"), std::string::npos);

  dashboard.UnlockProtectiveStop();
  EXPECT_EQ(dashboard.GetSafetyMode(), SafetyMode::kNormal);
  client.ReceiveLatest(net::Milliseconds(2000));  // drop states from before the unlock
  script.Send(robot::MoveJProgram(target, 2.0, 1.0));
  auto resumed_monitor = robot::MotionMonitor::ForJoints(target);
  const auto resumed = robot::WaitForMotion(client, resumed_monitor, net::Milliseconds(5000));
  ASSERT_EQ(resumed.status, MotionStatus::kReached) << resumed.detail;
}

TEST_F(RobotClientEmulatorTest, StopJPreemptsTheRunningMoveAndBrakesToRest) {
  PowerUp();
  auto client = StreamingClient();
  robot::ScriptClient script(testing::kEmulatorHost, emulator_->secondary_port());
  const robot::Joints target = {
      2.0, -1.5707963267948966, 1.5707963267948966, -1.5707963267948966, -1.5707963267948966, 0};
  script.Send(robot::MoveJProgram(target, 1.0, 1.0));
  // Wait until the move is well under way (0.5 rad done, cruising at 1 rad/s).
  double q0 = 0;
  for (int i = 0; i < 1000 && q0 < 0.5; ++i) {
    const auto sample = client.Receive(net::Milliseconds(2000));
    ASSERT_TRUE(sample);
    q0 = sample->state.actual_q[0];
  }
  script.Send(robot::StopJProgram(4.0));
  // Braking from <= 1 rad/s at 4 rad/s^2 takes <= 0.125 rad; allow for samples in flight.
  robot::RobotState state;
  for (int i = 0; i < 1000; ++i) {
    const auto sample = client.Receive(net::Milliseconds(2000));
    ASSERT_TRUE(sample);
    state = sample->state;
    if (state.runtime_state == robot::RuntimeState::kStopped) break;
  }
  EXPECT_EQ(state.runtime_state, robot::RuntimeState::kStopped);
  EXPECT_LT(state.actual_q[0], 0.5 + 0.2);
  EXPECT_LT(ToJoints(state.actual_qd).norm(), 1e-9);
  EXPECT_EQ(state.safety_mode, SafetyMode::kNormal);  // a normal stop, not a safety event
}

TEST_F(RobotClientEmulatorTest, UnsupportedScriptAnswersWithARuntimeError) {
  PowerUp();
  robot::ScriptClient script(testing::kEmulatorHost, emulator_->secondary_port());
  script.Send("def bad():\n  movej([0,-1.57,1.57,-1.57,-1.57,0])\n  set_tool_voltage(24)\nend\n");
  const auto messages = script.Poll(net::Milliseconds(2000));
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].message_type, robot::primary::kRuntimeException);
  EXPECT_EQ(messages[0].line, 3);
  EXPECT_NE(messages[0].text.find("set_tool_voltage"), std::string::npos);
  EXPECT_EQ(emulator_->Snapshot().scripts_run, 0);
  EXPECT_FALSE(emulator_->Snapshot().program_running);
}

TEST_F(RobotClientEmulatorTest, SecondaryInterfaceAnnouncesVersionAndTheTrueKinematics) {
  robot::ScriptClient script(testing::kEmulatorHost, emulator_->secondary_port());
  const auto info = script.WaitForKinematics(net::Milliseconds(2000));
  ASSERT_TRUE(info);
  ASSERT_TRUE(script.version());
  EXPECT_EQ(script.version()->project_name, "URControl");
  EXPECT_EQ(script.version()->major, 3);
  const auto truth = TestOptions().cell.dh;
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(info->a[i], truth.a[i]);
    EXPECT_EQ(info->d[i], truth.d[i]);
    EXPECT_EQ(info->alpha[i], truth.alpha[i]);
    EXPECT_EQ(info->theta[i], truth.theta_offset[i]);
  }
  EXPECT_NE(info->d[0], kinematics::NominalUr5().d[0]);  // the perturbed arm, not nominal
}

TEST_F(RobotClientEmulatorTest, SocketDropIsReportedAsADisconnect) {
  auto client = StreamingClient();
  robot::DashboardClient dashboard(testing::kEmulatorHost, emulator_->dashboard_port());
  ASSERT_TRUE(client.Receive(net::Milliseconds(2000)));
  emulator_->DropConnections();
  std::string error;
  try {
    for (int i = 0; i < 1000; ++i) client.Receive(net::Milliseconds(2000));
  } catch (const net::ConnectionError& dropped) {
    error = dropped.what();
  }
  EXPECT_NE(error.find("connection closed by peer"), std::string::npos) << error;
  EXPECT_NE(error.find(fmt::format("127.0.0.1:{}", emulator_->rtde_port())), std::string::npos)
      << error;
  EXPECT_THROW(dashboard.GetRobotMode(), net::ConnectionError);
  // The listeners stay up: a new client connects and streams again.
  auto again = StreamingClient();
  EXPECT_TRUE(again.Receive(net::Milliseconds(2000)));
}

TEST(RobotClientEmulator, ConnectingToAClosedPortNamesIt) {
  uint16_t port = 0;
  {
    auto emulator = StartEmulator(TestOptions());
    port = emulator->rtde_port();
  }
  const std::string error =
      ErrorOf([&] { robot::RtdeClient client(testing::kEmulatorHost, port); });
  EXPECT_NE(error.find(fmt::format("127.0.0.1:{}", port)), std::string::npos) << error;
}

}  // namespace
}  // namespace avc
