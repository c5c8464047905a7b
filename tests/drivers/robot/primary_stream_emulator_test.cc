// The emulator's primary (30001) and secondary (30002) interfaces as the driver's ScriptClient
// decodes them: VERSION on connect, the 10 Hz ROBOT_STATE stream (ROBOT_MODE_DATA, JOINT_DATA,
// CARTESIAN_INFO, KINEMATICS_INFO) matching the emulator's truth, and URScript on either port.

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <memory>

#include "core/kinematics/forward_kinematics.h"
#include "core/kinematics/pose_difference.h"
#include "drivers/robot/dashboard_client.h"
#include "drivers/robot/motion_monitor.h"
#include "drivers/robot/protocol/primary_robot_state.h"
#include "drivers/robot/script_client.h"
#include "drivers/robot/urscript.h"
#include "sim/cell/perturbation.h"
#include "sim/emulators/clock/emulator_clock.h"
#include "sim/emulators/ur5/ur5_emulator.h"
#include "tests/drivers/robot/emulator_test_settings.h"

namespace avc {
namespace {

using net::Milliseconds;
namespace primary = robot::primary;

class PrimaryStreamTest : public ::testing::Test {
 protected:
  void SetUp() override {
    options_.cell = sim::PerturbedCell(31);
    options_.rtde_port = options_.primary_port = options_.secondary_port = 0;
    options_.dashboard_port = 0;
    options_.encoder_noise_rad = testing::kEncoderNoise;
    emulator_ = std::make_unique<sim::ur5::Ur5Emulator>(
        options_, std::make_shared<sim::ScaledEmulatorClock>(10));
  }

  // Polls `client` until `done` or 3 s.
  static bool PollUntil(robot::ScriptClient& client, const std::function<bool()>& done) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(3);
    while (!done()) {
      if (std::chrono::steady_clock::now() > end) return false;
      client.Poll(net::Milliseconds(5));
    }
    return true;
  }

  // Waits for a ROBOT_STATE newer than the ones seen so far.
  static bool NextState(robot::ScriptClient& client) {
    const int seen = client.robot_states_received();
    return PollUntil(client, [&] { return client.robot_states_received() > seen; });
  }

  void ExpectJointsMatchTruth(const primary::JointData& joints) {
    const auto truth = emulator_->Snapshot().true_q;
    for (int i = 0; i < 6; ++i) {
      EXPECT_NEAR(joints.q_actual[i], truth[i], testing::kEncoderNoise * 1.01) << "joint " << i + 1;
    }
  }

  sim::ur5::Ur5EmulatorOptions options_;
  std::unique_ptr<sim::ur5::Ur5Emulator> emulator_;
};

TEST_F(PrimaryStreamTest, BothPortsAnnounceVersionAndStreamTheStateOfAPoweredOffArm) {
  for (const uint16_t port : {emulator_->primary_port(), emulator_->secondary_port()}) {
    robot::ScriptClient client(testing::kEmulatorHost, port);
    ASSERT_TRUE(PollUntil(client, [&] { return client.joint_data() && client.version(); }));
    EXPECT_EQ(client.version()->project_name, "URControl");
    const auto& mode = *client.robot_mode_data();
    EXPECT_EQ(mode.robot_mode, static_cast<int8_t>(robot::RobotMode::kPowerOff));
    EXPECT_FALSE(mode.power_on);
    EXPECT_FALSE(mode.program_running);
    EXPECT_FALSE(mode.protective_stopped);
    for (uint8_t joint_mode : client.joint_data()->mode) {
      EXPECT_EQ(joint_mode, primary::kJointModePowerOff);
    }
    ExpectJointsMatchTruth(*client.joint_data());
    ASSERT_TRUE(client.kinematics());
    EXPECT_EQ(client.kinematics()->d[0], options_.cell.dh.d[0]);
    EXPECT_GE(emulator_->Snapshot().script_clients, 1);
  }
}

TEST_F(PrimaryStreamTest, StateComesAtTenHertzOfControllerTime) {
  robot::ScriptClient client(testing::kEmulatorHost, emulator_->secondary_port());
  ASSERT_TRUE(PollUntil(client, [&] { return client.robot_mode_data().has_value(); }));
  const int first_count = client.robot_states_received();
  const uint64_t first_us = client.robot_mode_data()->timestamp_us;
  ASSERT_TRUE(
      PollUntil(client, [&] { return client.robot_states_received() >= first_count + 10; }));
  const double elapsed_s = (client.robot_mode_data()->timestamp_us - first_us) * 1e-6;
  const int states = client.robot_states_received() - first_count;
  EXPECT_NEAR(elapsed_s / states, 0.1, 0.009);  // within one 8 ms control period
}

TEST_F(PrimaryStreamTest, MoveSentOnThePrimaryPortShowsInModeJointAndCartesianData) {
  robot::DashboardClient dashboard(testing::kEmulatorHost, emulator_->dashboard_port());
  dashboard.PowerOn();
  dashboard.BrakeRelease();
  robot::ScriptClient client(testing::kEmulatorHost, emulator_->primary_port());
  ASSERT_TRUE(PollUntil(client, [&] {
    return client.robot_mode_data() &&
           client.robot_mode_data()->robot_mode == static_cast<int8_t>(robot::RobotMode::kRunning);
  }));
  EXPECT_TRUE(client.robot_mode_data()->power_on);
  EXPECT_EQ(client.joint_data()->mode[3], primary::kJointModeRunning);

  const robot::Joints target = {0.4, -1.4, 1.4, -1.6, -1.4, 0.3};
  client.Send(robot::MoveJProgram(target, 1.4, 1.0));
  ASSERT_TRUE(PollUntil(client, [&] { return client.robot_mode_data()->program_running; }));
  ASSERT_TRUE(PollUntil(client, [&] { return !client.robot_mode_data()->program_running; }));
  ASSERT_TRUE(NextState(client));
  const auto& joints = *client.joint_data();
  ExpectJointsMatchTruth(joints);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(joints.q_actual[i], target[i], 1e-4);
    EXPECT_NEAR(joints.q_target[i], target[i], 1e-9);  // the trajectory set-point, arrived
  }

