// avc-robot's node on an in-process bus (memq://) driving the UR5 emulator: commands become
// acks and motions, robot_state_t follows the controller, the envelope refuses with a reason.

#include "drivers/robot/robot_node.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/kinematics/forward_kinematics.h"
#include "core/kinematics/pose_difference.h"
#include "core/kinematics/row_major_pose.h"
#include "tests/drivers/robot/robot_node_harness.h"

namespace avc::robot::testing {
namespace {

class RobotNodeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    h_.StartEmulator();
    h_.StartNode();
    ASSERT_TRUE(h_.WaitHealth(avc::heartbeat_t::STATE_READY)) << h_.health->detail;
  }

  RobotNodeHarness h_;
};

TEST_F(RobotNodeTest, MoveJointsIsAcceptedThenDoneAndStateFollows) {
  ASSERT_TRUE(h_.node->controller_kinematics());  // read at connect
  EXPECT_EQ(h_.node->controller_kinematics()->d[3], h_.cell.dh.d[3]);
  h_.PowerUp();
  h_.Send(RobotNodeHarness::MoveJoints("move-1", kTarget));
  ASSERT_TRUE(h_.WaitHealth(avc::heartbeat_t::STATE_BUSY));
  EXPECT_EQ(h_.health->detail, "moving: move-1");
  ASSERT_TRUE(h_.RunUntil([&] { return h_.FinalAck("move-1").has_value(); }));
  const Ack done = *h_.FinalAck("move-1");
  ASSERT_EQ(done.status, Ack::STATUS_DONE) << done.reason;
  ASSERT_EQ(h_.AcksFor("move-1").front().status, Ack::STATUS_ACCEPTED);
  EXPECT_EQ(done.service, "avc-robot");
  ASSERT_TRUE(h_.WaitHealth(avc::heartbeat_t::STATE_READY));
  h_.states.clear();
  ASSERT_TRUE(h_.RunUntil([&] { return !h_.states.empty(); }));
  const auto& state = h_.states.back();
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(state.q[i], kTarget[i], 1e-3);
  EXPECT_FALSE(state.moving);
  EXPECT_EQ(state.robot_mode, static_cast<int8_t>(RobotMode::kRunning));
  EXPECT_EQ(state.active_request_id, "");
  const auto q = Eigen::Map<const JointVector>(state.q);
  const auto difference =
      kinematics::ComparePoses(kinematics::IsometryFromRowMajor(state.T_base_flange),
                               kinematics::ForwardKinematics(h_.cell.dh, q));
  EXPECT_LT(difference.translation_m, 1e-9);
  // A repeated request id is answered again and not executed again.
  const int scripts = h_.emulator->Snapshot().scripts_run;
  const size_t before = h_.AcksFor("move-1").size();
  h_.Send(RobotNodeHarness::MoveJoints("move-1", kTarget));
  ASSERT_TRUE(h_.RunUntil([&] { return h_.AcksFor("move-1").size() == before + 1; }));
  EXPECT_EQ(h_.AcksFor("move-1").back().status, Ack::STATUS_DONE);
  EXPECT_EQ(h_.emulator->Snapshot().scripts_run, scripts);
}

