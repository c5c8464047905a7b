// avc-turntable's node on an in-process bus, driving the LT360 emulator on a real pty through the
// real serial backend: acks, state, heartbeat, refusals, repeats, stop, stall, reconnect and
// shutdown.

#include "drivers/turntable/turntable_node.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <avc/ack_t.hpp>
#include <avc/heartbeat_t.hpp>
#include <avc/turntable_state_t.hpp>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <optional>

#include "core/bus/bus.h"
#include "core/bus/channels.h"
#include "core/bus/heartbeat.h"
#include "sim/emulators/lt360/lt360_emulator.h"
#include "tests/support/test_command_key.h"
#include "tests/support/test_support.h"

namespace avc::turntable {
namespace {

using std::chrono::milliseconds;
using std::chrono::seconds;
constexpr double kTenthRad = 0.1 * std::numbers::pi / 180;

struct Harness {
  explicit Harness(double emulator_speed_deg_s = 90,
                   std::function<void(TurntableNodeOptions&)> tune = {})
      : bus(bus::InProcessBusOptions()),
        heartbeat(bus, loop, "avc-turntable", milliseconds(50)),
        emulator_clock(std::make_shared<sim::SteppedEmulatorClock>(0.25)),
        signer(testing::TestCommandKey(), bus.options().source, bus.cell()) {
    sim::Lt360EmulatorOptions emulator_options;
    emulator_options.speed_deg_s = emulator_speed_deg_s;
    emulator = std::make_unique<sim::Lt360Emulator>(emulator_options, emulator_clock);
    bus.AttachTo(loop);
    bus.Subscribe<avc::ack_t>(
        channels::kAck, [this](const avc::ack_t& ack, const bus::RxInfo&) { acks.push_back(ack); });
    bus.Subscribe<avc::turntable_state_t>(
        channels::kTurntableState,
        [this](const avc::turntable_state_t& s, const bus::RxInfo&) { state = s; });
    bus.Subscribe<avc::heartbeat_t>(channels::kHeartbeat,
                                    [this](const avc::heartbeat_t& beat, const bus::RxInfo&) {
                                      if (beat.service == "avc-turntable") health = beat;
                                    });
    options.device = emulator->device_path();
    options.poll_period = milliseconds(20);
    options.device_options.command_timeout = milliseconds(300);
    options.reconnect_min = milliseconds(50);
    options.reconnect_max = milliseconds(200);
    options.controller.default_speed_deg_s = emulator_speed_deg_s;
    options.auth.key = testing::TestCommandKey();
    if (tune) tune(options);
    node = std::make_unique<TurntableNode>(bus, loop, heartbeat, options);
  }

  void Send(const std::string& id, int8_t kind, double angle = 0, double speed = 0) {
    avc::turntable_command_t command{};
    command.request_id = id;
    command.kind = kind;
    command.angle = angle;
    command.speed = speed;
    signer.Sign(command, bus.FullChannel(channels::kTurntableCommand));
    bus.Publish(channels::kTurntableCommand, command);
  }

  std::vector<avc::ack_t> AcksFor(const std::string& id) const {
    std::vector<avc::ack_t> out;
    for (const auto& ack : acks) {
      if (ack.request_id == id) out.push_back(ack);
    }
    return out;
  }

  // Runs the loop until an ack with that status arrives for id.
  bool WaitAck(const std::string& id, int8_t status, milliseconds timeout = milliseconds(5000)) {
    return loop.RunUntil(
        [&] {
          for (const auto& ack : acks) {
            if (ack.request_id == id && ack.status == status) return true;
          }
          return false;
        },
        timeout);
  }

  bool WaitHealth(int8_t wanted, milliseconds timeout = milliseconds(3000)) {
    return loop.RunUntil([&] { return health && health->state == wanted; }, timeout);
  }