  // CARTESIAN_INFO is the true arm's forward kinematics of the reported joints.
  const kinematics::JointVector reported =
      Eigen::Map<const kinematics::JointVector>(joints.q_actual.data());
  const auto reported_pose = robot::PoseFromVector(client.cartesian_info()->pose);
  EXPECT_LT(kinematics::ComparePoses(reported_pose,
                                     kinematics::ForwardKinematics(options_.cell.dh, reported))
                .translation_m,
            1e-9);
  // The true flange pose is FK of the true joints, a few micrometres from the reported one.
  const auto snapshot = emulator_->Snapshot();
  const auto truth = emulator_->TrueBaseFromFlange();
  EXPECT_TRUE(truth.isApprox(kinematics::ForwardKinematics(options_.cell.dh, snapshot.true_q)));
  EXPECT_TRUE(truth.isApprox(snapshot.true_T_base_flange));
  EXPECT_LT(kinematics::ComparePoses(reported_pose, truth).translation_m, 1e-4);
  EXPECT_GT((truth.translation() -
             kinematics::ForwardKinematics(kinematics::NominalUr5(), snapshot.true_q).translation())
                .norm(),
            1e-4);  // the perturbed arm, not the nominal one
}

TEST(PrimaryRobotState, EncodedStateDecodesBackAndSkipsUnknownSubPackages) {
  primary::RobotStateMessage state;
  state.mode = primary::RobotModeData{};
  state.mode->timestamp_us = 123456;
  state.mode->robot_mode = 7;
  state.mode->program_running = true;
  state.joints = primary::JointData{};
  state.joints->q_actual = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  state.joints->voltage[2] = 48.0f;
  state.joints->mode.fill(primary::kJointModeRunning);
  state.cartesian = primary::CartesianInfo{{1, 2, 3, 0.1, 0.2, 0.3}, {}};
  const auto bytes = primary::EncodeRobotState(state);
  primary::PackageFramer framer;
  framer.Append(bytes.data(), bytes.size());
  auto package = framer.Next();
  ASSERT_TRUE(package);
  EXPECT_EQ(package->type, primary::kRobotStateType);
  // ROBOT_MODE_DATA: 5 header + 8 + 7 + 1 + 1 + 24 + 1 reserved.
  EXPECT_EQ(package->body[3], 47);
  // An unknown sub-package in between is skipped by its size.
  const std::vector<uint8_t> unknown = {0, 0, 0, 8, 3, 1, 2, 3};
  package->body.insert(package->body.begin() + 47, unknown.begin(), unknown.end());
  const auto decoded = primary::DecodeRobotState(package->body);
  EXPECT_EQ(decoded.mode, state.mode);
  EXPECT_EQ(decoded.joints, state.joints);
  EXPECT_EQ(decoded.cartesian, state.cartesian);
  EXPECT_FALSE(decoded.kinematics);
  package->body.resize(60);  // JOINT_DATA cut short
  EXPECT_THROW(primary::DecodeRobotState(package->body), std::runtime_error);
}

}  // namespace
}  // namespace avc
