// avc-robot obeys only authentic commands for its own cell: unsigned, forged, altered, replayed,
// stale and wrong-cell commands are refused with the reason and logged, and the arm never gets a
// program for them; a refused copy does not become the genuine request's answer. STOP needs no
// signature, and unsigned operation is possible only when switched on.

#include <gtest/gtest.h>

#include <string>

#include "tests/drivers/robot/robot_node_harness.h"

namespace avc::robot::testing {
namespace {

class RobotNodeAuthTest : public ::testing::Test {
 protected:
  void Start() {
    h_.StartEmulator();
    h_.StartNode();
    ASSERT_TRUE(h_.WaitHealth(avc::heartbeat_t::STATE_READY)) << h_.health->detail;
    h_.PowerUp();
  }

  // Sends `command` (stamped by the bus, or exactly as it is) and expects a refusal naming `why`.
  void ExpectRefused(const Command& command, const std::string& why, bool stamped = true) {
    const size_t before = h_.AcksFor(command.request_id).size();
    if (stamped) {
      h_.SendAsIs(command);
    } else {
      h_.bus.PublishUnstamped(channels::kRobotCommand, command);
    }
    ASSERT_TRUE(h_.RunUntil([&] { return h_.AcksFor(command.request_id).size() > before; }));
    const Ack answer = h_.AcksFor(command.request_id).back();
    EXPECT_EQ(answer.status, Ack::STATUS_REFUSED);
    EXPECT_TRUE(Contains(answer.reason, "authentication: " + why)) << answer.reason;
  }

  Command SignedMove(const std::string& id, const std::string& channel) {
    Command command = RobotNodeHarness::MoveJoints(id, kTarget);
    h_.signer.Sign(command, channel);
    return command;
  }

  std::string Channel() { return h_.bus.FullChannel(channels::kRobotCommand); }

  RobotNodeHarness h_;
};

TEST_F(RobotNodeAuthTest, OnlyAuthenticCommandsMoveTheArm) {
  Start();
  const int scripts = h_.emulator->Snapshot().scripts_run;

  ExpectRefused(RobotNodeHarness::MoveJoints("m", kTarget), "unsigned command");

  auth::CommandKey other = TestCommandKey();
  other.bytes[0] ^= 1;
  auth::CommandSigner stranger(other, h_.bus.options().source, h_.bus.cell());
  Command forged = RobotNodeHarness::MoveJoints("m", kTarget);
  stranger.Sign(forged, Channel());
  ExpectRefused(forged, "bad signature");

  Command altered = SignedMove("m", Channel());
  altered.q[0] = 1.1;  // still inside the envelope: only the signature stops it
  ExpectRefused(altered, "bad signature");

  Command for_another_cell = SignedMove("m", "cellx/ROBOT_COMMAND");
  ExpectRefused(for_another_cell, "bad signature");

  // Another cell's process publishing on our channel by mistake (the bus would stamp our cell).
  auth::CommandSigner neighbour(TestCommandKey(), "avc-scan@cellx", "cellx");
  Command claims_another_cell = RobotNodeHarness::MoveJoints("m", kTarget);
  neighbour.Sign(claims_another_cell, Channel());
  ExpectRefused(claims_another_cell, "command for cell 'cellx' arrived on cell 'cellr'",
                /*stamped=*/false);

  // Signed by a sender whose clock is an hour behind (or a recording of an hour ago).
  ManualClock hour_ago(SystemClock().NowMicros() - 3'600'000'000);
  auth::CommandSigner late(TestCommandKey(), "old-laptop", h_.bus.cell(), &hour_ago);
  Command stale = RobotNodeHarness::MoveJoints("m", kTarget);
  late.Sign(stale, Channel());
  ExpectRefused(stale, "stale command from 'old-laptop'", /*stamped=*/false);
  EXPECT_EQ(h_.emulator->Snapshot().scripts_run, scripts);  // nothing reached the arm

  // The refusals were not remembered as "m"'s answer: the genuine command runs.
  Command genuine = SignedMove("m", Channel());
  h_.SendAsIs(genuine);
  ASSERT_TRUE(h_.RunUntil([&] { return h_.AcksFor("m").back().status == Ack::STATUS_DONE; }));
  EXPECT_EQ(h_.emulator->Snapshot().scripts_run, scripts + 1);

  // Its recorded datagram sent again is a replay, answered without touching the arm.
  h_.bus.PublishUnstamped(channels::kRobotCommand, genuine);
  ASSERT_TRUE(h_.RunUntil([&] { return h_.AcksFor("m").back().status == Ack::STATUS_REFUSED; }));
  EXPECT_TRUE(Contains(h_.AcksFor("m").back().reason, "replayed command"))
      << h_.AcksFor("m").back().reason;
  EXPECT_EQ(h_.emulator->Snapshot().scripts_run, scripts + 1);
  // Re-sent (and so signed anew) it is the same request: its answer, no second motion.
  h_.Send(RobotNodeHarness::MoveJoints("m", kTarget));
  ASSERT_TRUE(h_.RunUntil([&] { return h_.AcksFor("m").back().status == Ack::STATUS_DONE; }));
  EXPECT_EQ(h_.emulator->Snapshot().scripts_run, scripts + 1);
}

TEST_F(RobotNodeAuthTest, AnUnsignedStopIsObeyedButUnsignedPowerIsNot) {
  Start();
  h_.Send(RobotNodeHarness::MoveJoints("long", kTarget, 0.1));
  ASSERT_TRUE(h_.RunUntil([&] { return h_.emulator->Snapshot().program_running; }));
  h_.SendAsIs(RobotNodeHarness::Simple("halt", Command::KIND_STOP));
  ASSERT_TRUE(h_.RunUntil([&] { return h_.FinalAck("halt").has_value(); }));
  EXPECT_EQ(h_.FinalAck("halt")->status, Ack::STATUS_DONE) << h_.FinalAck("halt")->reason;
  ASSERT_TRUE(h_.RunUntil([&] { return h_.FinalAck("long").has_value(); }));
  EXPECT_EQ(h_.FinalAck("long")->status, Ack::STATUS_FAILED);
  ExpectRefused(RobotNodeHarness::Simple("unlock", Command::KIND_UNLOCK_PROTECTIVE_STOP),
                "unsigned command");
  ExpectRefused(RobotNodeHarness::Simple("brakes", Command::KIND_BRAKE_RELEASE),
                "unsigned command");
}

TEST_F(RobotNodeAuthTest, UnsignedOperationOnlyWithTheExplicitSwitch) {
  h_.config.auth = {};
  EXPECT_THROW(h_.StartNode(), std::invalid_argument);  // no key and no switch: no driver
  h_.config.auth.allow_unsigned = true;
  Start();
  h_.SendAsIs(RobotNodeHarness::MoveJoints("open", kTarget));
  ASSERT_TRUE(h_.RunUntil([&] { return h_.FinalAck("open").has_value(); }));
  EXPECT_EQ(h_.FinalAck("open")->status, Ack::STATUS_DONE) << h_.FinalAck("open")->reason;
}

}  // namespace
}  // namespace avc::robot::testing