  bus::Bus bus;
  bus::EventLoop loop;
  bus::HeartbeatPublisher heartbeat;
  std::shared_ptr<sim::SteppedEmulatorClock> emulator_clock;
  auth::CommandSigner signer;
  std::unique_ptr<sim::Lt360Emulator> emulator;
  TurntableNodeOptions options;
  std::unique_ptr<TurntableNode> node;
  std::vector<avc::ack_t> acks;
  std::optional<avc::turntable_state_t> state;
  std::optional<avc::heartbeat_t> health;
};

TEST(TurntableNode, GotoIsAcceptedThenDoneAndStateReportsTheAngle) {
  Harness h;
  ASSERT_TRUE(h.WaitHealth(avc::heartbeat_t::STATE_READY)) << (h.health ? h.health->detail : "");
  h.Send("g1", avc::turntable_command_t::KIND_GOTO, 1.0);
  ASSERT_TRUE(h.WaitAck("g1", avc::ack_t::STATUS_DONE));
  const auto acks = h.AcksFor("g1");
  ASSERT_EQ(acks.size(), 2u);
  EXPECT_EQ(acks[0].status, avc::ack_t::STATUS_ACCEPTED);
  EXPECT_EQ(acks[0].service, "avc-turntable");
  EXPECT_EQ(acks[1].status, avc::ack_t::STATUS_DONE);
  // 1 rad = 57.2958 deg: the table goes to 57.3 and the state says so within a tenth.
  EXPECT_EQ(h.emulator->ReportedTenths(), 573);
  ASSERT_TRUE(h.loop.RunUntil([&] { return h.state && !h.state->moving; }, seconds(2)));
  EXPECT_NEAR(h.state->angle, 1.0, kTenthRad);
  EXPECT_TRUE(h.state->connected);
  EXPECT_EQ(h.state->active_request_id, "");
  ASSERT_TRUE(h.WaitHealth(avc::heartbeat_t::STATE_READY));

  // Negative goto angles wrap into [0, 2 pi).
  h.Send("g2", avc::turntable_command_t::KIND_GOTO, -0.5);
  ASSERT_TRUE(h.WaitAck("g2", avc::ack_t::STATUS_DONE));
  ASSERT_TRUE(h.loop.RunUntil([&] { return h.state && !h.state->moving; }, seconds(2)));
  EXPECT_NEAR(h.state->angle, 2 * std::numbers::pi - 0.5, kTenthRad);
}

TEST(TurntableNode, StepAndHome) {
  Harness h;
  h.Send("s1", avc::turntable_command_t::KIND_STEP, -0.25);
  ASSERT_TRUE(h.WaitAck("s1", avc::ack_t::STATUS_DONE));
  EXPECT_EQ(h.emulator->ReportedTenths(), 3457);  // -14.3 deg
  h.Send("h1", avc::turntable_command_t::KIND_HOME);
  ASSERT_TRUE(h.WaitAck("h1", avc::ack_t::STATUS_DONE));
  ASSERT_TRUE(h.loop.RunUntil([&] { return h.state && h.state->homed; }, seconds(2)));
  EXPECT_EQ(h.emulator->ReportedTenths(), 0);
}

TEST(TurntableNode, RepeatedRequestIdResendsTheLastAckAndNeverMovesAgain) {
  Harness h;
  h.Send("once", avc::turntable_command_t::KIND_STEP, 0.1);
  ASSERT_TRUE(h.WaitAck("once", avc::ack_t::STATUS_DONE));
  const int64_t moves = h.emulator->moves_started();
  const int position = h.emulator->ReportedTenths();
  h.acks.clear();
  h.Send("once", avc::turntable_command_t::KIND_STEP, 0.1);
  ASSERT_TRUE(h.WaitAck("once", avc::ack_t::STATUS_DONE, milliseconds(2000)));
  h.loop.RunUntil([] { return false; }, milliseconds(100));
  EXPECT_EQ(h.AcksFor("once").size(), 1u);
  EXPECT_EQ(h.emulator->moves_started(), moves);
  EXPECT_EQ(h.emulator->ReportedTenths(), position);
}

TEST(TurntableNode, BadInputIsRefusedWithAReason) {
  Harness h;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  h.Send("nan", avc::turntable_command_t::KIND_GOTO, nan);
  h.Send("kind", 9);
  h.Send("speed", avc::turntable_command_t::KIND_GOTO, 1.0, -1);
  h.Send("big", avc::turntable_command_t::KIND_STEP, 7.0);
  h.Send("far", avc::turntable_command_t::KIND_GOTO, 1e20);
  h.Send("", avc::turntable_command_t::KIND_HOME);
  ASSERT_TRUE(h.WaitAck("", avc::ack_t::STATUS_REFUSED));
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"nan", "finite"},
      {"kind", "unknown command kind 9"},
      {"speed", "speed must be >= 0"},
      {"big", "exceeds one turn"},
      {"far", "beyond two turns"},
      {"", "empty request_id"}};
  for (const auto& [id, reason] : expected) {
    const auto acks = h.AcksFor(id);
    ASSERT_EQ(acks.size(), 1u) << id;
    EXPECT_EQ(acks[0].status, avc::ack_t::STATUS_REFUSED) << id;
    EXPECT_NE(acks[0].reason.find(reason), std::string::npos) << id << ": " << acks[0].reason;
  }
  EXPECT_EQ(h.emulator->moves_started(), 0);
}