TEST_F(RobotNodeTest, OutsideTheEnvelopeOrNotRunningIsRefusedWithAReason) {
  ASSERT_TRUE(h_.RunUntil([&] { return h_.node->last_state().has_value(); }));
  const Ack off = h_.Run(RobotNodeHarness::MoveJoints("too-early", kTarget));
  EXPECT_EQ(off.status, Ack::STATUS_REFUSED);
  EXPECT_NE(off.reason.find("POWER_OFF"), std::string::npos) << off.reason;
  h_.PowerUp();
  auto beyond = kTarget;
  beyond[0] = 1.5;  // joint 1 limit is 1.2 in this cell's envelope
  const Ack refused = h_.Run(RobotNodeHarness::MoveJoints("beyond", beyond));
  EXPECT_EQ(refused.status, Ack::STATUS_REFUSED);
  EXPECT_NE(refused.reason.find("joint 1"), std::string::npos) << refused.reason;
  EXPECT_NE(h_.Run(RobotNodeHarness::MoveJoints("fast", kTarget, 3.0)).reason.find("speed"),
            std::string::npos);
  auto not_a_number = kTarget;
  not_a_number[4] = std::nan("");
  const Ack nan_refused = h_.Run(RobotNodeHarness::MoveJoints("nan", not_a_number));
  EXPECT_EQ(nan_refused.status, Ack::STATUS_REFUSED);
  EXPECT_NE(nan_refused.reason.find("joint 5"), std::string::npos) << nan_refused.reason;
  Command linear = RobotNodeHarness::Simple("bad-pose", Command::KIND_MOVE_LINEAR);
  std::fill(std::begin(linear.T_base_flange), std::end(linear.T_base_flange), 0.0);
  linear.T_base_flange[15] = 1;  // zero rotation block: not a rigid transform
  const Ack pose_refused = h_.Run(linear);
  EXPECT_EQ(pose_refused.status, Ack::STATUS_REFUSED);
  EXPECT_NE(pose_refused.reason.find("orthonormal"), std::string::npos) << pose_refused.reason;
  EXPECT_EQ(h_.Run(RobotNodeHarness::Simple("", Command::KIND_STOP)).status, Ack::STATUS_REFUSED);
  EXPECT_EQ(h_.Run(RobotNodeHarness::Simple("odd", 42)).status, Ack::STATUS_REFUSED);
  EXPECT_EQ(h_.emulator->Snapshot().scripts_run, 0);
}

TEST_F(RobotNodeTest, ProtectiveStopFailsTheMotionAndUnlockLetsTheNextOneFinish) {
  h_.PowerUp();
  h_.emulator->ArmProtectiveStopAt(0.3);
  const Ack failed = h_.Run(RobotNodeHarness::MoveJoints("interrupted", kTarget));
  ASSERT_EQ(failed.status, Ack::STATUS_FAILED);
  EXPECT_NE(failed.reason.find("PROTECTIVE_STOP"), std::string::npos) << failed.reason;
  h_.states.clear();
  ASSERT_TRUE(h_.RunUntil([&] { return !h_.states.empty(); }));
  EXPECT_TRUE(h_.states.back().protective_stop);
  EXPECT_EQ(h_.Run(RobotNodeHarness::MoveJoints("while-stopped", kTarget)).status,
            Ack::STATUS_REFUSED);
  ASSERT_EQ(h_.Run(RobotNodeHarness::Simple("unlock", Command::KIND_UNLOCK_PROTECTIVE_STOP)).status,
            Ack::STATUS_DONE);
  ASSERT_TRUE(
      h_.RunUntil([&] { return h_.node->last_state()->safety_mode == SafetyMode::kNormal; }));
  const Ack resumed = h_.Run(RobotNodeHarness::MoveJoints("resumed", kTarget));
  EXPECT_EQ(resumed.status, Ack::STATUS_DONE) << resumed.reason;
}

TEST_F(RobotNodeTest, ShutdownStopsTheArmAndFailsTheMotion) {
  h_.PowerUp();
  h_.Send(RobotNodeHarness::MoveJoints("long", kTarget, 0.2));
  ASSERT_TRUE(h_.RunUntil([&] { return h_.emulator->Snapshot().program_running; }));
  h_.node->Shutdown();
  ASSERT_TRUE(h_.RunUntil([&] { return h_.FinalAck("long").has_value(); }));
  const auto final_ack = h_.FinalAck("long");
  EXPECT_EQ(final_ack->status, Ack::STATUS_FAILED);
  EXPECT_EQ(final_ack->reason, "avc-robot stopping");
  ASSERT_TRUE(
      h_.RunUntil([&] { return !h_.emulator->Snapshot().program_running; }, milliseconds(2000)));
  EXPECT_GT(std::abs(h_.emulator->Snapshot().true_q[0] - kTarget[0]), 0.05);
}

}  // namespace
}  // namespace avc::robot::testing
