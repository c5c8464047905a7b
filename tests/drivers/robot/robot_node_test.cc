// avc-robot's node on an in-process bus (memq://) driving the UR5 emulator: commands become
// acks and motions, robot_state_t follows the controller, the envelope refuses with a reason.

#include "drivers/robot/robot_node.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/kinematics/forward_kinematics.h"
#include "core/kinematics/pose_difference.h"
#include "core/kinematics/row_major_pose.h"
#include "tests/drivers/robot/robot_node_harness.h"

namespace avc::robot::testing {
namespace {

using kinematics::JointVector;

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
  EXPECT_NE(pose_refused.reason.find("not a rigid transform"), std::string::npos)
      << pose_refused.reason;
  EXPECT_EQ(h_.Run(RobotNodeHarness::Simple("", Command::KIND_STOP)).status, Ack::STATUS_REFUSED);
  EXPECT_EQ(h_.Run(RobotNodeHarness::Simple("odd", 42)).status, Ack::STATUS_REFUSED);
  EXPECT_EQ(h_.emulator->Snapshot().scripts_run, 0);
}

// A plant keep-out command: `radii` per 2 cm slab from z0, about a vertical axis through
// `axis` (base frame).
Command PlantKeepOut(const std::string& id, const Eigen::Vector3d& axis, double z0,
                     std::vector<double> radii) {
  Command command = RobotNodeHarness::Simple(id, Command::KIND_SET_PLANT_KEEP_OUT);
  Eigen::Isometry3d T_base_table = Eigen::Isometry3d::Identity();
  T_base_table.translation() = axis;
  kinematics::RowMajorFromIsometry(T_base_table, command.T_base_table);
  command.keep_out_z0 = z0;
  command.keep_out_slab = 0.02;
  command.keep_out_slabs = static_cast<int16_t>(radii.size());
  command.keep_out_radius = std::move(radii);
  return command;
}

TEST_F(RobotNodeTest, ThePlantKeepOutRefusesMovesIntoItUntilCleared) {
  h_.PowerUp();
  // A plant whose swept space reaches the flange's position at kTarget: the move there must not
  // start. The axis is 5 cm beside the flange; the slabs span 10 cm around its height.
  const Eigen::Vector3d flange =
      kinematics::ForwardKinematics(h_.cell.dh, Eigen::Map<const JointVector>(kTarget.data()))
          .translation();
  const Eigen::Vector3d axis = flange - Eigen::Vector3d(0.05, 0, 0) - Eigen::Vector3d::UnitZ();
  const std::vector<double> wide(5, 0.08);
  const Ack set = h_.Run(PlantKeepOut("keep-out", axis, 1 - 0.05, wide));
  ASSERT_EQ(set.status, Ack::STATUS_DONE) << set.reason;
  EXPECT_EQ(set.reason, "plant keep-out set");
  const Ack refused = h_.Run(RobotNodeHarness::MoveJoints("into-plant", kTarget));
  EXPECT_EQ(refused.status, Ack::STATUS_REFUSED);
  EXPECT_NE(refused.reason.find("plant's keep-out"), std::string::npos) << refused.reason;
  EXPECT_EQ(h_.emulator->Snapshot().scripts_run, 0);

  // Unusable values are refused and leave the keep-out in place; so does an unsigned clear.
  EXPECT_EQ(h_.Run(PlantKeepOut("negative", axis, 0, {0.1, -0.1})).status, Ack::STATUS_REFUSED);
  EXPECT_EQ(h_.Run(PlantKeepOut("nan", axis, std::nan(""), {0.1})).status, Ack::STATUS_REFUSED);
  EXPECT_EQ(h_.Run(PlantKeepOut("too-many", axis, 0, std::vector<double>(2000, 0.1))).status,
            Ack::STATUS_REFUSED);
  h_.SendAsIs(PlantKeepOut("unsigned-clear", axis, 0, {}));
  ASSERT_TRUE(h_.RunUntil([&] { return h_.FinalAck("unsigned-clear").has_value(); }));
  EXPECT_NE(h_.FinalAck("unsigned-clear")->reason.find("authentication"), std::string::npos);
  EXPECT_EQ(h_.Run(RobotNodeHarness::MoveJoints("still-kept-out", kTarget)).status,
            Ack::STATUS_REFUSED);

  // A narrow plant (2 cm) leaves the flange 5 cm away free; no slabs clears it altogether.
  const Ack narrow = h_.Run(PlantKeepOut("narrow", axis, 1 - 0.05, std::vector<double>(5, 0.02)));
  ASSERT_EQ(narrow.status, Ack::STATUS_DONE) << narrow.reason;
  const Ack beside = h_.Run(RobotNodeHarness::MoveJoints("beside-plant", kTarget));
  EXPECT_EQ(beside.status, Ack::STATUS_DONE) << beside.reason;
  const Ack cleared = h_.Run(PlantKeepOut("clear", axis, 0, {}));
  ASSERT_EQ(cleared.status, Ack::STATUS_DONE) << cleared.reason;
  EXPECT_EQ(cleared.reason, "plant keep-out cleared");
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