TEST(TurntableNode, BusyIsRefusedAndStopFailsTheRunningMove) {
  Harness h(/*emulator_speed_deg_s=*/1);
  h.Send("slow", avc::turntable_command_t::KIND_GOTO, 3.0);
  ASSERT_TRUE(h.WaitAck("slow", avc::ack_t::STATUS_ACCEPTED));
  ASSERT_TRUE(h.WaitHealth(avc::heartbeat_t::STATE_BUSY));
  h.Send("other", avc::turntable_command_t::KIND_GOTO, 1.0);
  ASSERT_TRUE(h.WaitAck("other", avc::ack_t::STATUS_NOT_READY));
  EXPECT_NE(h.AcksFor("other")[0].reason.find("busy with request 'slow'"), std::string::npos);
  h.Send("halt", avc::turntable_command_t::KIND_STOP);
  ASSERT_TRUE(h.WaitAck("halt", avc::ack_t::STATUS_DONE));
  ASSERT_TRUE(h.WaitAck("slow", avc::ack_t::STATUS_FAILED));
  EXPECT_NE(h.AcksFor("slow").back().reason.find("stopped by request 'halt'"), std::string::npos);
  EXPECT_FALSE(h.emulator->moving());
  ASSERT_TRUE(h.WaitHealth(avc::heartbeat_t::STATE_READY));
}

TEST(TurntableNode, StalledTableIsReportedFailed) {
  Harness h(/*emulator_speed_deg_s=*/5,
            [](TurntableNodeOptions& options) { options.controller.stall_timeout_s = 0.3; });
  h.Send("stuck", avc::turntable_command_t::KIND_GOTO, 3.0);
  ASSERT_TRUE(h.WaitAck("stuck", avc::ack_t::STATUS_ACCEPTED));
  h.emulator->InjectFault(sim::Lt360Fault::kStall);
  ASSERT_TRUE(h.WaitAck("stuck", avc::ack_t::STATUS_FAILED));
  EXPECT_NE(h.AcksFor("stuck").back().reason.find("stalled"), std::string::npos)
      << h.AcksFor("stuck").back().reason;
  EXPECT_FALSE(h.emulator->moving());  // stopped by the driver
}

