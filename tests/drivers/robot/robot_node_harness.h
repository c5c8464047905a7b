#pragma once

// A RobotNode on an in-process bus (memq://) and an EventLoop, with the UR5 emulator on
// ephemeral ports and a scaled clock: what the robot node tests share. Records every ack,
// robot_state_t and the node's own heartbeat. Commands are signed with the harness's cell key
// (Send), unless a test sends them itself.

#include <gtest/gtest.h>

#include <avc/ack_t.hpp>
#include <avc/heartbeat_t.hpp>
#include <avc/robot_command_t.hpp>
#include <avc/robot_state_t.hpp>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/auth/command_auth.h"
#include "core/bus/bus.h"
#include "core/bus/channels.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"
#include "drivers/robot/robot_node.h"
#include "sim/cell/perturbation.h"
#include "sim/emulators/clock/emulator_clock.h"
#include "sim/emulators/ur5/ur5_emulator.h"
#include "tests/support/test_command_key.h"

namespace avc::robot::testing {

using Command = avc::robot_command_t;
using Ack = avc::ack_t;
using std::chrono::milliseconds;

inline const std::array<double, 6> kTarget = {0.6, -1.3, 1.5, -1.8, -1.5, 0.2};

using avc::testing::TestCommandKey;

// A driver's reason or health detail says `part`.
inline bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

inline sim::ur5::Ur5EmulatorOptions EmulatorOptions() {
  sim::ur5::Ur5EmulatorOptions options;
  options.cell = sim::PerturbedCell(21);
  options.rtde_port = options.primary_port = options.secondary_port = options.dashboard_port = 0;
  return options;
}

struct RobotNodeHarness {
  RobotNodeHarness()
      : bus(bus::InProcessBusOptions("cellr", "robot-test")),
        heartbeat(bus, loop, "avc-robot", milliseconds(50)),
        signer(TestCommandKey(), bus.options().source, bus.cell()) {
    bus.AttachTo(loop);
    bus.Subscribe<Ack>(channels::kAck,
                       [this](const Ack& ack, const bus::RxInfo&) { acks.push_back(ack); });
    bus.Subscribe<avc::robot_state_t>(
        channels::kRobotState,
        [this](const avc::robot_state_t& state, const bus::RxInfo&) { states.push_back(state); });
    bus.Subscribe<avc::heartbeat_t>(channels::kHeartbeat,
                                    [this](const avc::heartbeat_t& beat, const bus::RxInfo&) {
                                      if (beat.service == "avc-robot") health = beat;
                                    });
    config.envelope.joint_min[0] = -1.0;
    config.envelope.joint_max[0] = 1.2;
    config.motion_timeout = milliseconds(10000);
    config.auth.key = TestCommandKey();
  }

  // The emulator with simulated time `scale` times faster than real time.
  void StartEmulator(sim::ur5::Ur5EmulatorOptions options = EmulatorOptions(), double scale = 10) {
    cell = options.cell;
    emulator = std::make_unique<sim::ur5::Ur5Emulator>(
        options, std::make_shared<sim::ScaledEmulatorClock>(scale));
    config.rtde_port = emulator->rtde_port();
    config.secondary_port = emulator->secondary_port();
    config.dashboard_port = emulator->dashboard_port();
  }

  void StartNode() { node = std::make_unique<RobotNode>(bus, loop, heartbeat, config); }

  bool RunUntil(const std::function<bool()>& done, milliseconds timeout = milliseconds(5000)) {
    return loop.RunUntil(done, timeout);
  }

  bool WaitHealth(int8_t state, milliseconds timeout = milliseconds(5000)) {
    return RunUntil([&] { return health && health->state == state; }, timeout);
  }

  std::vector<Ack> AcksFor(const std::string& id) const {
    std::vector<Ack> found;
    for (const auto& ack : acks) {
      if (ack.request_id == id) found.push_back(ack);
    }
    return found;
  }

  // The final answer (anything but ACCEPTED) to `id` once it arrived.
  std::optional<Ack> FinalAck(const std::string& id) const {
    for (const auto& ack : AcksFor(id)) {
      if (ack.status != Ack::STATUS_ACCEPTED) return ack;
    }
    return std::nullopt;
  }

  // Signed with the cell's key, as CellClient sends it.
  void Send(Command command) {
    signer.Sign(command, bus.FullChannel(channels::kRobotCommand));
    bus.Publish(channels::kRobotCommand, command);
  }
  // Exactly as given: unsigned, forged or replayed.
  void SendAsIs(Command command) { bus.Publish(channels::kRobotCommand, command); }

  // Sends a command and waits for its final answer (status -1 when none came).
  Ack Run(Command command, milliseconds timeout = milliseconds(5000)) {
    const std::string id = command.request_id;
    Send(std::move(command));
    RunUntil([&] { return FinalAck(id).has_value(); }, timeout);
    Ack none;
    none.status = -1;
    return FinalAck(id).value_or(none);
  }

  static Command Simple(const std::string& id, int8_t kind) {
    Command command{};
    command.request_id = id;
    command.kind = kind;
    command.auth_size = 0;
    return command;
  }

  static Command MoveJoints(const std::string& id, const std::array<double, 6>& q,
                            double speed = 1.0) {
    Command command = Simple(id, Command::KIND_MOVE_JOINTS);
    std::copy(q.begin(), q.end(), command.q);
    command.speed = speed;
    command.acceleration = 1.4;
    return command;
  }

  void PowerUp() {
    ASSERT_TRUE(RunUntil([&] { return node->last_state().has_value(); }));
    const Ack powered = Run(Simple("power", Command::KIND_POWER_ON));
    ASSERT_EQ(powered.status, Ack::STATUS_DONE) << powered.reason;
    EXPECT_EQ(powered.reason.rfind("robot mode IDLE", 0), 0u) << powered.reason;
    // DONE only once the controller reports the mode the command leads to: the emulator, like
    // the arm, takes a while to release the brakes.
    const Ack released = Run(Simple("brakes", Command::KIND_BRAKE_RELEASE));
    ASSERT_EQ(released.status, Ack::STATUS_DONE) << released.reason;
    EXPECT_EQ(released.reason.rfind("robot mode RUNNING", 0), 0u) << released.reason;
    ASSERT_TRUE(node->last_state() && node->last_state()->robot_mode == RobotMode::kRunning);
  }

  bus::EventLoop loop;
  bus::Bus bus;
  bus::HeartbeatPublisher heartbeat;
  auth::CommandSigner signer;
  RobotNodeConfig config;
  sim::CellTruth cell;
  std::unique_ptr<sim::ur5::Ur5Emulator> emulator;
  std::unique_ptr<RobotNode> node;
  std::vector<Ack> acks;
  std::vector<avc::robot_state_t> states;
  std::optional<avc::heartbeat_t> health;
};

}  // namespace avc::robot::testing
