// avc-robot's node on an in-process bus (memq://) driving the UR5 emulator: commands become
// acks and motions, robot_state_t follows the controller, the envelope refuses with a reason.

#include "drivers/robot/robot_node.h"

#include <gtest/gtest.h>

#include <avc/ack_t.hpp>
#include <avc/robot_command_t.hpp>
#include <avc/robot_state_t.hpp>
#include <cmath>
#include <functional>
#include <thread>
#include <vector>

#include "core/bus/channels.h"
#include "core/kinematics/forward_kinematics.h"
#include "core/kinematics/pose_difference.h"
#include "sim/cell/perturbation.h"
#include "sim/emulators/ur5/ur5_emulator.h"

namespace avc::robot {
namespace {

using Command = avc::robot_command_t;
using Ack = avc::ack_t;

class RobotNodeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    sim::ur5::Ur5EmulatorOptions options;
    options.cell = sim::PerturbedCell(21);
    options.rtde_port = options.secondary_port = options.dashboard_port = 0;
    options.time_scale = 10;
    emulator_ = std::make_unique<sim::ur5::Ur5Emulator>(options);
    cell_ = options.cell;
    bus_ = std::make_unique<bus::Bus>(bus::InProcessBusOptions("cellr", "robot-test"));
    bus_->Subscribe<Ack>(channels::kAck,
                         [this](const Ack& ack, const bus::RxInfo&) { acks_.push_back(ack); });
    bus_->Subscribe<avc::robot_state_t>(
        channels::kRobotState,
        [this](const avc::robot_state_t& state, const bus::RxInfo&) { states_.push_back(state); });
    RobotNodeConfig config;
    config.rtde_port = emulator_->rtde_port();
    config.secondary_port = emulator_->secondary_port();
    config.dashboard_port = emulator_->dashboard_port();
    config.envelope.joint_min[0] = -1.0;
    config.envelope.joint_max[0] = 1.2;
    config.motion_timeout = std::chrono::milliseconds(10000);
    node_ = std::make_unique<RobotNode>(*bus_, config);
  }