TEST(TurntableNode, TimeoutIsAnErrorUntilTheDeviceAnswersAgain) {
  Harness h(90, [](TurntableNodeOptions& options) {
    options.device_options.command_timeout = milliseconds(100);
    options.failures_before_reconnect = 100;
  });
  ASSERT_TRUE(h.WaitHealth(avc::heartbeat_t::STATE_READY));
  h.emulator->InjectFault(sim::Lt360Fault::kNoReply, 2);
  ASSERT_TRUE(h.WaitHealth(avc::heartbeat_t::STATE_ERROR));
  EXPECT_NE(h.health->detail.find("serial timeout after 0.1 s waiting for reply to"),
            std::string::npos)
      << h.health->detail;
  ASSERT_TRUE(h.WaitHealth(avc::heartbeat_t::STATE_READY));
  EXPECT_TRUE(h.node->connected());
}

TEST(TurntableNode, LostDeviceIsAnErrorAndIsReopenedWithBackoff) {
  testing::TempDir dir("avc-turntable-node");
  const std::filesystem::path link = dir / "ttyLT360";
  sim::Lt360EmulatorOptions second_options;
  second_options.start_deg = 12.3;
  auto second = std::make_unique<sim::Lt360Emulator>(second_options);
  // The node opens a symlink, as udev rules give stable names to USB adapters.
  auto h = std::make_unique<Harness>(90, [&](TurntableNodeOptions& options) {
    std::filesystem::create_symlink(options.device, link);
    options.device = link.string();
  });
  Harness* harness = h.get();
  ASSERT_TRUE(harness->WaitHealth(avc::heartbeat_t::STATE_READY));
  harness->emulator->Disconnect();
  ASSERT_TRUE(harness->WaitHealth(avc::heartbeat_t::STATE_ERROR));
  ASSERT_TRUE(harness->loop.RunUntil([&] { return harness->state && !harness->state->connected; },
                                     seconds(2)));
  // Commands are refused for now while disconnected.
  harness->Send("away", avc::turntable_command_t::KIND_HOME);
  ASSERT_TRUE(harness->WaitAck("away", avc::ack_t::STATUS_NOT_READY));
  EXPECT_NE(harness->AcksFor("away")[0].reason.find("not connected"), std::string::npos);
  // The "adapter" comes back under the same name.
  std::filesystem::remove(link);
  std::filesystem::create_symlink(second->device_path(), link);
  ASSERT_TRUE(harness->WaitHealth(avc::heartbeat_t::STATE_READY));
  ASSERT_TRUE(harness->loop.RunUntil([&] { return harness->state && harness->state->connected; },
                                     seconds(2)));
  EXPECT_NEAR(harness->state->angle, 12.3 * std::numbers::pi / 180, kTenthRad);
}

TEST(TurntableNode, ShutdownStopsAMovingTable) {
  Harness h(/*emulator_speed_deg_s=*/1);
  h.Send("long", avc::turntable_command_t::KIND_GOTO, 3.0);
  ASSERT_TRUE(h.WaitAck("long", avc::ack_t::STATUS_ACCEPTED));
  ASSERT_TRUE(h.loop.RunUntil([&] { return h.emulator->moving(); }, seconds(2)));
  h.node->Shutdown();
  h.loop.RunUntil([] { return false; }, milliseconds(50));
  EXPECT_FALSE(h.emulator->moving());
  const auto acks = h.AcksFor("long");
  ASSERT_EQ(acks.back().status, avc::ack_t::STATUS_FAILED);
  EXPECT_NE(acks.back().reason.find("stopping"), std::string::npos);
}

TEST(TurntableNode, BadOptionsAreRejected) {
  bus::Bus bus(bus::InProcessBusOptions());
  bus::EventLoop loop;
  bus::HeartbeatPublisher heartbeat(bus, loop, "avc-turntable");
  TurntableNodeOptions options;
  EXPECT_THROW(TurntableNode(bus, loop, heartbeat, options), std::invalid_argument);
  options.device = "/dev/null";
  options.controller.stall_timeout_s = 0;
  EXPECT_THROW(TurntableNode(bus, loop, heartbeat, options), std::invalid_argument);
}

}  // namespace
}  // namespace avc::turntable