  // Pumps bus and node until `done` or ~5 s of real time.
  bool PumpUntil(const std::function<bool()>& done) {
    for (int i = 0; i < 5000; ++i) {
      bus_->DispatchPending();
      node_->Poll();
      bus_->DispatchPending();
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
  }

  std::vector<Ack> AcksFor(const std::string& id) const {
    std::vector<Ack> found;
    for (const auto& ack : acks_) {
      if (ack.request_id == id) found.push_back(ack);
    }
    return found;
  }

  // Sends a command and waits for its final answer (anything but ACCEPTED).
  Ack Run(Command command) {
    bus_->Publish(channels::kRobotCommand, command);
    const std::string id = command.request_id;
    Ack final_ack;
    final_ack.status = -1;
    PumpUntil([&] {
      for (const auto& ack : AcksFor(id)) {
        if (ack.status != Ack::STATUS_ACCEPTED) final_ack = ack;
      }
      return final_ack.status != -1;
    });
    return final_ack;
  }

  static Command Simple(const std::string& id, int8_t kind) {
    Command command;
    command.request_id = id;
    command.kind = kind;
    command.auth_size = 0;
    return command;
  }

  static Command MoveJoints(const std::string& id, const std::array<double, 6>& q) {
    Command command = Simple(id, Command::KIND_MOVE_JOINTS);
    std::copy(q.begin(), q.end(), command.q);
    command.speed = 1.0;
    command.acceleration = 1.4;
    return command;
  }

  void PowerUp() {
    ASSERT_TRUE(PumpUntil([&] { return node_->last_state().has_value(); }));
    ASSERT_EQ(Run(Simple("power", Command::KIND_POWER_ON)).status, Ack::STATUS_DONE);
    ASSERT_EQ(Run(Simple("brakes", Command::KIND_BRAKE_RELEASE)).status, Ack::STATUS_DONE);
    ASSERT_TRUE(PumpUntil([&] { return node_->last_state()->robot_mode == RobotMode::kRunning; }));
  }

  std::unique_ptr<sim::ur5::Ur5Emulator> emulator_;
  sim::CellTruth cell_;
  std::unique_ptr<bus::Bus> bus_;
  std::unique_ptr<RobotNode> node_;
  std::vector<Ack> acks_;
  std::vector<avc::robot_state_t> states_;
};

const std::array<double, 6> kTarget = {0.6, -1.3, 1.5, -1.8, -1.5, 0.2};

TEST_F(RobotNodeTest, MoveJointsIsAcceptedThenDoneAndStateFollows) {
  ASSERT_TRUE(node_->controller_kinematics());  // read once at connect
  EXPECT_EQ(node_->controller_kinematics()->d[3], cell_.dh.d[3]);
  PowerUp();
  const Ack done = Run(MoveJoints("move-1", kTarget));
  ASSERT_EQ(done.status, Ack::STATUS_DONE) << done.reason;
  ASSERT_EQ(AcksFor("move-1").front().status, Ack::STATUS_ACCEPTED);
  EXPECT_EQ(done.service, "avc-robot");
  states_.clear();
  ASSERT_TRUE(PumpUntil([&] { return !states_.empty(); }));
  const auto& state = states_.back();
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(state.q[i], kTarget[i], 1e-3);
  EXPECT_FALSE(state.moving);
  EXPECT_EQ(state.robot_mode, static_cast<int8_t>(RobotMode::kRunning));
  EXPECT_EQ(state.active_request_id, "");
  const auto q = Eigen::Map<const JointVector>(state.q);
  const auto difference = kinematics::ComparePoses(IsometryFromRowMajor(state.T_base_flange),
                                                   kinematics::ForwardKinematics(cell_.dh, q));
  EXPECT_LT(difference.translation_m, 1e-9);
  // A repeated request id is answered again and not executed again.
  const int scripts = emulator_->Snapshot().scripts_run;
  const size_t before = AcksFor("move-1").size();
  bus_->Publish(channels::kRobotCommand, *std::make_unique<Command>(MoveJoints("move-1", kTarget)));
  ASSERT_TRUE(PumpUntil([&] { return AcksFor("move-1").size() == before + 1; }));
  EXPECT_EQ(AcksFor("move-1").back().status, Ack::STATUS_DONE);
  EXPECT_EQ(emulator_->Snapshot().scripts_run, scripts);
}

TEST_F(RobotNodeTest, OutsideTheEnvelopeOrNotRunningIsRefusedWithAReason) {
  ASSERT_TRUE(PumpUntil([&] { return node_->last_state().has_value(); }));
  const Ack off = Run(MoveJoints("too-early", kTarget));
  EXPECT_EQ(off.status, Ack::STATUS_REFUSED);
  EXPECT_NE(off.reason.find("POWER_OFF"), std::string::npos) << off.reason;
  PowerUp();
  auto beyond = kTarget;
  beyond[0] = 1.5;  // joint 1 limit is 1.2 in this cell's envelope
  const Ack refused = Run(MoveJoints("beyond", beyond));
  EXPECT_EQ(refused.status, Ack::STATUS_REFUSED);
  EXPECT_NE(refused.reason.find("joint 1"), std::string::npos) << refused.reason;
  Command fast = MoveJoints("fast", kTarget);
  fast.speed = 3.0;
  EXPECT_NE(Run(fast).reason.find("speed"), std::string::npos);
  auto not_a_number = kTarget;
  not_a_number[4] = std::nan("");
  const Ack nan_refused = Run(MoveJoints("nan", not_a_number));
  EXPECT_EQ(nan_refused.status, Ack::STATUS_REFUSED);
  EXPECT_NE(nan_refused.reason.find("joint 5"), std::string::npos) << nan_refused.reason;
  Command linear = Simple("bad-pose", Command::KIND_MOVE_LINEAR);
  std::fill(std::begin(linear.T_base_flange), std::end(linear.T_base_flange), 0.0);
  linear.T_base_flange[15] = 1;  // zero rotation block: not a rigid transform
  const Ack pose_refused = Run(linear);
  EXPECT_EQ(pose_refused.status, Ack::STATUS_REFUSED);
  EXPECT_NE(pose_refused.reason.find("orthonormal"), std::string::npos) << pose_refused.reason;
  EXPECT_EQ(Run(Simple("", Command::KIND_STOP)).status, Ack::STATUS_REFUSED);
  EXPECT_EQ(Run(Simple("odd", 42)).status, Ack::STATUS_REFUSED);
  EXPECT_EQ(emulator_->Snapshot().scripts_run, 0);
}

TEST_F(RobotNodeTest, ProtectiveStopFailsTheMotionAndUnlockLetsTheNextOneFinish) {
  PowerUp();
  emulator_->ArmProtectiveStopAt(0.3);
  const Ack failed = Run(MoveJoints("interrupted", kTarget));
  ASSERT_EQ(failed.status, Ack::STATUS_FAILED);
  EXPECT_NE(failed.reason.find("PROTECTIVE_STOP"), std::string::npos) << failed.reason;
  states_.clear();
  ASSERT_TRUE(PumpUntil([&] { return !states_.empty(); }));
  EXPECT_TRUE(states_.back().protective_stop);
  EXPECT_EQ(Run(MoveJoints("while-stopped", kTarget)).status, Ack::STATUS_REFUSED);
  ASSERT_EQ(Run(Simple("unlock", Command::KIND_UNLOCK_PROTECTIVE_STOP)).status, Ack::STATUS_DONE);
  ASSERT_TRUE(PumpUntil([&] { return node_->last_state()->safety_mode == SafetyMode::kNormal; }));
  const Ack resumed = Run(MoveJoints("resumed", kTarget));
  EXPECT_EQ(resumed.status, Ack::STATUS_DONE) << resumed.reason;
}

}  // namespace
}  // namespace avc::robot
